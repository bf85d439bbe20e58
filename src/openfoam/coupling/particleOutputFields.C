#include "particleOutputFields.H"
#include "zeroGradientFvPatchFields.H"

namespace Foam
{

particleOutputFields::particleOutputFields
(
    const fvMesh& mesh, const dictionary& dict, const coarseDemMesh& demMesh, const voidFraction& vf
)
:
    mesh_(mesh),
    demMesh_(demMesh),
    voidFraction_(vf),
    interval_(dict.lookupOrDefault<scalar>("particleFieldsInterval", 0))
{
    const word t = mesh.time().timeName();
    if (dict.lookupOrDefault<Switch>("solidVelocityField", false))
    {
        if (!vf.smoothing().canSmoothLikeAlpha())
        {
            WarningInFunction
                << "solidVelocityField with smoothingModel sizeAwareDiffusion: alphaPUs is not smoothed"
                << " (each size class has its own bandwidth), so alphaPUs/alphaP is not the solid velocity"
                << endl;
        }
        alphaPUs_.reset
        (
            new volVectorField
            (
                IOobject("alphaPUs", t, mesh, IOobject::NO_READ, IOobject::AUTO_WRITE),
                mesh, dimensionedVector(dimVelocity, Zero), zeroGradientFvPatchVectorField::typeName
            )
        );
    }
    binnedSpecies_ = dict.lookupOrDefault<Switch>("binnedSpeciesFields", false);
    if (dict.lookupOrDefault<Switch>("binnedParticleFields", false) || binnedSpecies_)
    {
        cdc_kernel_params prm = {};
        if (cdc_kernels_create(demMesh.context(), "centre", &prm, &binKernels_) != CDC_OK)
        {
            FatalIOErrorInFunction(dict)
                << "binnedParticleFields in " << dict.name() << ": " << cdc_last_error(demMesh.context())
                << exit(FatalIOError);
        }
        alphaPBinned_.reset
        (
            new volScalarField
            (
                IOobject("alphaPBinned", t, mesh, IOobject::NO_READ, IOobject::AUTO_WRITE),
                mesh, dimensionedScalar(dimless, Zero), zeroGradientFvPatchScalarField::typeName
            )
        );
        alphaPUsBinned_.reset
        (
            new volVectorField
            (
                IOobject("alphaPUsBinned", t, mesh, IOobject::NO_READ, IOobject::AUTO_WRITE),
                mesh, dimensionedVector(dimVelocity, Zero), zeroGradientFvPatchVectorField::typeName
            )
        );
    }
}

particleOutputFields::~particleOutputFields()
{
    cdc_kernels_destroy(binKernels_);
}

bool particleOutputFields::due()
{
    const Time& rt = mesh_.time();
    if (interval_ <= 0) return true;
    // the step nearest each multiple of the interval since the start, as an adjustableRunTime
    // function object samples (Time's and timeControl's index rule), plus the write times
    const label index = label((rt.value() - rt.startTime().value() + 0.5*rt.deltaTValue())/interval_);
    if (index <= lastIndex_ && !rt.writeTime()) return false;
    lastIndex_ = max(index, lastIndex_);
    return true;
}

void particleOutputFields::update
(
    const cdc_particles& local, const cdc_particles& ghosts, const particleHalo& halo,
    const demParticles& particles, const std::vector<double>& volume, const vector* v,
    const spreader& spread
)
{
    if (!(alphaPUs_.valid() || binKernels_) || !due()) return;
    vectorField q(particles.size());
    forAll(q, i) q[i] = volume[i]*v[i];
    const double* qd = reinterpret_cast<const double*>(q.cdata());
    if (alphaPUs_.valid())
    {
        double* aUs = reinterpret_cast<double*>(alphaPUs_().primitiveFieldRef().data());
        spread(voidFraction_.kernels(), qd, 3, aUs);
        voidFraction_.smoothing().smoothLikeAlpha(aUs, 3);   // as alphaP, so alphaPUs/alphaP is a velocity
        alphaPUs_().correctBoundaryConditions();
    }
    if (!binKernels_) return;
    buildKernels(demMesh_, binKernels_, local, ghosts, halo, "binnedParticleFields (centre kernels)");
    spread(binKernels_, volume.data(), 1, alphaPBinned_().primitiveFieldRef().data());
    spread(binKernels_, qd, 3, reinterpret_cast<double*>(alphaPUsBinned_().primitiveFieldRef().data()));
    alphaPBinned_().correctBoundaryConditions();
    alphaPUsBinned_().correctBoundaryConditions();
    if (binnedSpecies_) binSpecies(particles, volume, spread);
}

// alphaPBinned of each DEM atom type (binnedSpeciesFields): the species of a polydisperse bed apart,
// counted in the cell of their centre as alphaPBinned is (their sum is alphaPBinned)
void particleOutputFields::binSpecies
(
    const demParticles& particles, const std::vector<double>& volume, const spreader& spread
)
{
    const label n = particles.size();
    label nTypes = 0;
    for (label i = 0; i < n; ++i) nTypes = max(nTypes, label(particles.type[i]));
    reduce(nTypes, maxOp<label>());
    const word t0 = mesh_.time().timeName();
    for (label t = alphaPBinnedType_.size() + 1; t <= nTypes; ++t)
    {
        alphaPBinnedType_.append
        (
            new volScalarField
            (
                IOobject("alphaPBinned.type" + Foam::name(t), t0, mesh_, IOobject::NO_READ, IOobject::AUTO_WRITE),
                mesh_, dimensionedScalar(dimless, Zero), zeroGradientFvPatchScalarField::typeName
            )
        );
    }
    std::vector<double> q(n);
    forAll(alphaPBinnedType_, k)
    {
        for (label i = 0; i < n; ++i) q[i] = particles.type[i] == k + 1 ? volume[i] : 0.0;
        spread(binKernels_, q.data(), 1, alphaPBinnedType_[k].primitiveFieldRef().data());
        alphaPBinnedType_[k].correctBoundaryConditions();
    }
}

} // End namespace Foam
