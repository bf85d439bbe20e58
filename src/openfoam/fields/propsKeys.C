#include "propsKeys.H"
#include "error.H"

void Foam::checkPropsKeys(const dictionary& props, const wordList& valid)
{
    for (const entry& e : props)
    {
        if (!valid.found(e.keyword()))
        {
            string names;
            for (const word& w : valid) names += (names.empty() ? "" : ", ") + w;
            FatalIOErrorInFunction(props)
                << "unknown entry " << e.keyword() << " in " << props.name()
                << " (it would be ignored and the model would run with its default)" << nl
                << "    valid entries: " << (names.empty() ? string("none") : names).c_str()
                << exit(FatalIOError);
        }
    }
}
