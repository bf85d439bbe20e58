/*---------------------------------------------------------------------------*\
    coarseDemCoupling, the diagnostics: they change no number the fluid or the
    DEM sees. Balances of solid volume and momentum, the momentum exchanged in
    time over each DEM segment, lost particles, explicit coupling beyond its
    range, and the Coupling / Exchange lines of the log.
\*---------------------------------------------------------------------------*/
#include "coarseDemCoupling.H"
#include "largestOnRanks.H"

#include <cmath>
#include <string>

namespace Foam
{

Foam::vector coarseDemCoupling::fluidMomentumSource(const volVectorField& U) const
{
    const scalarField& V = mesh_.V();
    return fluid_.rho*gSum
    (
        (fFluid.primitiveField() - Ksl.primitiveField()*U.primitiveField() + KslUs.primitiveField())*V
    );
}

void coarseDemCoupling::compareExchangeInTime(const volVectorField& U, bool segmentChanged)
{
    // before the exchange fields are replaced: U is the fluid's velocity after the step that used
    // them, and the DEM has just run the segment that used them
    if (!diag_.exchange.pending()) return;
    if (segmentChanged)
    {
        diag_.exchange.skip();
        return;
    }
    // the forceScale of the last coupling, whose forces the segment used (recordBalances replaces it
    // later in this step)
    diag_.exchange.compare
    (
        returnReduce(dem_->couplingImpulse(), sumOp<vector>()), fluidMomentumSource(U), diag_.balances.forceScale
    );
}

// Balances for the Coupling line: solid volume in cells vs particles; the momentum the fluid gets (at
// the current U) vs minus what the particles get from the forces that act back on it.
void coarseDemCoupling::recordBalances(const volVectorField& U)
{
    timers_.start(stageTimers::monitor);
    vector fParticles(Zero);
    diag_.balances.forceScale = 0;
    vector nonReacting(Zero);
    // the particles' buoyant weight and the part of it the fluid's force carries (p holds the
    // hydrostatic part: Model A's -V grad p and Model B's Archimedes both carry rho_f V g)
    const scalar gMag = mag(fluid_.g);
    const vector up = gMag > 0 ? -fluid_.g/gMag : vector::zero;
    scalar weight = 0, carried = 0;
    const particleFluidState& state = forces_->state();
    const scalarField& K = forces_->K();
    const vectorField& fReact = forces_->fReact();
    const std::vector<double>& volume = forces_->volumes();
    forAll(K, i)
    {
        const vector f = forces_->force(i);
        fParticles += K[i]*(state.Uf[i] - state.v[i]) + fReact[i];
        nonReacting += forces_->fOther()[i] - fReact[i];
        diag_.balances.forceScale += mag(f);
        weight += (particles_.density[i] - fluid_.rho)*volume[i]*gMag;
        carried += (f & up) - fluid_.rho*volume[i]*gMag;
    }
    // this rank's sums; report() reduces them over the ranks once
    diag_.balances.weightBuoyant += weight;
    diag_.balances.weightCarried += carried;
    ++diag_.balances.nWeightSamples;
    scalar vp = 0;
    for (const double v : volume) vp += v;
    diag_.balances.solidVolumeParticles = returnReduce(vp, sumOp<scalar>());
    diag_.balances.solidVolumeCells = gSum(alphaP.primitiveField()*mesh_.V());
    diag_.crossings.limiter(returnReduce(voidFraction_.movedVolume(), sumOp<scalar>()), diag_.balances.solidVolumeParticles);
    const vector fluidTotal = fluidMomentumSource(U);
    reduce(fParticles, sumOp<vector>());
    reduce(nonReacting, sumOp<vector>());
    reduce(diag_.balances.forceScale, sumOp<scalar>());
    diag_.exchange.setNonReacting(nonReacting);
    diag_.balances.momentumImbalance = mag(fluidTotal + fParticles);
    timers_.stop();
}

void coarseDemCoupling::checkExplicitRange(const volScalarField& alpha)
{
    const scalar dt = mesh_.time().deltaTValue();
    const scalar dtParticle = switches_.implicitParticleDrag ? dem_->timestep() : dt;
    const label n = particles_.size();
    scalarField particleRatio(n);
    const scalarField& K = forces_->K();
    forAll(particleRatio, i) particleRatio[i] = dtParticle*K[i]/(particles_.density[i]*forces_->volumes()[i]);
    diag_.range.checkParticles(particleRatio, switches_.implicitParticleDrag, mesh_.time().timeName());
    if (switches_.implicitDrag)
    {
        diag_.range.fluidImplicit();   // Ksl is implicit in the fluid momentum equation: no limit
        return;
    }
    const scalarField Kr(K/fluid_.rho);
    scalarField KslExplicit(mesh_.nCells(), 0);
    transfer_.spread(voidFraction_.kernels(), Kr.cdata(), 1, KslExplicit.data());
    diag_.range.checkFluid(dt*KslExplicit/alpha.primitiveField(), dict_.name(), mesh_.time().timeName());
}

void coarseDemCoupling::report(Ostream& os) const
{
    const scalar volErr = diag_.balances.solidVolumeParticles > 0
        ? mag(diag_.balances.solidVolumeCells - diag_.balances.solidVolumeParticles)/diag_.balances.solidVolumeParticles : 0;
    os  << "Coupling: particles " << nParticles_
        << ", solid volume particles " << diag_.balances.solidVolumeParticles << " cells " << diag_.balances.solidVolumeCells
        << " (rel. err " << volErr << ")"
        << ", momentum imbalance " << diag_.balances.momentumImbalance << " N of " << diag_.balances.forceScale << " N"
        << ", limiter moved " << returnReduce(voidFraction_.movedVolume(), sumOp<scalar>()) << " m3 in "
        << returnReduce(voidFraction_.nLimitedCells(), sumOp<label>()) << " cells"
        << ", drag dt K/m max " << diag_.range.particleRatio() << " (" << diag_.range.nParticlesBeyond()
        << " particles > 1)";
    if (alphaRelaxationTime_ > 0)
    {
        os  << ", alpha relaxed over " << alphaRelaxationTime_ << " s: solid volume 1 - alpha "
            << diag_.balances.solidVolumeAlpha << " (rel. err " << (diag_.balances.solidVolumeParticles > 0
               ? mag(diag_.balances.solidVolumeAlpha - diag_.balances.solidVolumeParticles)/diag_.balances.solidVolumeParticles : 0) << ")";
    }
    forces_->report(os);
    if (!switches_.implicitDrag)
    {
        os  << ", explicit fluid drag dt Ksl/alpha max " << diag_.range.fluidRatio() << " ("
            << diag_.range.nCellsBeyond()
            << " cells > 1)";
    }
    diag_.coverage.report(os);
    os  << endl;
    diag_.balances.reportWeight(os);
    if (diag_.inventory.open() || diag_.inventory.nChanged() > 0) diag_.inventory.report(os);
    diag_.exchange.report(os);
    diag_.crossings.report(os, voidFraction_.method(), mesh_.time().value());

    // particles reaching through the mesh boundary: a DEM wall's contact overlap (small depths), or a
    // particle leaving the mesh (large ones); counted here, at reports only (six locations each)
    const cdc_particles cp = coreParticles();
    int32_t nOut = 0;
    double depth = 0;
    int64_t id = -1;
    demMesh_.check(cdc_kernels_partly_outside(voidFraction_.kernels(), &cp, &nOut, &depth, &id),
                   "particles partly outside the mesh");
    const label nOutAll = returnReduce(label(nOut), sumOp<label>());
    if (nOutAll > 0)
    {
        scalar deepest[2] = {scalar(depth), scalar(id)};
        largestOnRanks(deepest);
        os  << "Particles partly outside the mesh: " << nOutAll << ", the deepest reaches " << 100*deepest[0]
            << " % of its radius beyond it (particle " << std::to_string(std::llround(deepest[1])).c_str() << ")" << endl;
    }
}

} // End namespace Foam
