#include "coarseDemCoupling.H"
#include "setupAdvice.H"
#include "couplingEntries.H"
#include "particleCloud.H"
#include "demTimeStepCheck.H"
#include "demNeighbourCheck.H"
#include "demUnitsCheck.H"
#include "fvc.H"
#include "noAliasFvc.H"
#include "zeroGradientFvPatchFields.H"
#include "mathematicalConstants.H"

#include <cmath>

namespace Foam
{

static IOobject couplingDictIO(const fvMesh& mesh)
{
    return IOobject("couplingProperties", mesh.time().constant(), mesh, IOobject::MUST_READ, IOobject::NO_WRITE);
}


coarseDemCoupling::coarseDemCoupling
(
    const fvMesh& mesh, const dimensionedScalar& rho, const dimensionedScalar& nu, const dimensionedVector& g
)
:
    mesh_(mesh),
    dict_(couplingDictIO(mesh)),
    modelB_(false),
    couplingInterval_(checkCouplingEntries(dict_).get<label>("couplingInterval")),
    switches_(dict_),
    cgFactor_(dict_.lookupOrDefault<scalar>("coarseGrainingFactor", 1)),
    alphaRelaxationTime_(dict_.lookupOrDefault<scalar>("alphaRelaxationTime", 0)),
    fluid_{rho.value(), nu.value(), g.value()},
    demMesh_(mesh, dict_),
    voidFraction_(dict_, demMesh_),
    halo_(mesh),
    transfer_(demMesh_, halo_, particles_, ghosts_),
    nParticles_(0),
    diag_(mesh, dict_, switches_.allowParticleLoss),
    keepRestartForces_(false),
    alphaP
    (
        IOobject("alphaP", mesh.time().timeName(), mesh, IOobject::NO_READ, IOobject::AUTO_WRITE),
        mesh, dimensionedScalar(dimless, Zero), zeroGradientFvPatchScalarField::typeName
    ),
    Ksl
    (
        IOobject
        (
            "Ksl", mesh.time().timeName(), mesh, IOobject::NO_READ,
            dict_.lookupOrDefault<Switch>("writeExchangeFields", false) ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
        ),
        mesh, dimensionedScalar(dimless/dimTime, Zero)
    ),
    KslUs
    (
        IOobject
        (
            "KslUs", mesh.time().timeName(), mesh, IOobject::NO_READ,
            dict_.lookupOrDefault<Switch>("writeExchangeFields", false) ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
        ),
        mesh, dimensionedVector(dimAcceleration, Zero)
    ),
    fFluid
    (
        IOobject("fFluid", mesh.time().timeName(), mesh, IOobject::NO_READ, IOobject::AUTO_WRITE),
        mesh, dimensionedVector(dimAcceleration, Zero)
    )
{
    checkEntries();
    forces_.reset(new particleForces(dict_, modelB_, fluid_));
    averaging_ = fluidAveraging::New(dict_, demMesh_, voidFraction_);
    outputFields_.reset(new particleOutputFields(mesh, dict_, demMesh_, voidFraction_));
    dem_.reset(new liggghtsDem(mesh, dict_));
    checkDemUnits(dem_->lammps(), mesh, dict_);    // DEM box and particles against the mesh
    checkDemCoarseGraining(dem_->lammps(), cgFactor_, dict_);
    // vs Rayleigh and Hertz times (warn / stop), then the neighbour lists vs the particle sizes it measured
    checkDemNeighbours(dem_->lammps(), dict_, checkDemTimestep(dem_->lammps(), dict_));
    keepRestartForces_ = dem_->restarted();

    printSummary();
}

coarseDemCoupling::~coarseDemCoupling()
{
}

void coarseDemCoupling::evolveDem()
{
    timers_.start(stageTimers::dem);
    dem_->run(couplingInterval_);
    diag_.exchange.setSegment(couplingInterval_*dem_->timestep());
    timers_.stop();
}

cdc_particles coarseDemCoupling::coreParticles() const
{
    static_assert(sizeof(long long) == sizeof(int64_t), "DEM ids are 64 bit");
    return {int32_t(particles_.size()), particles_.x.data(), particles_.radius.data(),
            reinterpret_cast<const int64_t*>(particles_.id.data()), nullptr};
}

void coarseDemCoupling::couple
(
    const volVectorField& U, volScalarField& alpha, const volScalarField& p,
    const volScalarField& nuEff, const volVectorField* DUDt
)
{
    ++nCouplings_;
    pullParticles();                           // particles_ from the DEM, ghosts_ from the neighbours
    // the particles that entered and left (the loss guard), and the momentum exchanged over the last
    // DEM segment unless particles entered or left in it
    timers_.start(stageTimers::monitor);
    const bool segmentChanged = diag_.inventory.update(particles_);
    timers_.stop();
    compareExchangeInTime(U, segmentChanged);
    const cdc_particles cp = coreParticles();  // NaN positions and bad radii are caught by the core
    const cdc_particles cg = {int32_t(ghosts_.size()), ghosts_.x.data(), ghosts_.radius.data(),
                              reinterpret_cast<const int64_t*>(ghosts_.id.data()), nullptr};
    updateVoidFraction(cp, cg, alpha);         // kernels, alpha_p, alpha
    timers_.start(stageTimers::forces);       // the fluid sampled at the particles, their forces
    forces_->setParticles(particles_, cgFactor_, mesh_.time().timeName());
    sampleFluid(U, alpha, p, nuEff, DUDt);
    forces_->evaluate(particles_, mesh_.time().deltaTValue());
    timers_.stop();
    timers_.start(stageTimers::monitor);
    diag_.crossings.update(particles_.id, cdc_kernels_hosts(voidFraction_.kernels()), forces_->state().Uf,
                      forces_->state().v, mesh_.time().value());
    timers_.stop();
    pushForces();                              // to the DEM for its next segment

    timers_.start(stageTimers::sources);
    diag_.exchange.setCfdStep(mesh_.time().deltaTValue());
    fluidSources(U);                           // Ksl, KslUs, fFluid with the same kernels
    Ksl.correctBoundaryConditions();
    KslUs.correctBoundaryConditions();
    fFluid.correctBoundaryConditions();
    timers_.stop();

    timers_.start(stageTimers::fields);        // alphaPUs, binned fields: no effect on the flow
    outputFields_->update(cp, cg, halo_, particles_, forces_->volumes(), forces_->state().v,
        [this](const cdc_kernels* k, const double* local, int ncomp, double* out) { transfer_.spread(k, local, ncomp, out); });
    timers_.stop();
    recordBalances(U);                         // solid volume and momentum for the Coupling line
    checkExplicitRange(alpha);
    if (nCouplings_ == 1) adviseOnSetup(dict_, voidFraction_, mesh_.V(), particles_.radius);
    if (nCouplings_ == 1 || mesh_.time().writeTime())
    {
        // a parcel filling a cell beyond the packing limit; dense cells the drag misses
        const word time = mesh_.time().timeName();
        diag_.coverage.checkParcelFill(voidFraction_, forces_->volumes(), particles_, mesh_.V(), cgFactor_, dict_.name(), time);
        diag_.coverage.checkDragCoverage(voidFraction_, averaging_->reaction(), alphaP, dict_.name(), time);
    }
}

// The DEM's particles of this rank and the ghosts: copies of the neighbours' particles whose kernels
// (or background kernels) reach into this rank's cells.
void coarseDemCoupling::pullParticles()
{
    dem_->pull(particles_);
    const label n = particles_.size();
    nParticles_ = returnReduce(n, sumOp<label>());
    timers_.start(stageTimers::ghosts);
    reach_.resize(n);
    for (label i = 0; i < n; ++i)
    {
        reach_[i] = averaging_->reach(particles_.radius[i]);
    }
    halo_.update(particles_, reach_, ghosts_);
    timers_.stop();
}

// Kernels, alpha_p (smoothed and limited by voidFraction), alpha, and the background kernels.
void coarseDemCoupling::updateVoidFraction(const cdc_particles& cp, const cdc_particles& cg, volScalarField& alpha)
{
    voidFraction_.update(cp, cg, halo_, alphaP.primitiveFieldRef());
    double tLocate = 0, tKernel = 0;
    cdc_kernels_timing(voidFraction_.kernels(), &tLocate, &tKernel);
    timers_.add(stageTimers::locate, tLocate);
    timers_.add(stageTimers::kernel, tKernel);
    timers_.add(stageTimers::alphaP, voidFraction_.alphaPSeconds());
    alphaP.correctBoundaryConditions();
    setFluidFraction(alpha);
    timers_.start(stageTimers::kernel);
    averaging_->build(cp, cg, halo_);   // the background kernels, when they are kernels of their own
    timers_.stop();
}

// The forces to the DEM for its next segment: with implicitParticleDrag the other forces as a force
// and the drag as K and u_f (the fix applies K (u_f - v) with v of each DEM step), else all as a force.
// A run's first coupling after a restart keeps the forces stored in the DEM restart instead.
void coarseDemCoupling::pushForces()
{
    timers_.start(stageTimers::forces);
    forces_->packForDem(switches_.implicitParticleDrag);
    timers_.stop();
    timers_.start(stageTimers::push);
    if (keepRestartForces_)
    {
        keepRestartForces_ = false;   // the balance line of this step describes forces not applied
        diag_.exchange.setPending(false);
    }
    else
    {
        dem_->push(forces_->demForce());
        if (switches_.implicitParticleDrag) dem_->pushDrag(forces_->demDragK(), forces_->demDragUf());
        diag_.exchange.setPending(nCouplings_ > 1);
    }
    timers_.stop();
}

// alpha = 1 - alpha_p; with alphaRelaxationTime tau > 0 the fluid fraction follows the particles' with
// the time constant tau: alpha(n+1) = alpha(n) + w (1 - alpha_p - alpha(n)), w = min(1, dt/tau).
// Why: a kernel whose cells enter or leave as its particle moves (centre, divided, bigParticle, a
// truncated gaussian) changes alpha_p by a jump within one CFD step, whatever the step. The fluid has to
// displace that volume within the step; the pressure pulse this takes grows as 1/dt and reaches the
// particles through -V grad(p), so the CFD-step refinement of a fluidized bed does not converge
// (tests/stability/README.md, refinement study). With tau fixed, d(alpha)/dt stays bounded as the step
// shrinks; steps >= tau are unchanged (w = 1). A convex combination of two fields that each hold the
// particles' volume holds it too, and stays within [alphaMin, 1].
void coarseDemCoupling::setFluidFraction(volScalarField& alpha)
{
    scalarField& a = alpha.primitiveFieldRef();   // first: stores the old-time alpha at a new time step
    const scalarField& ap = alphaP.primitiveField();
    scalar w = 1;
    if (alphaRelaxationTime_ > 0)
    {
        // a run's first coupling: the particles' alpha at a fresh start, at a restart the alpha read
        // from the restart time (the uninterrupted run's, which already lags the particles')
        w = nCouplings_ > 1
          ? min(scalar(1), mesh_.time().deltaTValue()/alphaRelaxationTime_)
          : (dem_->restarted() ? 0 : 1);
    }
    if (w >= 1)
    {
        a = 1 - ap;
    }
    else if (w > 0)
    {
        a = (1 - w)*alpha.oldTime().primitiveField() + w*(1 - ap);
    }
    alpha.correctBoundaryConditions();
    if (alphaRelaxationTime_ > 0) diag_.balances.solidVolumeAlpha = gSum((1 - a)*mesh_.V());
}

void coarseDemCoupling::write()
{
    if (!mesh_.time().writeTime()) return;
    diag_.inventory.write(particles_);
    if (switches_.demRestart)
    {
        const fileName dir = mesh_.time().globalPath()/mesh_.time().timeName();
        if (Pstream::master()) mkDir(dir);
        dem_->writeRestart(dir/"dem.restart");
    }
    if (switches_.writeParticleCloud)
    {
        // the particles of this step's coupling, with the force it gave each (drag and the others)
        const label n = particles_.size();
        scalarField d(n);
        vectorField f(n);
        for (label i = 0; i < n; ++i)
        {
            d[i] = 2*particles_.radius[i];
            f[i] = forces_->force(i);
        }
        writeParticleCloud(mesh_, "particles", particles_, cdc_kernels_hosts(voidFraction_.kernels()), d, f);
    }
}

} // End namespace Foam
