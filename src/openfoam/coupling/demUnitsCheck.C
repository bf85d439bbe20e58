#include "demUnitsCheck.H"
#include "error.H"
#include "volFields.H"

#include <mpi.h>

#include "lammps.h"
#include "atom.h"
#include "domain.h"
#include "force.h"

void Foam::checkDemUnits(LAMMPS_NS::LAMMPS* lmp, const fvMesh& mesh, const dictionary& couplingDict)
{
    // Far outside any real set-up: a DEM box a little larger than the mesh, or particles a few
    // times the cells, are normal; a factor of 1000 is millimetres against metres.
    const scalar maxRatio = 100;
    const boundBox& bb = mesh.bounds();   // the whole mesh (reduced over the ranks)
    const vector meshSize = bb.span();
    const vector demSize
    (
        lmp->domain->boxhi[0] - lmp->domain->boxlo[0],
        lmp->domain->boxhi[1] - lmp->domain->boxlo[1],
        lmp->domain->boxhi[2] - lmp->domain->boxlo[2]
    );
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        const scalar ratio = demSize[d]/meshSize[d];
        if (ratio > maxRatio || ratio < 1/maxRatio)
        {
            FatalErrorInFunction
                << "the DEM box is " << demSize << " m but the CFD mesh " << meshSize << " m ("
                << ratio << " times along " << vector::componentNames[d] << "): the DEM script ("
                << couplingDict.lookupOrDefault<fileName>("demScript", "") << ") and the mesh are in"
                << " different units" << nl
                << "    both must be in metres (LIGGGHTS units si; a mesh drawn in millimetres needs"
                << " scale 0.001 in system/blockMeshDict, or transformPoints -scale)" << exit(FatalError);
        }
    }

    double rMax = 0;
    for (int i = 0; i < lmp->atom->nlocal; ++i) rMax = std::max(rMax, lmp->atom->radius[i]);
    double rMaxAll = 0;
    MPI_Allreduce(&rMax, &rMaxAll, 1, MPI_DOUBLE, MPI_MAX, lmp->world);
    const scalar meanCell = Foam::cbrt(gSum(mesh.V())/returnReduce(mesh.nCells(), sumOp<label>()));
    if (2*rMaxAll > maxRatio*meanCell)
    {
        FatalErrorInFunction
            << "the largest DEM particle (diameter " << 2*rMaxAll << " m) is " << 2*rMaxAll/meanCell
            << " times the mean CFD cell (" << meanCell << " m): the DEM script and the mesh are most"
            << " likely in different units (both must be in metres)" << exit(FatalError);
    }
}

void Foam::checkDemCoarseGraining(LAMMPS_NS::LAMMPS* lmp, scalar factor, const dictionary& couplingDict)
{
    // LIGGGHTS-PUBLIC 3.8 has no coarse-graining command (force->cg() is 1 and cg_active() false):
    // its particles are the grains, with contact models of their own size, and the factor is the
    // coupling's alone. A LIGGGHTS that sets its own factor must set this one.
    LAMMPS_NS::Force& force = *lmp->force;
    if (!force.cg_active()) return;
    const scalar dem = force.cg_max();
    if (mag(dem - factor) > 1e-12*dem)
    {
        FatalIOErrorInFunction(couplingDict)
            << "entry coarseGrainingFactor " << factor << " in " << couplingDict.name() << " disagrees"
            << " with the DEM's coarse-graining factor " << dem << " (its script "
            << couplingDict.lookupOrDefault<fileName>("demScript", "") << "): set both to the same value"
            << exit(FatalIOError);
    }
}
