/*---------------------------------------------------------------------------*\
    coarseDemCoupling, construction: the checked top-level entries of
    constant/couplingProperties, the background kernels,
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

void coarseDemCoupling::printSummary() const
{
    const word modelType(modelB_ ? "B" : "A");
    Info<< "coarseDemCoupling: model " << modelType << ", voidFractionModel " << voidFraction_.method()
        << ", smoothing " << voidFraction_.smoothingName()
        << (voidFraction_.smoothing().smoothsExchangeFields() ? " (alpha_p and the fluid's sources)" : "")
        << ", background fields " << averaging_->description().c_str()
        << ", drag on the fluid " << (switches_.implicitDrag ? "implicit" : "explicit") << ", on the particles "
        << (switches_.implicitParticleDrag ? "every DEM step" : "held for the CFD step") << ", forces " << forces_->names()
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
