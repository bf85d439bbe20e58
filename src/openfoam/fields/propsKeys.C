#include "propsKeys.H"
#include "error.H"

void Foam::checkPropsKeys(const dictionary& props, const wordList& valid)
{
    // every unknown entry in one message, so that a dictionary is mended in one go
    wordList unknown;
    for (const entry& e : props)
    {
        if (!valid.found(e.keyword())) unknown.append(e.keyword());
    }
    if (unknown.empty()) return;
    string names, bad;
    for (const word& w : valid) names += (names.empty() ? "" : ", ") + w;
    for (const word& w : unknown) bad += (bad.empty() ? "" : ", ") + w;
    FatalIOErrorInFunction(props)
        << "unknown entr" << (unknown.size() > 1 ? "ies " : "y ") << bad.c_str() << " in " << props.name()
        << " (" << (unknown.size() > 1 ? "they" : "it") << " would be ignored and the model would run with"
        << " its default)" << nl
        << "    valid entries: " << (names.empty() ? string("none") : names).c_str()
        << exit(FatalIOError);
}
