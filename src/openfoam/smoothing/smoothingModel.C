#include "smoothingModel.H"
#include "error.H"

namespace Foam
{
defineTypeNameAndDebug(smoothingModel, 0);
defineRunTimeSelectionTable(smoothingModel, dictionary);

autoPtr<smoothingModel> smoothingModel::New(const dictionary& couplingDict, const coarseDemMesh& mesh)
{
    const word name = couplingDict.lookupOrDefault<word>("smoothingModel", "off");
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(name);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(couplingDict)
            << "unknown smoothingModel " << name << " in " << couplingDict.name() << nl
            << "    valid smoothing models: " << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }
    if
    (
        name != "diffusion" && couplingDict.isDict("diffusionProps")
     && couplingDict.subDict("diffusionProps").lookupOrDefault<Switch>("smoothExchangeFields", false)
    )
    {
        WarningInFunction
            << "smoothExchangeFields in " << couplingDict.name() << "/diffusionProps acts with smoothingModel"
            << " diffusion only; smoothingModel is " << name << ": ignored" << endl;
    }
    return cstrIter()(couplingDict, mesh);
}

scalar smoothingModel::readTolerance(const dictionary& couplingDict, const dictionary& props, const word& propsName)
{
    const scalar tol = props.lookupOrDefault<scalar>("tolerance", CDC_DIFFUSION_DEFAULT_TOLERANCE);
    if (!(tol > 0 && tol < 1))
    {
        FatalIOErrorInFunction(couplingDict)
            << "entry tolerance " << tol << " in " << couplingDict.name() << "/" << propsName
            << " is invalid: must be > 0 and < 1 (the CG solves' relative residual)"
            << exit(FatalIOError);
    }
    return tol;
}

} // End namespace Foam
