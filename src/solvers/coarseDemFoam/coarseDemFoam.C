/*---------------------------------------------------------------------------*\
Application
    coarseDemFoam

Description
    Transient incompressible CFD-DEM solver for coarse particles (particles
    as large as or larger than the cells). LIGGGHTS runs in the same process
    (fix couple/coarse); the void fraction, the fluid sampling at particles
    and the momentum exchange use the kernels of the coarse-dem C core,
    chosen in constant/couplingProperties (see src/openfoam/coupling).

    Fluid: Zhang et al., Phys. Fluids 35, 113330 (2023), eqs. 14-19, PIMPLE;
    Model A / Model B after Zhou et al. (2010) and Weaver & Miskovic, Fluids
    8, 215 (2023); drag optionally implicit (Ksl).

    The CFD time step is couplingInterval DEM steps. With adjustTimeStep yes
    in controlDict the coupling interval adapts to keep the Courant number
    below maxCo.
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "singlePhaseTransportModel.H"
#include "turbulentTransportModel.H"
#include "pimpleControl.H"
#include "fixedFluxPressureFvPatchScalarField.H"
#include "wallFvPatch.H"
#include "coarseDemCoupling.H"
#include "noAliasFvc.H"
#include "growingOscillation.H"

#include <chrono>

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "CFD-DEM solver for coarse particles with LIGGGHTS in-process and"
        " swappable void-fraction kernels (constant/couplingProperties)"
    );

    argList::addBoolOption
    (
        "frozenParticles",
        "couple once at the start, then solve the fluid alone with the particles, alpha and the"
        " exchange fields frozen (bench/coupled: the fluid's share of a coupled run)"
    );
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"
    pimpleControl pimple(mesh);
    #include "createFields.H"
    #include "initContinuityErrs.H"

    #include "setCouplingTimeStep.H"

    // The fluid acceleration only when a force model needs it (virtual mass).
    auto couple = [&]()
    {
        const tmp<volVectorField> DUDt
        (
            (coupling.needs() & forceModel::needDUfDt) ? fvc::DDt(phi, U) : tmp<volVectorField>()
        );
        coupling.couple(U, alpha, p, turbulence->nuEff()(), DUDt.valid() ? &DUDt() : nullptr);
    };

    // First coupling before the first DEM segment, so it starts with the fluid forces.
    couple();
    alpha.oldTime() = alpha;
    alphaf = fvc::interpolate(alpha);
    alphaPhi = alphaf*phi;
    coupling.report(Info);

    const auto wall0 = std::chrono::steady_clock::now();
    const scalar t0 = runTime.value();
    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "adjustCouplingInterval.H"
        ++runTime;
        Info<< "Time = " << runTime.timeName() << nl << endl;

        if (!frozenParticles)
        {
            coupling.evolveDem();
            couple();
        }
        alphaf = fvc::interpolate(alpha);
        alphaPhi = alphaf*phi;

        coupling.timers().start(stageTimers::fluid);
        while (pimple.loop())
        {
            #include "UEqn.H"
            #include "pEqnCoeffs.H"
            while (pimple.correct())
            {
                #include "pEqn.H"
            }
            if (pimple.turbCorr())
            {
                laminarTransport.correct();
                turbulence->correct();
            }
        }
        coupling.timers().stop();

        runTime.write();
        coupling.write();

        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
        const scalar done = runTime.value() - t0, left = runTime.endTime().value() - runTime.value();
        Info<< "Progress: t = " << runTime.timeName() << " s of " << runTime.endTime().value()
            << " s, " << label(runTime.timeIndex()) << " steps, wall " << wall << " s, estimated left "
            << (done > 0 && left > 0 ? wall/done*left : 0) << " s" << nl;   // 0 at the end, not -1e-14
        if (runTime.writeTime())
        {
            coupling.report(Info);
            reportCourant(Info);
            coupling.timers().print(Info);
        }
        Info<< endl;
    }

    Info<< "End: ";
    coupling.report(Info);
    reportCourant(Info);
    coupling.timers().print(Info);
    Info<< "ExecutionTime = " << runTime.elapsedCpuTime() << " s  ClockTime = " << runTime.elapsedClockTime()
        << " s" << nl << endl;
    return 0;
}
