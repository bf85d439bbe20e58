/*---------------------------------------------------------------------------*\
    dtCheckTest: runs checkDemTimestep (src/openfoam/coupling/demTimeStepCheck)
    on a case's DEM script and constant/couplingProperties, without a mesh:

        dtCheckTest -case <dir> [-parallel]

    Reads couplingProperties, starts LIGGGHTS on MPI_COMM_WORLD, reads the
    demScript (from the case directory), prints the estimate as one line

        ESTIMATE dt tRayleigh tHertz impactVelocity nParticles rMin rhoMin rhoMax EMax

    then calls checkDemTimestep and prints "dtCheckTest: check passed" if it
    returned (FatalIOError exits non-zero with its message).
\*---------------------------------------------------------------------------*/
#include "argList.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "demTimeStepCheck.H"

#include <mpi.h>
#include <string>
#include <vector>
#include "lammps.h"
#include "input.h"

using namespace Foam;

int main(int argc, char* argv[])
{
    argList::addNote("DEM time-step check on a case's DEM script (stability suite)");
    #include "setRootCase.H"

    const fileName caseDir = args.rootPath()/args.globalCaseName();
    IFstream is(caseDir/"constant"/"couplingProperties");
    if (!is.good())
    {
        FatalErrorInFunction << "cannot read " << is.name() << exit(FatalError);
    }
    const dictionary dict(is);

    int started = 0;
    MPI_Initialized(&started);
    if (!started) MPI_Init(nullptr, nullptr);

    std::vector<std::string> a = {"liggghts", "-screen", "none", "-log", caseDir/"log.liggghts"};
    std::vector<char*> av;
    for (auto& s : a) av.push_back(&s[0]);
    LAMMPS_NS::LAMMPS* lmp = new LAMMPS_NS::LAMMPS(int(av.size()), av.data(), MPI_COMM_WORLD);
    const fileName cwd0 = cwd();
    chDir(caseDir);
    lmp->input->file(fileName(caseDir/dict.get<fileName>("demScript")).c_str());
    chDir(cwd0);

    const demTimestepEstimate e =
        estimateDemTimestep(lmp, dict.lookupOrDefault<scalar>("demMaxImpactVelocity", 1.0));
    Info<< "ESTIMATE " << e.dt << " " << e.tRayleigh << " " << e.tHertz << " " << e.impactVelocity << " "
        << e.nParticles << " " << e.rMin << " " << e.rhoMin << " " << e.rhoMax << " " << e.EMax
        << " valid " << (e.valid ? 1 : 0) << endl;

    checkDemTimestep(lmp, dict);
    Info<< "dtCheckTest: check passed" << endl;

    delete lmp;
    if (!started && !Pstream::parRun()) MPI_Finalize();
    return 0;
}
