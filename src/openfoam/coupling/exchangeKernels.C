#include "exchangeKernels.H"

namespace Foam
{

exchangeKernels::exchangeKernels(const dictionary& dict, const coarseDemMesh& demMesh, const voidFraction& vf)
:
    demMesh_(demMesh),
    vf_(vf)
{
    if (!dict.lookupOrDefault<Switch>("backgroundFields", false)) return;
    // n = 5 when not given (the paper's background kernel), as voidFractionModel bigParticle
    cdc_kernel_params prm = readKernelParams(dict, "backgroundFields", "bigParticle", {"reactionKernel"},
                                             recommendedKernelParams("bigParticle"));
    // Where the particles' reaction goes into the fluid. voidFraction (the paper's): the cells of
    // the alpha_p kernels, with the explicit correction K (u_bg - u_k); a cell's gas then gets a
    // drag that does not grow with its own velocity, and with the centre kernel (one cell per
    // particle) the Mueller bed's gas ran above Courant 1 in nearly every step. background: the
    // cells the drag's fluid velocity was averaged over, with the same weights (the gather's
    // adjoint): implicit in each cell's own velocity, no correction, the balance exact as before.
    const dictionary& props = dict.optionalSubDict("backgroundFieldsProps");
    const word reaction(props.lookupOrDefault<word>("reactionKernel", "voidFraction"));
    if (reaction != "voidFraction" && reaction != "background")
    {
        FatalIOErrorInFunction(props)
            << "reactionKernel " << reaction << " in " << dict.name() << "/backgroundFieldsProps is"
            << " not known" << nl << "    valid: voidFraction (default), background" << exit(FatalIOError);
    }
    reactionViaBackground_ = reaction == "background";
    // bigParticle with the background's own parameters (the paper's comparison run for
    // bigParticle n = 5): its kernels are the background kernels. Building them twice doubled
    // the kernel stage, and the explicit correction between the two (K (u_f - u_f)) is zero.
    // Every member is compared, not only those bigParticle reads today.
    const cdc_kernel_params& own = vf.params();
    if
    (
        vf.method() == "bigParticle"
     && own.expansion_factor == prm.expansion_factor && own.search_factor == prm.search_factor
     && own.bandwidth == prm.bandwidth && own.cutoff_factor == prm.cutoff_factor
     && own.wall_mirror == prm.wall_mirror
    )
    {
        sameAsVoidFraction_ = true;
        return;
    }
    if (cdc_kernels_create(demMesh.context(), "bigParticle", &prm, &background_) != CDC_OK)
    {
        FatalIOErrorInFunction(dict)
            << "backgroundFieldsProps in " << dict.name() << ": " << cdc_last_error(demMesh.context())
            << exit(FatalIOError);
    }
}

exchangeKernels::~exchangeKernels()
{
    cdc_kernels_destroy(background_);
}

double exchangeKernels::reach(double r) const
{
    const double own = cdc_kernels_reach(vf_.kernels(), r) + r;
    return background_ ? std::max(own, cdc_kernels_reach(background_, r) + r) : own;
}

void exchangeKernels::build(const cdc_particles& local, const cdc_particles& ghosts, const particleHalo& halo)
{
    if (background_) buildKernels(demMesh_, background_, local, ghosts, halo, "background kernels");
}

std::string exchangeKernels::description() const
{
    std::string s = background_ ? "bigParticle kernel"
                  : sameAsVoidFraction_ ? "bigParticle kernel (the void-fraction kernels: the same, built once)"
                  : "void-fraction kernels";
    if (reactionViaBackground_ && background_) s += ", the fluid's reaction through the background kernels";
    return s;
}

} // End namespace Foam
