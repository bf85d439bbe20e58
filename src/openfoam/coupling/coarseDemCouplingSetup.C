/*---------------------------------------------------------------------------*\
    coarseDemCoupling, construction: the checked top-level entries of
    constant/couplingProperties, the force models, the background kernels,
    the output-only fields and the start-up summary line
    (doc/couplingProperties.md is the reference of every entry).
\*---------------------------------------------------------------------------*/
#include "coarseDemCoupling.H"
#include "zeroGradientFvPatchFields.H"

namespace Foam
{

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
    bool hasDrag = false, hasGradP = false;
    wordList buoyant;
    forAll(names, i)
    {
        forces_.append(forceModel::New(names[i], dict_));
        const forceModel& fm = forces_.last();
        needs_ |= fm.needs();
        hasDrag = hasDrag || fm.isDrag();
        hasGradP = hasGradP || fm.carriesPressureGradient();
        if (fm.carriesBuoyancy()) buoyant.append(fm.name());
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
    if (dragOverAlpha_ && buoyant.empty() && mag(fluid_.g) > 0)
    {
        WarningInFunction
            << "modelType B without gradPForce or Archimedes in " << dict_.name() << ": the particles"
            << " get no buoyancy (rho_f V g); add Archimedes (drag / alpha_f carries the rest of the"
            << " pressure gradient)" << endl;
    }
    if (buoyant.size() > 1)
    {
        FatalIOErrorInFunction(dict_)
            << "forceModels in " << dict_.name() << " has " << buoyant << ", which all carry the buoyancy:"
            << " it would be counted twice (the pressure gradient holds the hydrostatic part)"
            << exit(FatalIOError);
    }
    return names;
}

// backgroundFields on: u and alpha at the particles from bigParticle kernels (Zhang et al. eqs. 21-22).
void coarseDemCoupling::createBackgroundKernels()
{
    if (!dict_.lookupOrDefault<Switch>("backgroundFields", false)) return;
    {
        // n = 5 when not given (the paper's background kernel), as voidFractionModel bigParticle
        cdc_kernel_params prm = readKernelParams(dict_, "backgroundFields", "bigParticle", {"reactionKernel"},
                                                 recommendedKernelParams("bigParticle"));
        // Where the particles' reaction goes into the fluid. voidFraction (the paper's): the cells of
        // the alpha_p kernels, with the explicit correction K (u_bg - u_k); a cell's gas then gets a
        // drag that does not grow with its own velocity, and with the centre kernel (one cell per
        // particle) the Mueller bed's gas ran above Courant 1 in nearly every step. background: the
        // cells the drag's fluid velocity was averaged over, with the same weights (the gather's
        // adjoint): implicit in each cell's own velocity, no correction, the balance exact as before.
        const dictionary& props = dict_.optionalSubDict("backgroundFieldsProps");
        const word reaction(props.lookupOrDefault<word>("reactionKernel", "voidFraction"));
        if (reaction != "voidFraction" && reaction != "background")
        {
            FatalIOErrorInFunction(props)
                << "reactionKernel " << reaction << " in " << dict_.name() << "/backgroundFieldsProps is"
                << " not known" << nl << "    valid: voidFraction (default), background" << exit(FatalIOError);
        }
        reactionViaBackground_ = reaction == "background";
        // bigParticle with the background's own parameters (the paper's comparison run for
        // bigParticle n = 5): its kernels are the background kernels. Building them twice doubled
        // the kernel stage, and the explicit correction between the two (K (u_f - u_f)) is zero.
        // Every member is compared, not only those bigParticle reads today.
        const cdc_kernel_params& vf = voidFraction_.params();
        if
        (
            voidFraction_.method() == "bigParticle"
         && vf.expansion_factor == prm.expansion_factor && vf.search_factor == prm.search_factor
         && vf.bandwidth == prm.bandwidth && vf.cutoff_factor == prm.cutoff_factor
         && vf.wall_mirror == prm.wall_mirror
        )
        {
            backgroundIsVoidFraction_ = true;
            return;
        }
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

    binnedSpecies_ = dict_.lookupOrDefault<Switch>("binnedSpeciesFields", false);
    if (dict_.lookupOrDefault<Switch>("binnedParticleFields", false) || binnedSpecies_)
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
        << (
               backgroundKernels_ ? "bigParticle kernel"
             : backgroundIsVoidFraction_ ? "bigParticle kernel (the void-fraction kernels: the same, built once)"
             : "void-fraction kernels"
           )
        << (reactionViaBackground_ && backgroundKernels_ ? ", the fluid's reaction through the background kernels" : "")
        << ", drag on the fluid " << (switches_.implicitDrag ? "implicit" : "explicit") << ", on the particles "
        << (switches_.implicitParticleDrag ? "every DEM step" : "held for the CFD step") << ", forces " << names
        << ", DEM step " << dem_->timestep() << " s x " << couplingInterval_;
    if (cgFactor_ != 1)
    {
        Info<< ", coarse-grained: each grain " << cgFactor_ << " real diameters, the drag of "
            << pow3(cgFactor_) << " real particles (coarseGrainingFactor)";
    }
    if (alphaRelaxationTime_ > 0)
    {
        Info<< ", fluid fraction relaxed over " << alphaRelaxationTime_ << " s (alphaRelaxationTime)";
    }
    Info<< endl;
    Info<< endl;
}

} // End namespace Foam
