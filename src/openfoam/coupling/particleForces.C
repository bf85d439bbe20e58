/*---------------------------------------------------------------------------*\
    particleForces: see particleForces.H.
\*---------------------------------------------------------------------------*/
#include "particleForces.H"
#include "mathematicalConstants.H"

#include <cmath>

namespace Foam
{

// forceModels: the models, what they need, and the combinations that count a force twice or miss one.
particleForces::particleForces(const dictionary& dict, bool modelB, const fluidProperties& fluid)
:
    names_(dict.get<wordList>("forceModels")),
    fluid_(fluid),
    modelB_(modelB)
{
    bool hasDrag = false, hasGradP = false;
    wordList buoyant;
    forAll(names_, i)
    {
        models_.append(forceModel::New(names_[i], dict));
        const forceModel& fm = models_.last();
        needs_ |= fm.needs();
        hasDrag = hasDrag || fm.isDrag();
        hasGradP = hasGradP || fm.carriesPressureGradient();
        if (fm.carriesBuoyancy()) buoyant.append(fm.name());
    }
    if (!hasDrag)
    {
        WarningInFunction << "no drag model in forceModels of " << dict.name() << endl;
    }
    if (!modelB && names_.size() && !hasGradP)
    {
        // Model A's fluid carries -alpha grad(p) (Zhang et al. 2023 eq. 15): the particles must get
        // -V grad(p), or the dynamic pressure force leaves the fluid and reaches no particle.
        FatalIOErrorInFunction(dict)
            << "forceModels in " << dict.name() << " lacks gradPForce, which modelType A needs: the"
            << " fluid equation has alpha grad(p), so the particles must get -V grad(p)" << nl
            << "    (or modelType B with drag and Archimedes: the drag is then divided by the fluid"
            << " fraction)" << exit(FatalIOError);
    }
    dragOverAlpha_ = modelB && !hasGradP;
    if (dragOverAlpha_ && buoyant.empty() && mag(fluid.g) > 0)
    {
        WarningInFunction
            << "modelType B without gradPForce or Archimedes in " << dict.name() << ": the particles"
            << " get no buoyancy (rho_f V g); add Archimedes (drag / alpha_f carries the rest of the"
            << " pressure gradient)" << endl;
    }
    if (buoyant.size() > 1)
    {
        FatalIOErrorInFunction(dict)
            << "forceModels in " << dict.name() << " has " << buoyant << ", which all carry the buoyancy:"
            << " it would be counted twice (the pressure gradient holds the hydrostatic part)"
            << exit(FatalIOError);
    }
}

void particleForces::setParticles(const demParticles& particles, scalar cgFactor, const word& timeName)
{
    const scalar pi = constant::mathematical::pi;
    const label n = particles.size();
    diameter_.resize(n);
    volume_.resize(n);
    for (label i = 0; i < n; ++i)
    {
        const double r = particles.radius[i];
        if (!std::isfinite(particles.v[3*i]) || !std::isfinite(particles.v[3*i + 1]) || !std::isfinite(particles.v[3*i + 2]))
        {
            FatalErrorInFunction
                << "particle " << label(particles.id[i]) << " has a non-finite velocity at time "
                << timeName << " (DEM diverged: check the DEM time step)" << exit(FatalError);
        }
        diameter_[i] = 2*r/cgFactor;
        volume_[i] = 4.0/3.0*pi*r*r*r;
    }
    state_.n = n;
    state_.v = reinterpret_cast<const vector*>(particles.v.data());
    state_.d = diameter_.data();
    state_.volume = volume_.data();
}

void particleForces::evaluate(const demParticles& particles, scalar dt)
{
    const label n = state_.n;
    if (needs_ & forceModel::needDvDt)
    {
        velocities_.accelerations(particles, state_.v, dt, state_.dvdt);
    }

    K_.setSize(n);
    K_ = 0;
    fOther_.setSize(n);
    fOther_ = Zero;
    fReact_.setSize(n);
    fReact_ = Zero;
    scalarField Ki(n);
    vectorField fi(n);
    for (const forceModel& fm : models_)
    {
        Ki = 0;
        fi = Zero;
        fm.force(state_, fluid_, Ki, fi);
        K_ += Ki;
        fOther_ += fi;
        // the drag's reaction goes to the fluid through K; of the explicit parts, those that react
        if (fm.reactsOnFluid(modelB_)) fReact_ += fi;
    }
    // Model B without gradPForce (Zhou et al. 2010, CFDEM's modelType B): the fluid carries -grad(p)
    // and every reaction; the particles get the dynamic pressure gradient's share through the drag
    // divided by the fluid fraction, for every drag law (without it a gas bed at eps 0.42 would
    // fluidize at 0.77 instead of 0.43 m/s)
    if (dragOverAlpha_)
    {
        forAll(K_, i) K_[i] /= state_.alphaf[i];
    }
}

void particleForces::packForDem(bool implicitParticleDrag)
{
    const label n = K_.size();
    force_.resize(3*n);
    dragK_.resize(implicitParticleDrag ? n : 0);
    dragUf_.resize(implicitParticleDrag ? 3*n : 0);
    for (label i = 0; i < n; ++i)
    {
        const vector f = force(i);
        const vector fDem = implicitParticleDrag ? fOther_[i] : f;
        for (direction d = 0; d < 3; ++d) force_[3*i + d] = fDem[d];
        if (implicitParticleDrag)
        {
            dragK_[i] = K_[i];
            for (direction d = 0; d < 3; ++d) dragUf_[3*i + d] = state_.Uf[i][d];
        }
    }
}

} // End namespace Foam
