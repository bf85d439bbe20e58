#include "backgroundAveraging.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
defineTypeNameAndDebug(backgroundAveraging, 0);
addToRunTimeSelectionTable(fluidAveraging, backgroundAveraging, dictionary);

backgroundAveraging::backgroundAveraging
(
    const dictionary& couplingDict, const coarseDemMesh& demMesh, const voidFraction& vf
)
:
    fluidAveraging(demMesh, vf)
{
    // n = 5 when not given (the paper's background kernel), as voidFractionModel bigParticle
    const cdc_kernel_params prm = readKernelParams(couplingDict, "backgroundFields", "bigParticle",
                                                   {"reactionKernel"}, recommendedKernelParams("bigParticle"));
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
        FatalIOErrorInFunction(couplingDict)
            << "backgroundFieldsProps in " << couplingDict.name() << ": " << cdc_last_error(demMesh.context())
            << exit(FatalIOError);
    }
}

backgroundAveraging::~backgroundAveraging()
{
    cdc_kernels_destroy(background_);
}

double backgroundAveraging::reach(double r) const
{
    const double own = fluidAveraging::reach(r);
    return background_ ? std::max(own, cdc_kernels_reach(background_, r) + r) : own;
}

void backgroundAveraging::build(const cdc_particles& local, const cdc_particles& ghosts, const particleHalo& halo)
{
    if (background_) buildKernels(demMesh_, background_, local, ghosts, halo, "background kernels");
}

std::string backgroundAveraging::description() const
{
    return background_ ? "bigParticle kernel"
         : "bigParticle kernel (the void-fraction kernels: the same, built once)";
}


// backgroundReaction: as background, and the reaction through the background kernels too: the
// cells the drag's fluid velocity was averaged over, with the same weights (the gather's adjoint),
// implicit in each cell's own velocity, no correction. With the paper's voidFraction reaction a
// cell's gas gets a drag that does not grow with its own velocity, and with the centre kernel (one
// cell per particle) the Mueller bed's gas ran above Courant 1 in nearly every step.
class backgroundReactionAveraging : public backgroundAveraging
{
public:
    TypeName("backgroundReaction");
    using backgroundAveraging::backgroundAveraging;

    const cdc_kernels* reaction() const override { return sample(); }
    std::string description() const override
    {
        return backgroundAveraging::description()
             + (background_ ? ", the fluid's reaction through the background kernels" : "");
    }
};
defineTypeNameAndDebug(backgroundReactionAveraging, 0);
addToRunTimeSelectionTable(fluidAveraging, backgroundReactionAveraging, dictionary);

} // End namespace Foam
