#include "forceModel.H"
#include "error.H"
#include "propsKeys.H"
#include "Pstream.H"
#include "OStringStream.H"

namespace Foam
{
defineTypeNameAndDebug(forceModel, 0);
defineRunTimeSelectionTable(forceModel, dictionary);
}

Foam::forceModel::forceModel(const word& name, const dictionary& props)
:
    name_(name)
{
    (void)props;
}

Foam::autoPtr<Foam::forceModel> Foam::forceModel::New(const word& name, const dictionary& couplingDict)
{
    auto cstrIter = dictionaryConstructorTablePtr_->cfind(name);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(couplingDict)
            << "unknown force model " << name << " in entry forceModels of " << couplingDict.name() << nl
            << "    valid force models: " << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }
    autoPtr<forceModel> model(cstrIter()(name, couplingDict.optionalSubDict(name + "Props")));
    if (couplingDict.isDict(name + "Props"))
    {
        checkPropsKeys(couplingDict.subDict(name + "Props"), model->propsKeys());
    }
    return model;
}

void Foam::forceModel::warnOutOfRange
(
    const word& key, const string& quantity, scalar value, const string& range
) const
{
    if (!warned_.insert(key)) return;
    OStringStream msg;
    msg << name_ << ": " << quantity.c_str() << " = " << value << " is outside the range of the law, "
        << range.c_str() << nl
        << "    the law is applied as written; reported once per run";
    if (Pstream::master())
    {
        WarningInFunction << msg.str().c_str() << endl;
    }
    else
    {
        // OpenFOAM's Warning prints on the master only; another rank reports through Pout
        Pout<< "--> FOAM Warning : " << msg.str().c_str() << endl;
    }
}
