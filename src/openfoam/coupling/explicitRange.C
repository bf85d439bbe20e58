#include "explicitRange.H"
#include "error.H"
#include "PstreamReduceOps.H"

namespace Foam
{

//- Largest step x rate over all ranks and how many exceed 1 (the explicit update's range)
static void tallyStepRatios(const UList<scalar>& ratio, scalar& largest, label& nBeyond)
{
    largest = 0;
    nBeyond = 0;
    for (const scalar r : ratio)
    {
        largest = max(largest, r);
        if (r > 1) ++nBeyond;
    }
    reduce(largest, maxOp<scalar>());
    reduce(nBeyond, sumOp<label>());
}

void explicitRange::checkParticles(const UList<scalar>& ratio, bool demStep, const word& time)
{
    tallyStepRatios(ratio, particleRatio_, nParticlesBeyond_);
    if (nParticlesBeyond_ > 0 && !warnedParticles_)
    {
        WarningInFunction
            << "explicit particle-side coupling beyond its range at time " << time
            << ": " << nParticlesBeyond_ << " particle(s) have "
            << (demStep ? "DEM step" : "CFD step") << " x K/m > 1 (max "
            << particleRatio_ << "); the drag K (u_f - v) is held for that step, so their"
            << " velocity overshoots (unstable above 2): "
            << (demStep ? "reduce the DEM time step" : "set implicitParticleDrag true or reduce couplingInterval")
            << endl;
        warnedParticles_ = true;
    }
}

void explicitRange::checkFluid(const UList<scalar>& ratio, const fileName& dictName, const word& time)
{
    tallyStepRatios(ratio, fluidRatio_, nCellsBeyond_);
    if (nCellsBeyond_ > 0 && !warnedFluid_)
    {
        WarningInFunction
            << "explicit fluid drag beyond its range at time " << time << ": "
            << nCellsBeyond_ << " cell(s) have CFD step x Ksl/alpha_f > 1 (max " << fluidRatio_
            << "); set implicitDrag true in " << dictName << " or reduce couplingInterval" << endl;
        warnedFluid_ = true;
    }
}

} // End namespace Foam
