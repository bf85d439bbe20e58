/*---------------------------------------------------------------------------*\
    coarseDemLinkCheck: proves that one OpenFOAM application compiles and links
    against Debian's OpenFOAM v1912, the project's LIGGGHTS (with fix
    couple/coarse) and the C core, and that all three work in one process.
    Built and run by tests/integration/run_wmake_link.sh.
\*---------------------------------------------------------------------------*/

#include <mpi.h>

#include "fvCFD.H"

#include "coarse_dem.h"

#include "lammps.h"
#include "input.h"
#include "modify.h"
#include "fix_couple_coarse.h"

int main(int argc, char *argv[])
{
    argList::addNote("Link check: OpenFOAM + LIGGGHTS + coarse-dem core in one process");
    argList::noParallel();
    #include "setRootCase.H"

    // OpenFOAM does not start MPI in a serial run; LIGGGHTS needs it.
    int mpiStarted = 0;
    MPI_Initialized(&mpiStarted);
    if (!mpiStarted)
    {
        MPI_Init(&argc, &argv);
    }

    // OpenFOAM side
    const vector g(0, 0, -9.81);
    Info<< "OpenFOAM: mag(g) = " << mag(g) << endl;

    // core side
    Info<< "core " << CDC_VERSION_STRING << ": methods " << cdc_method_list() << endl;

    // LIGGGHTS side: a box with one particle and fix couple/coarse
    char arg0[] = "liggghts", arg1[] = "-screen", arg2[] = "none", arg3[] = "-log", arg4[] = "none";
    char* lmpArgv[] = {arg0, arg1, arg2, arg3, arg4, nullptr};
    LAMMPS_NS::LAMMPS* lmp = new LAMMPS_NS::LAMMPS(5, lmpArgv, MPI_COMM_WORLD);
    const char* lines[] =
    {
        "atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
        "communicate single vel yes", "units si",
        "region domain block 0 1 0 1 0 1 units box", "create_box 1 domain",
        "create_atoms 1 single 0.5 0.5 0.5 units box",
        "set group all diameter 0.01", "set group all density 1000",
        "fix cpl all couple/coarse"
    };
    for (const char* line : lines)
    {
        lmp->input->one(line);
    }
    const int ifix = lmp->modify->find_fix("cpl");
    LAMMPS_NS::FixCoupleCoarse* fix = ifix < 0 ? nullptr
        : dynamic_cast<LAMMPS_NS::FixCoupleCoarse*>(lmp->modify->fix[ifix]);
    if (!fix || fix->nlocal() != 1)
    {
        FatalErrorInFunction << "fix couple/coarse not found or wrong particle count"
            << exit(FatalError);
    }
    double x[3], v[3], r, rho;
    int type;
    long long id;
    fix->pull(x, v, &r, &rho, &type, &id);
    Info<< "LIGGGHTS: particle " << label(id) << " at (" << x[0] << ' ' << x[1] << ' ' << x[2]
        << ") radius " << r << endl;
    delete lmp;

    Info<< "coarseDemLinkCheck: OK" << endl;
    MPI_Finalize();
    return 0;
}
