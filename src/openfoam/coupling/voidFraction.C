#include "voidFraction.H"
#include "Time.H"
#include "mathematicalConstants.H"
#include "propsKeys.H"

#include <chrono>

namespace Foam
{

// The numeric <method>Props entries: the member of cdc_kernel_params each sets and the parameter bit
// of the core's methods that reads it (0 when absent: the method's own default). wallMirror, the
// one switch, follows them.
static const struct { const char* key; double cdc_kernel_params::*member; unsigned bit; } kernelKeys[] =
{
    {"expansionFactor", &cdc_kernel_params::expansion_factor, CDC_PARAM_EXPANSION_FACTOR},
    {"searchFactor", &cdc_kernel_params::search_factor, CDC_PARAM_SEARCH_FACTOR},
    {"bandwidth", &cdc_kernel_params::bandwidth, CDC_PARAM_BANDWIDTH},
    {"cutoffFactor", &cdc_kernel_params::cutoff_factor, CDC_PARAM_CUTOFF_FACTOR},
};

cdc_kernel_params recommendedKernelParams(const word& method)
{
    cdc_kernel_params prm = {};
    // bigParticle: the paper's optimised form, n = 5 (Zhang et al. 2023 recommend 4-5), not the
    // core's original equal split (n = 0), which the docs advise against for coarse particles
    if (method == "bigParticle") prm.expansion_factor = 5;
    return prm;
}

cdc_kernel_params readKernelParams
(
    const dictionary& dict, const word& name, const word& method, const wordList& otherKeys,
    const cdc_kernel_params& defaults
)
{
    cdc_kernel_params prm = {};
    const dictionary& props = dict.optionalSubDict(name + "Props");
    const unsigned reads = cdc_method_params(method.c_str());
    wordList valid;
    for (const auto& k : kernelKeys) if (reads & k.bit) valid.append(k.key);
    if (reads & CDC_PARAM_WALL_MIRROR) valid.append("wallMirror");
    valid.append(otherKeys);   // the caller's own entries (backgroundFieldsProps: reactionKernel)
    if (dict.isDict(name + "Props")) checkPropsKeys(props, valid);
    // read, and say what the method runs with, so that a user sees a default taken
    Info<< (name == method ? word("voidFractionModel") : name) << " " << method << ":";
    cdc_kernel_params dflt = defaults;   // the caller's, then the method's own
    cdc_method_fill_defaults(method.c_str(), &dflt);
    cdc_kernel_params coreDflt = {};      // what the core puts in place of a 0
    cdc_method_fill_defaults(method.c_str(), &coreDflt);
    for (const auto& k : kernelKeys) prm.*k.member = props.lookupOrDefault<scalar>(k.key, dflt.*k.member);
    for (const auto& k : kernelKeys)
    {
        if (!(reads & k.bit)) continue;
        // 0 stands for "not given" in the core: where the core has a default of its own, an explicit
        // 0 would silently become it (bigParticle's expansionFactor 0 is a form of its own, allowed)
        if (props.found(k.key) && prm.*k.member == 0 && coreDflt.*k.member != 0)
        {
            FatalIOErrorInFunction(props)
                << k.key << " 0 in " << dict.name() << "/" << name << "Props is not a valid value (leave the entry"
                << " out for the default, " << dflt.*k.member << ")" << exit(FatalIOError);
        }
        Info<< " " << k.key << " " << prm.*k.member << (props.found(k.key) ? "" : " (default)");
    }
    // mirrored at walls unless told otherwise: an expansion kernel cut off at a wall reads the wall's
    // cells dilute and lets the fluid bypass a bed there (doc/methods.md)
    prm.wall_mirror = props.lookupOrDefault<Switch>("wallMirror", true) ? 1 : 0;
    if (reads & CDC_PARAM_WALL_MIRROR)
    {
        Info<< " wallMirror " << (prm.wall_mirror ? "true" : "false") << (props.found("wallMirror") ? "" : " (default)");
    }
    if (valid.empty()) Info<< " no parameters";   // centre, divided: say so rather than end the line
    Info<< endl;
    if (name == "gaussian" && !props.found("bandwidth"))
    {
        FatalIOErrorInFunction(dict)
            << "keyword bandwidth is undefined in dictionary " << dict.name() << "/" << name << "Props"
            << nl << "    (the Gaussian kernel width b in metres; Zhang et al. recommend b = 6 d)"
            << exit(FatalIOError);
    }
    return prm;
}

void buildKernels(const coarseDemMesh& mesh, cdc_kernels* k, const cdc_particles& p, const cdc_particles& ghosts,
                  const particleHalo& halo, const word& what)
{
    const cdc_status st = halo.active() ? cdc_kernels_build_raw(k, &p, &ghosts) : cdc_kernels_build(k, &p);
    if (st == CDC_ERR_OUTSIDE)
    {
        // in parallel a particle inside the whole mesh but outside this rank's part was handed to
        // this rank by the DEM's own decomposition: the two split the domain at different planes
        const boundBox& whole = mesh.mesh().bounds();   // global (reduced over the ranks)
        label outsideWhole = 0;
        for (int32_t i = 0; i < p.n; ++i)
        {
            if (!whole.contains(point(p.position[3*i], p.position[3*i + 1], p.position[3*i + 2]))) ++outsideWhole;
        }
        const bool decompositionMismatch = Pstream::parRun() && outsideWhole == 0;
        FatalErrorInFunction
            << what << ": " << cdc_last_error(mesh.context()) << nl
            << "    at time " << mesh.mesh().time().timeName() << ": "
            << (decompositionMismatch
                ? "these particles are inside the CFD mesh but in another rank's part of it: the DEM"
                  " (LIGGGHTS processors command) and the CFD (system/decomposeParDict) must split the"
                  " domain at the same planes and number the parts alike, e.g. simple (2 1 1) with an even"
                  " number of cells across and processors * 1 1, or hierarchical (Nx Ny 1) with order yxz"
                  " and processors Nx Ny 1 (LIGGGHTS numbers its ranks with y varying fastest)"
                : "particles must stay inside the CFD mesh (check the DEM walls and insertion region)")
            << exit(FatalError);
    }
    mesh.check(st, what);
    if (halo.active())
    {
        // global sums: the ghosts' partial sums go to the owners, the totals come back
        const double* raw = cdc_kernels_raw_sums(k);
        std::vector<double> sums(raw, raw + p.n + ghosts.n);
        halo.addToOwners(sums.data() + p.n, 1, sums.data());
        std::vector<double> totals;
        halo.toGhosts(sums.data(), 1, totals);
        std::copy(totals.begin(), totals.end(), sums.begin() + p.n);
        mesh.check(cdc_kernels_normalise(k, sums.data(), p.id), what);
    }
}

voidFraction::voidFraction(const dictionary& dict, const coarseDemMesh& mesh)
:
    mesh_(mesh),
    method_(dict.get<word>("voidFractionModel")),
    params_(readKernelParams(dict, method_, method_, wordList(), recommendedKernelParams(method_))),
    kernels_(nullptr),
    alphaMin_(dict.get<scalar>("alphaMin")),
    movedVolume_(0),
    nLimitedCells_(0),
    alphaPSeconds_(0)
{
    const cdc_status st = cdc_kernels_create(mesh.context(), method_.c_str(), &params_, &kernels_);
    if (st != CDC_OK)
    {
        FatalIOErrorInFunction(dict)
            << "entry voidFractionModel " << method_ << " (or its " << method_ << "Props) in "
            << dict.name() << ": " << cdc_last_error(mesh.context()) << exit(FatalIOError);
    }
    if (!(alphaMin_ > 0 && alphaMin_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "entry alphaMin " << alphaMin_ << " in " << dict.name()
            << " is invalid: must be in (0, 1) (e.g. 0.3 for spheres)" << exit(FatalIOError);
    }

    smoothing_ = smoothingModel::New(dict, mesh);
}

voidFraction::~voidFraction()
{
    cdc_kernels_destroy(kernels_);
}

void voidFraction::update
(
    const cdc_particles& p, const cdc_particles& ghosts, const particleHalo& halo, scalarField& alphaP
)
{
    buildKernels(mesh_, kernels_, p, ghosts, halo, "void fraction (" + method_ + ")");
    double* a = alphaP.data();
    const auto t0 = std::chrono::steady_clock::now();
    // particle volumes of the local particles, then of the ghosts
    const label n = p.n + ghosts.n;
    volumes_.resize(n);
    radii_.resize(n);
    for (label i = 0; i < n; ++i)
    {
        const double r = i < p.n ? p.radius[i] : ghosts.radius[i - p.n];
        radii_[i] = r;
        volumes_[i] = 4.0/3.0*constant::mathematical::pi*r*r*r;
    }
    smoothing_->alphaP(kernels_, volumes_, radii_, a);
    double moved = 0;
    int32_t nLimited = 0;
    mesh_.check(cdc_limit_packing(mesh_.context(), 1.0 - alphaMin_, 200, a, &moved, &nLimited), "packing limiter");
    alphaPSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    movedVolume_ = moved;
    nLimitedCells_ = nLimited;
}

} // End namespace Foam
