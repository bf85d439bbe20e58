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

void coarseDemCoupling::printSummary(const wordList& names) const
{
    const word modelType(modelB_ ? "B" : "A");
    Info<< "coarseDemCoupling: model " << modelType << ", voidFractionModel " << voidFraction_.method()
        << ", smoothing " << voidFraction_.smoothingName()
        << (voidFraction_.smoothsExchangeFields() ? " (alpha_p and the fluid's sources)" : "")
        << ", background fields " << exchangeKernels_->description().c_str()
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
