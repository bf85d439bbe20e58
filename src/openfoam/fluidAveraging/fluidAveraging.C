#include "fluidAveraging.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
defineTypeNameAndDebug(fluidAveraging, 0);
defineRunTimeSelectionTable(fluidAveraging, dictionary);

// voidFraction: the base class's kernels, registered under its name
class voidFractionAveraging : public fluidAveraging
{
public:
    TypeName("voidFraction");
    voidFractionAveraging(const dictionary&, const coarseDemMesh& demMesh, const voidFraction& vf)
    :
        fluidAveraging(demMesh, vf)
    {}
};
defineTypeNameAndDebug(voidFractionAveraging, 0);
addToRunTimeSelectionTable(fluidAveraging, voidFractionAveraging, dictionary);

autoPtr<fluidAveraging> fluidAveraging::New
(
    const dictionary& couplingDict, const coarseDemMesh& demMesh, const voidFraction& vf
)
{
    word name("voidFraction");
    if (couplingDict.lookupOrDefault<Switch>("backgroundFields", false))
    {
        // Where the particles' reaction goes into the fluid: voidFraction (the paper's) or background
        const dictionary& props = couplingDict.optionalSubDict("backgroundFieldsProps");
        const word reaction(props.lookupOrDefault<word>("reactionKernel", "voidFraction"));
        if (reaction != "voidFraction" && reaction != "background")
        {
            FatalIOErrorInFunction(props)
                << "reactionKernel " << reaction << " in " << couplingDict.name() << "/backgroundFieldsProps is"
                << " not known" << nl << "    valid: voidFraction (default), background" << exit(FatalIOError);
        }
        name = reaction == "background" ? "backgroundReaction" : "background";
    }
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(name);
    if (!cstrIter.found())
    {
        FatalErrorInFunction
            << "no fluid averaging " << name << "; known: " << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalError);
    }
    return cstrIter()(couplingDict, demMesh, vf);
}

} // End namespace Foam
