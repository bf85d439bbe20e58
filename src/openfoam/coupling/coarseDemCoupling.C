#include "coarseDemCoupling.H"
#include "demTimeStepCheck.H"
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

// The sub-dictionaries of couplingProperties are the <model>Props of the models. One whose name
// matches no model (a misspelt name) would be ignored and its model would run with the defaults:
// refuse it, naming the dictionaries that are read. Returns its argument, so that the check runs
// before the first model reads its dictionary.
static const dictionary& checkPropsDictionaries(const dictionary& dict)
{
    wordHashSet known{"backgroundFieldsProps", "diffusionProps", "sizeAwareDiffusionProps"};
    for (int i = 0; i < cdc_method_count(); ++i) known.insert(word(cdc_method_name(i)) + "Props");
    for (const word& f : forceModel::dictionaryConstructorTablePtr_->sortedToc()) known.insert(f + "Props");
    for (const entry& e : dict)
    {
        const word& k = e.keyword();
        if (e.isDict() && k != "FoamFile" && !known.found(k))
        {
            string names;
            for (const word& w : known.sortedToc()) names += (names.empty() ? "" : ", ") + w;
            FatalIOErrorInFunction(dict)
                << "unknown dictionary " << k << " in " << dict.name() << " (a misspelt model name?"
                << " it would be ignored)" << nl << "    dictionaries read: " << names.c_str()
                << exit(FatalIOError);
        }
    }
    return dict;
}

coarseDemCoupling::coarseDemCoupling
(
    const fvMesh& mesh, const dimensionedScalar& rho, const dimensionedScalar& nu, const dimensionedVector& g
)
:
    mesh_(mesh),
    dict_(couplingDictIO(mesh)),
    modelB_(false),
    couplingInterval_(checkPropsDictionaries(dict_).get<label>("couplingInterval")),
    implicitDrag_(dict_.lookupOrDefault<Switch>("implicitDrag", true)),
    implicitParticleDrag_(dict_.lookupOrDefault<Switch>("implicitParticleDrag", true)),
    demRestart_(dict_.lookupOrDefault<Switch>("demRestart", true)),
    allowParticleLoss_(dict_.lookupOrDefault<Switch>("allowParticleLoss", false)),
    cgFactor_(dict_.lookupOrDefault<scalar>("coarseGrainingFactor", 1)),
    alphaRelaxationTime_(dict_.lookupOrDefault<scalar>("alphaRelaxationTime", 0)),
    fluid_{rho.value(), nu.value(), g.value()},
    demMesh_(mesh, dict_),
    voidFraction_(dict_, demMesh_),
    backgroundKernels_(nullptr),
    binKernels_(nullptr),
    particleFieldsInterval_(dict_.lookupOrDefault<scalar>("particleFieldsInterval", 0)),
    particleFieldsIndex_(-1),
    needs_(0),
    halo_(mesh),
    solidVolumeParticles_(0), solidVolumeCells_(0), momentumImbalance_(0), forceScale_(0),
    nParticles_(0),
    nParticlesBefore_(-1),
    particleDragRatio_(0),
    nParticlesBeyond_(0),
    fluidDragRatio_(0),
    nCellsBeyond_(0),
    warnedParticleSide_(false),
    warnedFluidSide_(false),
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
    const wordList names(readForceModels());
    createBackgroundKernels();
    createOutputFields();
    dem_.reset(new liggghtsDem(mesh, dict_));
    checkDemUnits(dem_->lammps(), mesh, dict_);    // DEM box and particles against the mesh
    checkDemTimestep(dem_->lammps(), dict_);   // vs Rayleigh and Hertz times: warn / stop
    keepRestartForces_ = dem_->restarted();

    printSummary(names);
}

coarseDemCoupling::~coarseDemCoupling()
{
    cdc_kernels_destroy(backgroundKernels_);
    cdc_kernels_destroy(binKernels_);
}

// The top-level entries with a range: refused, naming the entry, when out of it.
void coarseDemCoupling::checkEntries()
{
    const word modelType = dict_.get<word>("modelType");
    if (modelType != "A" && modelType != "B")
    {
        FatalIOErrorInFunction(dict_)
            << "entry modelType " << modelType << " in " << dict_.name() << " is invalid" << nl
            << "    valid model types: A (alpha grad p in the fluid) B (grad p)" << exit(FatalIOError);
    }
    modelB_ = modelType == "B";
    if (couplingInterval_ <= 0)
    {
        FatalIOErrorInFunction(dict_)
            << "entry couplingInterval " << couplingInterval_ << " in " << dict_.name()
            << " is invalid: must be a positive number of DEM steps" << exit(FatalIOError);
    }
    if (!(alphaRelaxationTime_ >= 0))
    {
        FatalIOErrorInFunction(dict_)
            << "entry alphaRelaxationTime " << alphaRelaxationTime_ << " in " << dict_.name()
            << " is invalid: must be >= 0 (s; 0: alpha = 1 - alpha_p at every step)" << exit(FatalIOError);
    }
    if (!(cgFactor_ >= 1))
    {
        FatalIOErrorInFunction(dict_)
            << "entry coarseGrainingFactor " << cgFactor_ << " in " << dict_.name()
            << " is invalid: must be >= 1" << exit(FatalIOError);
    }
}

// forceModels: the models, what they need, and the combinations that count a force twice or miss one.
wordList coarseDemCoupling::readForceModels()
{
    const wordList names(dict_.get<wordList>("forceModels"));
    bool hasDrag = false, hasGradP = false, hasArchimedes = false;
    forAll(names, i)
    {
        forces_.append(forceModel::New(names[i], dict_));
        needs_ |= forces_.last().needs();
        hasDrag = hasDrag || forces_.last().isDrag();
        hasGradP = hasGradP || names[i] == "gradPForce";
        hasArchimedes = hasArchimedes || names[i] == "Archimedes";
    }
    if (!hasDrag)
    {
        WarningInFunction << "no drag model in forceModels of " << dict_.name() << endl;
    }
    if (!modelB_ && names.size() && !hasGradP)
    {
        // Model A's fluid carries -alpha grad(p) (Zhang et al. 2023 eq. 15): the particles must get
        // -V grad(p), or the dynamic pressure force leaves the fluid and reaches no particle.
        FatalIOErrorInFunction(dict_)
            << "forceModels in " << dict_.name() << " lacks gradPForce, which modelType A needs: the"
            << " fluid equation has alpha grad(p), so the particles must get -V grad(p)" << nl
            << "    (or modelType B with drag and Archimedes: the drag is then divided by the fluid"
            << " fraction)" << exit(FatalIOError);
    }
    dragOverAlpha_ = modelB_ && !hasGradP;
    if (dragOverAlpha_ && !hasArchimedes && mag(fluid_.g) > 0)
    {
        WarningInFunction
            << "modelType B without gradPForce or Archimedes in " << dict_.name() << ": the particles"
            << " get no buoyancy (rho_f V g); add Archimedes (drag / alpha_f carries the rest of the"
            << " pressure gradient)" << endl;
    }
    if (hasGradP && hasArchimedes)
    {
        FatalIOErrorInFunction(dict_)
            << "forceModels in " << dict_.name() << " has both gradPForce and Archimedes: the pressure"
            << " gradient already carries the buoyancy, so it would be counted twice" << exit(FatalIOError);
    }
    return names;
}

// backgroundFields on: u and alpha at the particles from bigParticle kernels (Zhang et al. eqs. 21-22).
void coarseDemCoupling::createBackgroundKernels()
{
    if (!dict_.lookupOrDefault<Switch>("backgroundFields", false)) return;
    {
        cdc_kernel_params prm = readKernelParams(dict_, "backgroundFields", "bigParticle");
        if (prm.expansion_factor == 0) prm.expansion_factor = 5;
        const cdc_status st = cdc_kernels_create(demMesh_.context(), "bigParticle", &prm, &backgroundKernels_);
        if (st != CDC_OK)
        {
            FatalIOErrorInFunction(dict_)
                << "backgroundFieldsProps in " << dict_.name() << ": " << cdc_last_error(demMesh_.context())
                << exit(FatalIOError);
        }
    }
}

// Output-only fields: alphaPUs (solidVelocityField) and the binned particle fields.
void coarseDemCoupling::createOutputFields()
{
    const fvMesh& mesh = mesh_;
    if (dict_.lookupOrDefault<Switch>("solidVelocityField", false))
    {
        if (!voidFraction_.canSmoothLikeAlpha())
        {
            WarningInFunction
                << "solidVelocityField with smoothingModel sizeAwareDiffusion: alphaPUs is not smoothed"
                << " (each size class has its own bandwidth), so alphaPUs/alphaP is not the solid velocity"
                << endl;
        }
        alphaPUs.reset
        (
            new volVectorField
            (
                IOobject("alphaPUs", mesh.time().timeName(), mesh, IOobject::NO_READ, IOobject::AUTO_WRITE),
                mesh, dimensionedVector(dimVelocity, Zero), zeroGradientFvPatchVectorField::typeName
            )
        );
    }

    if (dict_.lookupOrDefault<Switch>("binnedParticleFields", false))
    {
        cdc_kernel_params prm = {};
        if (cdc_kernels_create(demMesh_.context(), "centre", &prm, &binKernels_) != CDC_OK)
        {
            FatalIOErrorInFunction(dict_)
                << "binnedParticleFields in " << dict_.name() << ": " << cdc_last_error(demMesh_.context())
                << exit(FatalIOError);
        }
        const word t = mesh.time().timeName();
        alphaPBinned.reset
        (
            new volScalarField
            (
                IOobject("alphaPBinned", t, mesh, IOobject::NO_READ, IOobject::AUTO_WRITE),
                mesh, dimensionedScalar(dimless, Zero), zeroGradientFvPatchScalarField::typeName
            )
        );
        alphaPUsBinned.reset
        (
            new volVectorField
            (
                IOobject("alphaPUsBinned", t, mesh, IOobject::NO_READ, IOobject::AUTO_WRITE),
                mesh, dimensionedVector(dimVelocity, Zero), zeroGradientFvPatchVectorField::typeName
            )
        );
    }
}

void coarseDemCoupling::printSummary(const wordList& names) const
{
    const word modelType(modelB_ ? "B" : "A");
    Info<< "coarseDemCoupling: model " << modelType << ", voidFractionModel " << voidFraction_.method()
        << ", smoothing " << voidFraction_.smoothingName()
        << (voidFraction_.smoothsExchangeFields() ? " (alpha_p and the fluid's sources)" : "")
        << ", background fields "
        << (backgroundKernels_ ? "bigParticle kernel" : "void-fraction kernels")
        << ", drag on the fluid " << (implicitDrag_ ? "implicit" : "explicit") << ", on the particles "
        << (implicitParticleDrag_ ? "every DEM step" : "held for the CFD step") << ", forces " << names
        << ", DEM step " << dem_->timestep() << " s x " << couplingInterval_;
    if (alphaRelaxationTime_ > 0)
    {
        Info<< ", fluid fraction relaxed over " << alphaRelaxationTime_ << " s (alphaRelaxationTime)";
    }
    Info<< endl;
    Info<< endl;
}

void coarseDemCoupling::evolveDem()
{
    timers_.start(stageTimers::dem);
    dem_->run(couplingInterval_);
    segmentSeconds_ = couplingInterval_*dem_->timestep();
    timers_.stop();
}

Foam::vector coarseDemCoupling::fluidMomentumSource(const volVectorField& U) const
{
    const scalarField& V = mesh_.V();
    return fluid_.rho*gSum
    (
        (fFluid.primitiveField() - Ksl.primitiveField()*U.primitiveField() + KslUs.primitiveField())*V
    );
}

void coarseDemCoupling::compareExchangeInTime(const volVectorField& U)
{
    // before the exchange fields are replaced: U is the fluid's velocity after the step that used
    // them, and the DEM has just run the segment that used them
    if (!exchangePending_) return;
    const vector particles =
        returnReduce(dem_->couplingImpulse(), sumOp<vector>()) - segmentSeconds_*nonReacting_;
    const vector fluid = exchangeDt_*fluidMomentumSource(U);
    // relative to the larger of the step's exchange at the coupling (CFD step x sum |f|) and either
    // phase's impulse: at a start from rest the forces at the coupling are near zero while the fluid's
    // implicit drag at its new velocity is not, and the difference is then the whole impulse (1)
    const scalar exchanged = exchangeDt_*forceScale_;
    const scalar scale = max(exchanged, max(mag(particles), mag(fluid)));
    exchangeLastRel_ = scale > 0 ? mag(particles + fluid)/scale : 0;
    exchangeMaxRel_ = max(exchangeMaxRel_, exchangeLastRel_);
    exchangeNet_ += particles + fluid;
    exchangeGross_ += exchanged;
    ++nExchangesCompared_;
}

void coarseDemCoupling::sampleFluid
(
    const volVectorField& U, const volScalarField& alpha, const volScalarField& p,
    const volScalarField& nuEff, const volVectorField* DUDt
)
{
    const cdc_kernels* k = backgroundKernels_ ? backgroundKernels_ : voidFraction_.kernels();
    const label n = state_.n;
    auto gatherVector = [&](const vectorField& field, vectorField& out)
    {
        out.setSize(n);
        gather(k, reinterpret_cast<const double*>(field.cdata()), 3, reinterpret_cast<double*>(out.data()));
    };
    gatherVector(U.primitiveField(), state_.Uf);
    state_.alphaf.setSize(n);
    gather(k, alpha.primitiveField().cdata(), 1, state_.alphaf.data());
    if (needs_ & forceModel::needGradP)
    {
        gatherVector(fvc::grad(p)().primitiveField(), state_.gradP);
    }
    if (needs_ & forceModel::needDivTau)
    {
        const volVectorField divTau
        (
            fvc::laplacian(nuEff, U) + fvc::div(nuEff*noAliasFvc::dev2GradUT(U))
        );
        gatherVector(divTau.primitiveField(), state_.divTau);
    }
    if ((needs_ & forceModel::needDUfDt) && DUDt)
    {
        gatherVector(DUDt->primitiveField(), state_.DUfDt);
    }
    if (needs_ & forceModel::needVorticity)
    {
        gatherVector(noAliasFvc::curl(U)().primitiveField(), state_.vorticity);
    }
}

cdc_particles coarseDemCoupling::coreParticles() const
{
    static_assert(sizeof(long long) == sizeof(int64_t), "DEM ids are 64 bit");
    return {int32_t(particles_.size()), particles_.x.data(), particles_.radius.data(),
            reinterpret_cast<const int64_t*>(particles_.id.data()), nullptr};
}

void coarseDemCoupling::gather(const cdc_kernels* k, const double* field, int ncomp, double* out)
{
    const label n = particles_.size(), ng = ghosts_.size();
    buffer_.resize(size_t(n + ng)*ncomp);
    demMesh_.check(cdc_gather(k, field, ncomp, buffer_.data()), "gather");
    halo_.addToOwners(buffer_.data() + size_t(n)*ncomp, ncomp, buffer_.data());
    std::copy(buffer_.begin(), buffer_.begin() + size_t(n)*ncomp, out);
}

void coarseDemCoupling::spread(const cdc_kernels* k, const double* local, int ncomp, double* out)
{
    withGhosts(local, ncomp, buffer_);
    demMesh_.check(cdc_spread(k, buffer_.data(), ncomp, out), "spread");
}

void coarseDemCoupling::withGhosts(const double* local, int ncomp, std::vector<double>& all)
{
    const label n = particles_.size();
    halo_.toGhosts(local, ncomp, ghostBuffer_);
    all.assign(local, local + size_t(n)*ncomp);
    all.insert(all.end(), ghostBuffer_.begin(), ghostBuffer_.end());
}

// The fluid's sources from the particles' forces, with the void-fraction kernels (src/core/exchange.c:
// Newton's third law between the phases to round-off, for every method). Implicit drag: Ksl, KslUs and
// the other reacting forces in fFluid, with the background-fields correction K (u_f - u_k) (the
// implicit sink takes K u_k with U gathered by these kernels, the particles got K u_f). Explicit drag,
// and smoothExchangeFields: the whole reaction in fFluid; with smoothExchangeFields and implicit drag
// the smoothed Ksl enters as -Ksl (U_new - U) (KslUs = Ksl U), zero at the current U, which keeps the
// fluid's response to a large dt Ksl/alpha stable (CFDEM's implicit/explicit split of the drag).
void coarseDemCoupling::fluidSources(const volVectorField& U)
{
    const label n = particles_.size();
    const bool smooth = voidFraction_.smoothsExchangeFields();
    const bool implicit = implicitDrag_ && !smooth;
    const cdc_kernels* k = voidFraction_.kernels();
    withGhosts(K_.cdata(), 1, exchangeK_);
    withGhosts(reinterpret_cast<const double*>(state_.v), 3, exchangeV_);
    withGhosts(reinterpret_cast<const double*>(state_.Uf.cdata()), 3, exchangeUf_);
    withGhosts(reinterpret_cast<const double*>(fReact_.cdata()), 3, exchangeF_);
    const bool correct = implicit && backgroundKernels_;
    if (correct)
    {
        vectorField uKernel(n);
        gather(k, reinterpret_cast<const double*>(U.primitiveField().cdata()), 3, reinterpret_cast<double*>(uKernel.data()));
        withGhosts(reinterpret_cast<const double*>(uKernel.cdata()), 3, exchangeUk_);
    }
    const cdc_exchange_in in =
    {
        int32_t(exchangeK_.size()), exchangeK_.data(), exchangeV_.data(), exchangeUf_.data(),
        correct ? exchangeUk_.data() : nullptr, exchangeF_.data(), fluid_.rho,
        implicit ? CDC_EXCHANGE_IMPLICIT : CDC_EXCHANGE_EXPLICIT
    };
    double* f = reinterpret_cast<double*>(fFluid.primitiveFieldRef().data());
    demMesh_.check
    (
        cdc_exchange_sources(k, &in, Ksl.primitiveFieldRef().data(),
                             reinterpret_cast<double*>(KslUs.primitiveFieldRef().data()), f),
        "momentum exchange"
    );
    if (smooth)
    {
        // diffusion in flux form keeps sum(f V), so the balance holds as spread
        voidFraction_.smoothLikeAlpha(f, 3);
        if (implicitDrag_)
        {
            scalarField Kr(K_/fluid_.rho);
            spread(k, Kr.cdata(), 1, Ksl.primitiveFieldRef().data());
            voidFraction_.smoothLikeAlpha(Ksl.primitiveFieldRef().data(), 1);
            KslUs.primitiveFieldRef() = Ksl.primitiveField()*U.primitiveField();
        }
    }
}

bool coarseDemCoupling::particleFieldsDue()
{
    const Time& rt = mesh_.time();
    if (particleFieldsInterval_ <= 0) return true;
    // the step nearest each multiple of the interval since the start, as an adjustableRunTime
    // function object samples (Time's and timeControl's index rule), plus the write times
    const label index = label((rt.value() - rt.startTime().value() + 0.5*rt.deltaTValue())/particleFieldsInterval_);
    if (index <= particleFieldsIndex_ && !rt.writeTime()) return false;
    particleFieldsIndex_ = max(index, particleFieldsIndex_);
    return true;
}

void coarseDemCoupling::binParticles
(
    const cdc_particles& local, const cdc_particles& ghosts, const vectorField& volumeVelocity
)
{
    buildKernels(demMesh_, binKernels_, local, ghosts, halo_, "binnedParticleFields (centre kernels)");
    spread(binKernels_, volume_.data(), 1, alphaPBinned().primitiveFieldRef().data());
    spread(binKernels_, reinterpret_cast<const double*>(volumeVelocity.cdata()), 3,
           reinterpret_cast<double*>(alphaPUsBinned().primitiveFieldRef().data()));
    alphaPBinned().correctBoundaryConditions();
    alphaPUsBinned().correctBoundaryConditions();
}

void coarseDemCoupling::couple
(
    const volVectorField& U, volScalarField& alpha, const volScalarField& p,
    const volScalarField& nuEff, const volVectorField* DUDt
)
{
    compareExchangeInTime(U);                  // the momentum exchanged over the last DEM segment
    ++nCouplings_;
    pullParticles();                           // particles_ from the DEM, ghosts_ from the neighbours
    const cdc_particles cp = coreParticles();  // NaN positions and bad radii are caught by the core
    const cdc_particles cg = {int32_t(ghosts_.size()), ghosts_.x.data(), ghosts_.radius.data(),
                              reinterpret_cast<const int64_t*>(ghosts_.id.data()), nullptr};
    updateVoidFraction(cp, cg, alpha);         // kernels, alpha_p, alpha
    particleForces(U, alpha, p, nuEff, DUDt);  // K_, fOther_, fReact_ per particle
    pushForces();                              // to the DEM for its next segment

    timers_.start(stageTimers::exchange);
    exchangeDt_ = mesh_.time().deltaTValue();
    fluidSources(U);                           // Ksl, KslUs, fFluid with the same kernels
    Ksl.correctBoundaryConditions();
    KslUs.correctBoundaryConditions();
    fFluid.correctBoundaryConditions();
    timers_.stop();

    outputFields(cp, cg);                      // alphaPUs, binned fields: no effect on the flow
    recordBalances(U);                         // solid volume and momentum for the Coupling line
    checkExplicitRange(alpha);
}

// The DEM's particles of this rank, checked against the last count, and the ghosts: copies of the
// neighbours' particles whose kernels (or background kernels) reach into this rank's cells.
void coarseDemCoupling::pullParticles()
{
    dem_->pull(particles_);
    const label n = particles_.size();
    nParticles_ = returnReduce(n, sumOp<label>());
    checkParticleCount();
    timers_.start(stageTimers::exchange);
    reach_.resize(n);
    for (label i = 0; i < n; ++i)
    {
        const double r = particles_.radius[i];
        reach_[i] = cdc_kernels_reach(voidFraction_.kernels(), r) + r;
        if (backgroundKernels_) reach_[i] = max(reach_[i], cdc_kernels_reach(backgroundKernels_, r) + r);
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
    timers_.add(stageTimers::smoothing, voidFraction_.smoothingSeconds());
    alphaP.correctBoundaryConditions();
    setFluidFraction(alpha);
    if (backgroundKernels_)
    {
        timers_.start(stageTimers::kernel);
        buildKernels(demMesh_, backgroundKernels_, cp, cg, halo_, "background kernels");
        timers_.stop();
    }
}

// The particles' diameters and volumes, the fluid sampled at them, and the enabled forces: the drag
// coefficient K_ (drag K (u_f - v)), the other forces fOther_, of which fReact_ acts back on the fluid.
void coarseDemCoupling::particleForces
(
    const volVectorField& U, const volScalarField& alpha, const volScalarField& p,
    const volScalarField& nuEff, const volVectorField* DUDt
)
{
    const scalar pi = constant::mathematical::pi;
    const label n = particles_.size();
    timers_.start(stageTimers::forces);
    diameter_.resize(n);
    volume_.resize(n);
    for (label i = 0; i < n; ++i)
    {
        const double r = particles_.radius[i];
        if (!std::isfinite(particles_.v[3*i]) || !std::isfinite(particles_.v[3*i + 1]) || !std::isfinite(particles_.v[3*i + 2]))
        {
            FatalErrorInFunction
                << "particle " << label(particles_.id[i]) << " has a non-finite velocity at time "
                << mesh_.time().timeName() << " (DEM diverged: check the DEM time step)" << exit(FatalError);
        }
        diameter_[i] = 2*r/cgFactor_;
        volume_[i] = 4.0/3.0*pi*r*r*r;
    }
    state_.n = n;
    state_.v = reinterpret_cast<const vector*>(particles_.v.data());
    state_.d = diameter_.data();
    state_.volume = volume_.data();
    sampleFluid(U, alpha, p, nuEff, DUDt);
    if (needs_ & forceModel::needDvDt) particleAccelerations();

    K_.setSize(n);
    K_ = 0;
    fOther_.setSize(n);
    fOther_ = Zero;
    fReact_.setSize(n);
    fReact_ = Zero;
    scalarField Ki(n);
    vectorField fi(n);
    for (const forceModel& fm : forces_)
    {
        if (fm.isDrag())
        {
            Ki = 0;
            fm.dragCoefficient(state_, fluid_, Ki);
            K_ += Ki;
        }
        else
        {
            fi = Zero;
            fm.addForce(state_, fluid_, fi);
            fOther_ += fi;
            if (fm.reactsOnFluid(modelB_)) fReact_ += fi;
        }
    }
    // Model B without gradPForce (Zhou et al. 2010, CFDEM's modelType B): the fluid carries -grad(p)
    // and every reaction; the particles get the dynamic pressure gradient's share through the drag
    // divided by the fluid fraction, for every drag law (without it a gas bed at eps 0.42 would
    // fluidize at 0.77 instead of 0.43 m/s)
    if (dragOverAlpha_)
    {
        forAll(K_, i) K_[i] /= state_.alphaf[i];
    }
    timers_.stop();
}

// The forces to the DEM for its next segment: with implicitParticleDrag the other forces as a force
// and the drag as K and u_f (the fix applies K (u_f - v) with v of each DEM step), else all as a force.
// A run's first coupling after a restart keeps the forces stored in the DEM restart instead.
void coarseDemCoupling::pushForces()
{
    const label n = particles_.size();
    timers_.start(stageTimers::forces);
    force_.resize(3*n);
    dragK_.resize(implicitParticleDrag_ ? n : 0);
    dragUf_.resize(implicitParticleDrag_ ? 3*n : 0);
    for (label i = 0; i < n; ++i)
    {
        const vector f = K_[i]*(state_.Uf[i] - state_.v[i]) + fOther_[i];
        const vector fDem = implicitParticleDrag_ ? fOther_[i] : f;
        for (direction d = 0; d < 3; ++d) force_[3*i + d] = fDem[d];
        if (implicitParticleDrag_)
        {
            dragK_[i] = K_[i];
            for (direction d = 0; d < 3; ++d) dragUf_[3*i + d] = state_.Uf[i][d];
        }
    }
    timers_.stop();
    timers_.start(stageTimers::exchange);
    if (keepRestartForces_)
    {
        keepRestartForces_ = false;   // the balance line of this step describes forces not applied
        exchangePending_ = false;
    }
    else
    {
        dem_->push(force_);
        if (implicitParticleDrag_) dem_->pushDrag(dragK_, dragUf_);
        exchangePending_ = nCouplings_ > 1;
    }
    timers_.stop();
}

// Output-only fields (no effect on the flow): particle volume x velocity, spread with the method's
// kernels and/or binned by centre; only on the steps they are sampled or written.
void coarseDemCoupling::outputFields(const cdc_particles& cp, const cdc_particles& cg)
{
    if (!(alphaPUs.valid() || binKernels_) || !particleFieldsDue()) return;
    timers_.start(stageTimers::fields);
    vectorField q(particles_.size());
    forAll(q, i) q[i] = volume_[i]*state_.v[i];
    if (alphaPUs.valid())
    {
        double* aUs = reinterpret_cast<double*>(alphaPUs().primitiveFieldRef().data());
        spread(reinterpret_cast<const double*>(q.cdata()), 3, aUs);
        voidFraction_.smoothLikeAlpha(aUs, 3);   // as alphaP, so alphaPUs/alphaP is a velocity
        alphaPUs().correctBoundaryConditions();
    }
    if (binKernels_) binParticles(cp, cg, q);
    timers_.stop();
}

// Balances for the Coupling line: solid volume in cells vs particles; the momentum the fluid gets (at
// the current U) vs minus what the particles get from the forces that act back on it.
void coarseDemCoupling::recordBalances(const volVectorField& U)
{
    timers_.start(stageTimers::exchange);
    vector fParticles(Zero);
    forceScale_ = 0;
    nonReacting_ = Zero;
    forAll(K_, i)
    {
        const vector f = K_[i]*(state_.Uf[i] - state_.v[i]) + fOther_[i];
        fParticles += K_[i]*(state_.Uf[i] - state_.v[i]) + fReact_[i];
        nonReacting_ += fOther_[i] - fReact_[i];
        forceScale_ += mag(f);
    }
    scalar vp = 0;
    for (const double v : volume_) vp += v;
    solidVolumeParticles_ = returnReduce(vp, sumOp<scalar>());
    solidVolumeCells_ = gSum(alphaP.primitiveField()*mesh_.V());
    const vector fluidTotal = fluidMomentumSource(U);
    reduce(fParticles, sumOp<vector>());
    reduce(nonReacting_, sumOp<vector>());
    reduce(forceScale_, sumOp<scalar>());
    momentumImbalance_ = mag(fluidTotal + fParticles);
    timers_.stop();
}

void coarseDemCoupling::particleAccelerations()
{
    const label n = particles_.size();
    const scalar dt = mesh_.time().deltaTValue();
    Map<vector> current(2*n);
    for (label i = 0; i < n; ++i) current.set(label(particles_.id[i]), state_.v[i]);
    if (Pstream::parRun())
    {
        // A particle that changed rank since the last coupling left its velocity on the old rank:
        // every rank shares the velocities of its particles that are gone (few: those that crossed).
        List<labelList> goneIds(Pstream::nProcs());
        List<vectorField> goneVelocities(Pstream::nProcs());
        DynamicList<label> ids;
        DynamicList<vector> velocities;
        forAllConstIters(previousVelocity_, iter)
        {
            if (!current.found(iter.key()))
            {
                ids.append(iter.key());
                velocities.append(iter.val());
            }
        }
        goneIds[Pstream::myProcNo()] = ids;
        goneVelocities[Pstream::myProcNo()] = velocities;
        Pstream::gatherList(goneIds);
        Pstream::scatterList(goneIds);
        Pstream::gatherList(goneVelocities);
        Pstream::scatterList(goneVelocities);
        forAll(goneIds, proci)
        {
            if (proci == Pstream::myProcNo()) continue;
            forAll(goneIds[proci], k)
            {
                if (current.found(goneIds[proci][k])) previousVelocity_.set(goneIds[proci][k], goneVelocities[proci][k]);
            }
        }
    }
    state_.dvdt.setSize(n);
    label nNew = 0;
    for (label i = 0; i < n; ++i)
    {
        const auto iter = previousVelocity_.cfind(label(particles_.id[i]));
        state_.dvdt[i] = iter.found() ? (state_.v[i] - *iter)/dt : Zero;
        if (!iter.found()) ++nNew;
    }
    reduce(nNew, sumOp<label>());
    if (firstDvDt_ < 0) firstDvDt_ = nNew;
    else unknownDvDt_ += nNew;
    previousVelocity_.transfer(current);
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
    if (alphaRelaxationTime_ > 0) solidVolumeAlpha_ = gSum((1 - a)*mesh_.V());
}

void coarseDemCoupling::checkParticleCount()
{
    // LIGGGHTS deletes particles that leave its box (boundary f) and may only say so at its next
    // thermo output: a drop is lost solid mass, so it stops the run unless it is intended
    if (nParticlesBefore_ >= 0 && nParticles_ < nParticlesBefore_ && !allowParticleLoss_)
    {
        FatalErrorInFunction
            << "the DEM lost " << nParticlesBefore_ - nParticles_ << " particle(s) in the CFD step"
            << " ending at time " << mesh_.time().timeName() << " (" << nParticlesBefore_ << " -> "
            << nParticles_ << "): LIGGGHTS deletes particles that leave its box; check the DEM"
            << " walls and the time steps, or set allowParticleLoss true in " << dict_.name()
            << " if particles are removed on purpose" << exit(FatalError);
    }
    nParticlesBefore_ = nParticles_;
}

//- Largest step x rate over all ranks and how many exceed 1 (the explicit update's range)
static void tallyStepRatios(const UList<scalar>& ratio, scalar& largest, label& nBeyond)
{
    largest = 0;
    nBeyond = 0;
    for (const scalar r : ratio)
    {
        largest = max(largest, r);
        if (r > 1) ++nBeyond;
    }
    reduce(largest, maxOp<scalar>());
    reduce(nBeyond, sumOp<label>());
}

void coarseDemCoupling::checkExplicitRange(const volScalarField& alpha)
{
    const scalar dt = mesh_.time().deltaTValue();
    const scalar dtParticle = implicitParticleDrag_ ? dem_->timestep() : dt;
    const label n = particles_.size();
    scalarField particleRatio(n);
    forAll(particleRatio, i) particleRatio[i] = dtParticle*K_[i]/(particles_.density[i]*volume_[i]);
    tallyStepRatios(particleRatio, particleDragRatio_, nParticlesBeyond_);
    if (nParticlesBeyond_ > 0 && !warnedParticleSide_)
    {
        WarningInFunction
            << "explicit particle-side coupling beyond its range at time " << mesh_.time().timeName()
            << ": " << nParticlesBeyond_ << " particle(s) have "
            << (implicitParticleDrag_ ? "DEM step" : "CFD step") << " x K/m > 1 (max "
            << particleDragRatio_ << "); the drag K (u_f - v) is held for that step, so their"
            << " velocity overshoots (unstable above 2): "
            << (implicitParticleDrag_ ? "reduce the DEM time step"
                                      : "set implicitParticleDrag true or reduce couplingInterval")
            << endl;
        warnedParticleSide_ = true;
    }

    fluidDragRatio_ = 0;
    nCellsBeyond_ = 0;
    if (implicitDrag_) return;   // Ksl is implicit in the fluid momentum equation: no limit
    const scalarField Kr(K_/fluid_.rho);
    scalarField KslExplicit(mesh_.nCells(), 0);
    spread(Kr.cdata(), 1, KslExplicit.data());
    tallyStepRatios(dt*KslExplicit/alpha.primitiveField(), fluidDragRatio_, nCellsBeyond_);
    if (nCellsBeyond_ > 0 && !warnedFluidSide_)
    {
        WarningInFunction
            << "explicit fluid drag beyond its range at time " << mesh_.time().timeName() << ": "
            << nCellsBeyond_ << " cell(s) have CFD step x Ksl/alpha_f > 1 (max " << fluidDragRatio_
            << "); set implicitDrag true in " << dict_.name() << " or reduce couplingInterval" << endl;
        warnedFluidSide_ = true;
    }
}

void coarseDemCoupling::write()
{
    if (demRestart_ && mesh_.time().writeTime())
    {
        const fileName dir = mesh_.time().globalPath()/mesh_.time().timeName();
        if (Pstream::master()) mkDir(dir);
        dem_->writeRestart(dir/"dem.restart");
    }
}

void coarseDemCoupling::report(Ostream& os) const
{
    const scalar volErr = solidVolumeParticles_ > 0
        ? mag(solidVolumeCells_ - solidVolumeParticles_)/solidVolumeParticles_ : 0;
    os  << "Coupling: particles " << nParticles_
        << ", solid volume particles " << solidVolumeParticles_ << " cells " << solidVolumeCells_
        << " (rel. err " << volErr << ")"
        << ", momentum imbalance " << momentumImbalance_ << " N of " << forceScale_ << " N"
        << ", limiter moved " << returnReduce(voidFraction_.movedVolume(), sumOp<scalar>()) << " m3 in "
        << returnReduce(voidFraction_.nLimitedCells(), sumOp<label>()) << " cells"
        << ", drag dt K/m max " << particleDragRatio_ << " (" << nParticlesBeyond_ << " particles > 1)";
    if (alphaRelaxationTime_ > 0)
    {
        os  << ", alpha relaxed over " << alphaRelaxationTime_ << " s: solid volume 1 - alpha "
            << solidVolumeAlpha_ << " (rel. err " << (solidVolumeParticles_ > 0
               ? mag(solidVolumeAlpha_ - solidVolumeParticles_)/solidVolumeParticles_ : 0) << ")";
    }
    if (needs_ & forceModel::needDvDt)
    {
        // particles without a velocity of the last coupling (at the start or restart: all; later:
        // inserted ones) get dv/dt = 0 for that step
        os  << ", dv/dt unknown for " << firstDvDt_ << " particles at the first coupling, "
            << unknownDvDt_ << " since";
    }
    if (!implicitDrag_)
    {
        os  << ", explicit fluid drag dt Ksl/alpha max " << fluidDragRatio_ << " (" << nCellsBeyond_
            << " cells > 1)";
    }
    os  << endl;
    os  << "Exchange in time: " << nExchangesCompared_ << " couplings compared, |particles' + fluid's"
        << " impulse| of a coupling step last " << exchangeLastRel_ << " max " << exchangeMaxRel_
        << " x exchange; since the start net " << exchangeNet_ << " N s of " << exchangeGross_
        << " N s" << endl;

    // particles reaching through the mesh boundary: a DEM wall's contact overlap (small depths), or a
    // particle leaving the mesh (large ones); counted here, at reports only (six locations each)
    const cdc_particles cp = coreParticles();
    int32_t nOut = 0;
    double depth = 0;
    int64_t id = -1;
    demMesh_.check(cdc_kernels_partly_outside(voidFraction_.kernels(), &cp, &nOut, &depth, &id),
                   "particles partly outside the mesh");
    const label nOutAll = returnReduce(label(nOut), sumOp<label>());
    if (nOutAll > 0)
    {
        const scalar deepest = returnReduce(scalar(depth), maxOp<scalar>());
        const scalar idDeepest = returnReduce(depth == deepest ? scalar(id) : scalar(-1), maxOp<scalar>());
        os  << "Particles partly outside the mesh: " << nOutAll << ", the deepest reaches " << 100*deepest
            << " % of its radius beyond it (particle " << std::to_string(std::llround(idDeepest)).c_str() << ")" << endl;
    }
}

} // End namespace Foam
