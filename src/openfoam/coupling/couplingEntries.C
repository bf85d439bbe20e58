#include "couplingEntries.H"
#include "forceModel.H"
#include "coarse_dem.h"
#include "OStringStream.H"
#include "HashTable.H"
#include "HashSet.H"
#include "Pstream.H"

namespace Foam
{

// In a parallel run the master reads couplingProperties and streams it to the other ranks, whose copy
// is then named after the stream ("IOstream"): every error raised on those ranks would name no file.
// Names the dictionary, its entries (a bad value's error names its entry) and its sub-dictionaries
// after the master's file on every rank, as OpenFOAM names them when it reads the file.
// The entries are found by keyword, not with the dictionary's non-const iterator: in OpenFOAM v1912
// an entry replaced by a later one of the same keyword (a key given twice) leaves a link to the deleted
// entry that only that iterator follows (DLListBase::replace), and the renaming crashed there.
static void nameAfterFile(dictionary& dict, const fileName& name)
{
    dict.name() = name;
    for (const word& keyword : dict.toc())
    {
        entry* e = dict.findEntry(keyword, keyType::LITERAL);
        if (!e) continue;
        e->name() = name + '.' + keyword;
        if (e->isDict()) nameAfterFile(e->dict(), e->name());
    }
}

// Every entry of couplingProperties, checked before any model reads it: an entry nothing reads (a
// misspelt name, or a model's entry written at the top level instead of in its <model>Props) would be
// ignored and the run would go on with the defaults. Sub-dictionaries must be the <model>Props of a
// model (or openSystem); plain entries the solver's own. All unknown entries are named in one message,
// each misplaced one with the dictionary it belongs in. Returns its argument, so that the check (and
// the naming after the file) runs before the first model reads its dictionary.
const dictionary& checkCouplingEntries(IOdictionary& io)
{
    dictionary& file = io;          // as a dictionary: IOdictionary's own name() is the object's
    fileName path = file.name();    // the master's: the file it read
    Pstream::scatter(path);
    nameAfterFile(file, path);
    // read through a const view: the non-const iterator would follow the link nameAfterFile avoids
    const dictionary& dict = file;
    wordHashSet dicts{"backgroundFieldsProps", "diffusionProps", "sizeAwareDiffusionProps", "openSystem"};
    for (int i = 0; i < cdc_method_count(); ++i) dicts.insert(word(cdc_method_name(i)) + "Props");
    for (const word& f : forceModel::dictionaryConstructorTablePtr_->sortedToc()) dicts.insert(f + "Props");
    // the plain entries read from the top level (doc/couplingProperties.md)
    const wordHashSet entries
    {
        "modelType", "couplingInterval", "demScript", "implicitDrag", "implicitParticleDrag",
        "voidFractionModel", "mirrorPatches", "alphaMin", "alphaRelaxationTime", "smoothingModel",
        "backgroundFields", "forceModels", "coarseGrainingFactor", "demRestart", "demFreshStart",
        "demCouplingFix", "demTimeStepWarnFraction", "demTimeStepMaxFraction", "demTimeStepForce",
        "demMaxImpactVelocity", "allowParticleLoss", "particleFieldsInterval", "solidVelocityField",
        "binnedParticleFields", "binnedSpeciesFields", "writeExchangeFields", "writeParticleCloud"
    };
    // entries of a model's dictionary, where they belong when written at the top level
    const HashTable<word> belongs
    {
        {"expansionFactor", "bigParticleProps or backgroundFieldsProps"},
        {"wallMirror", "bigParticleProps, twoGridProps, gaussianProps or backgroundFieldsProps"},
        {"searchFactor", "twoGridProps"},
        {"bandwidth", "diffusionProps or gaussianProps"},
        {"smoothExchangeFields", "diffusionProps"},
        {"nSteps", "diffusionProps or sizeAwareDiffusionProps"},
        {"tolerance", "diffusionProps or sizeAwareDiffusionProps"},
        {"DRule", "diffusionProps"},
        {"particleDiameter", "diffusionProps"},
        {"bandwidthOverD", "sizeAwareDiffusionProps"},
        {"classRatio", "sizeAwareDiffusionProps"},
        {"reactionKernel", "backgroundFieldsProps"},
        {"reynoldsNumber", "DiFeliceDragProps"},
        {"Cvm", "virtualMassForceProps"}
    };
    OStringStream unknown;
    label nUnknown = 0;
    for (const entry& e : dict)
    {
        const word& k = e.keyword();
        if (k == "FoamFile") continue;
        const bool ok = e.isDict() ? dicts.found(k) : entries.found(k);
        if (ok) continue;
        ++nUnknown;
        unknown << nl << "    " << (e.isDict() ? "dictionary " : "entry ") << k;
        if (!e.isDict() && belongs.found(k))
        {
            unknown << ": an entry of " << belongs[k] << ", not of the top level";
        }
        else if (e.isDict())
        {
            unknown << ": no model of that name (a misspelt model name?)";
        }
        else
        {
            unknown << ": not an entry of couplingProperties (misspelt?)";
        }
    }
    if (nUnknown)
    {
        string dNames, eNames;
        for (const word& w : dicts.sortedToc()) dNames += (dNames.empty() ? "" : ", ") + w;
        for (const word& w : entries.sortedToc()) eNames += (eNames.empty() ? "" : ", ") + w;
        FatalIOErrorInFunction(dict)
            << nUnknown << " unknown entr" << (nUnknown > 1 ? "ies" : "y") << " in " << dict.name()
            << " (each would be ignored):" << unknown.str().c_str() << nl
            << "    entries read: " << eNames.c_str() << nl
            << "    dictionaries read: " << dNames.c_str() << exit(FatalIOError);
    }
    return dict;
}

} // End namespace Foam
