/*---------------------------------------------------------------------------*\
    coarseDemCoupling, the diagnostics: they change no number the fluid or the
    DEM sees. Balances of solid volume and momentum, the momentum exchanged in
    time over each DEM segment, lost particles, explicit coupling beyond its
    range, and the Coupling / Exchange lines of the log.
\*---------------------------------------------------------------------------*/
#include "coarseDemCoupling.H"

#include <cmath>
#include <string>

namespace Foam
{

//- checkDragCoverage warns above this share of dense cells without drag. Measured with centre +
//  diffusion (35bc19c): the Mueller bed bubbling at dx/d = 1 16 % (it runs, and its profiles are
//  among the best, but the gas crosses those cells at twice the speed of the other dense cells at the
//  same gas fraction: validation/muller/gasBypass.py), settled at dx/d = 1 6 %; settled at dx/d = 0.67
//  64 % (diverges; with reactionKernel background 0 %, and it runs); the packed bed of
//  tutorials/packedBedCylinder 56 % (pressure drop about 90 % below Ergun's). The count is reported at
//  write times at any share.
static const scalar maxDragFreeDenseFraction = 0.25;

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
    // them, and the DEM has just run the segment that used them. A segment in which particles
    // entered or left is not compared: the particles' impulse misses the part of the segment
    // they were not in the DEM for.
    if (!exchangePending_) return;
    if (segmentChanged)
    {
        ++nExchangesSkipped_;
        return;
    }
    const vector particles =
        returnReduce(dem_->couplingImpulse(), sumOp<vector>()) - segmentSeconds_*nonReacting_;
    const vector fluid = exchangeDt_*fluidMomentumSource(U);
    // relative to the larger of the step's exchange at the coupling (CFD step x sum |f|) and either
    // phase's impulse: at a start from rest the forces at the coupling are near zero while the fluid's
    // implicit drag at its new velocity is not, and the difference is then the whole impulse (1)
    const scalar exchanged = exchangeDt_*forceScale_;
    const scalar scale = max(exchanged, max(mag(particles), mag(fluid)));
    exchangeLastRel_ = scale > 0 ? mag(particles + fluid)/scale : 0;
    exchangeMaxRel_ = max(exchangeMaxRel_, exchangeLastRel_);
    exchangeNet_ += particles + fluid;
    exchangeGross_ += exchanged;
    ++nExchangesCompared_;
}

// Balances for the Coupling line: solid volume in cells vs particles; the momentum the fluid gets (at
// the current U) vs minus what the particles get from the forces that act back on it.
void coarseDemCoupling::recordBalances(const volVectorField& U)
{
    timers_.start(stageTimers::monitor);
    vector fParticles(Zero);
    forceScale_ = 0;
    nonReacting_ = Zero;
    // the particles' buoyant weight and the part of it the fluid's force carries (p holds the
    // hydrostatic part: Model A's -V grad p and Model B's Archimedes both carry rho_f V g)
    const scalar gMag = mag(fluid_.g);
    const vector up = gMag > 0 ? -fluid_.g/gMag : vector::zero;
    scalar weight = 0, carried = 0;
    forAll(K_, i)
    {
        const vector f = particleForce(i);
        fParticles += K_[i]*(state_.Uf[i] - state_.v[i]) + fReact_[i];
        nonReacting_ += fOther_[i] - fReact_[i];
        forceScale_ += mag(f);
        weight += (particles_.density[i] - fluid_.rho)*volume_[i]*gMag;
        carried += (f & up) - fluid_.rho*volume_[i]*gMag;
    }
    // this rank's sums; report() reduces them over the ranks once
    weightBuoyant_ += weight;
    weightCarried_ += carried;
    ++nWeightSamples_;
    scalar vp = 0;
    for (const double v : volume_) vp += v;
    solidVolumeParticles_ = returnReduce(vp, sumOp<scalar>());
    solidVolumeCells_ = gSum(alphaP.primitiveField()*mesh_.V());
    const vector fluidTotal = fluidMomentumSource(U);
    reduce(fParticles, sumOp<vector>());
    reduce(nonReacting_, sumOp<vector>());
    reduce(forceScale_, sumOp<scalar>());
    momentumImbalance_ = mag(fluidTotal + fParticles);
    timers_.stop();
}

void coarseDemCoupling::checkExplicitRange(const volScalarField& alpha)
{
    const scalar dt = mesh_.time().deltaTValue();
    const scalar dtParticle = implicitParticleDrag_ ? dem_->timestep() : dt;
    const label n = particles_.size();
    scalarField particleRatio(n);
    forAll(particleRatio, i) particleRatio[i] = dtParticle*K_[i]/(particles_.density[i]*volume_[i]);
    tallyStepRatios(particleRatio, particleDragRatio_, nParticlesBeyond_);
    if (nParticlesBeyond_ > 0 && !warnedParticleSide_)
    {
        WarningInFunction
            << "explicit particle-side coupling beyond its range at time " << mesh_.time().timeName()
            << ": " << nParticlesBeyond_ << " particle(s) have "
            << (implicitParticleDrag_ ? "DEM step" : "CFD step") << " x K/m > 1 (max "
            << particleDragRatio_ << "); the drag K (u_f - v) is held for that step, so their"
            << " velocity overshoots (unstable above 2): "
            << (implicitParticleDrag_ ? "reduce the DEM time step"
                                      : "set implicitParticleDrag true or reduce couplingInterval")
            << endl;
        warnedParticleSide_ = true;
    }

    fluidDragRatio_ = 0;
    nCellsBeyond_ = 0;
    if (implicitDrag_) return;   // Ksl is implicit in the fluid momentum equation: no limit
    const scalarField Kr(K_/fluid_.rho);
    scalarField KslExplicit(mesh_.nCells(), 0);
    spread(Kr.cdata(), 1, KslExplicit.data());
    tallyStepRatios(dt*KslExplicit/alpha.primitiveField(), fluidDragRatio_, nCellsBeyond_);
    if (nCellsBeyond_ > 0 && !warnedFluidSide_)
    {
        WarningInFunction
            << "explicit fluid drag beyond its range at time " << mesh_.time().timeName() << ": "
            << nCellsBeyond_ << " cell(s) have CFD step x Ksl/alpha_f > 1 (max " << fluidDragRatio_
            << "); set implicitDrag true in " << dict_.name() << " or reduce couplingInterval" << endl;
        warnedFluidSide_ = true;
    }
}

// A particle whose kernel puts more than the packing limit 1 - alphaMin into one cell by itself (a
// grain larger than the cells with the centre method, or a coarse-grained parcel): the limiter then
// moves the excess at every step, and alpha_p no longer says where the solid is. Smoothing spreads
// alpha_p after the kernels, so the check is for unsmoothed fields only.
void coarseDemCoupling::checkParcelFill()
{
    if (warnedParcelFill_ || voidFraction_.smoothingName() != "off") return;
    const cdc_kernels* k = voidFraction_.kernels();
    const int32_t* offsets = cdc_kernels_offsets(k);
    const int32_t* cells = cdc_kernels_cells(k);
    const double* weights = cdc_kernels_weights(k);
    const scalarField& V = mesh_.V();
    scalar worst = 0;
    label worstId = -1;
    for (label i = 0; i < particles_.size(); ++i)
    {
        for (int32_t e = offsets[i]; e < offsets[i + 1]; ++e)
        {
            if (cells[e] >= V.size()) continue;   // a cell of another rank: checked there
            const scalar fill = volume_[i]*weights[e]/V[cells[e]];
            if (fill > worst) { worst = fill; worstId = label(particles_.id[i]); }
        }
    }
    const scalar worstAll = returnReduce(worst, maxOp<scalar>());
    const scalar limit = 1 - voidFraction_.alphaMin();
    if (worstAll <= limit) return;
    const label id = returnReduce(worst == worstAll ? worstId : -1, maxOp<label>());
    WarningInFunction
        << "particle " << id << " alone fills " << worstAll << " of a cell's volume at time "
        << mesh_.time().timeName() << ", beyond the packing limit 1 - alphaMin = " << limit << " ("
        << dict_.name() << ": voidFractionModel " << voidFraction_.method() << ", coarseGrainingFactor "
        << cgFactor_ << ")" << nl
        << "    the limiter moves the excess to neighbouring cells at every step (the Coupling line counts"
        << " it): use a method that spreads a particle over several cells (bigParticle, divided, twoGrid)"
        << " or diffusion smoothing, or smaller grains" << endl;
    warnedParcelFill_ = true;
}

// Smoothing spreads alpha_p beyond the cells of the kernels, while the fluid's drag (Ksl, fFluid)
// stays in those cells unless diffusionProps/smoothExchangeFields smooths it alike. Where particles
// are as large as the cells or larger, many dense cells then hold solid and no drag, and the gas
// bypasses the particles through them: a packed bed about 90 % below Ergun (doc/methods.md); the
// Mueller bed at dx/d = 0.67 (centre + diffusion b = 6 d, 64 % of the settled bed's cells without a
// particle centre) diverged in its first CFD steps. A dense cell: alpha_p above half the packing limit.
void coarseDemCoupling::checkDragCoverage()
{
    if (voidFraction_.smoothingName() == "off" || voidFraction_.smoothsExchangeFields())
    {
        return;
    }
    const cdc_kernels* k = reactionKernels();   // where the drag goes into the fluid
    const int32_t* offsets = cdc_kernels_offsets(k);
    const int32_t* cells = cdc_kernels_cells(k);
    const double* weights = cdc_kernels_weights(k);
    const label nCells = mesh_.nCells();
    std::vector<bool> dragged(nCells, false);
    // the ghosts' kernels too: a neighbour's particle can put drag into this rank's cells
    const label nKernels = cdc_kernels_count(k);
    for (label i = 0; i < nKernels; ++i)
    {
        for (int32_t e = offsets[i]; e < offsets[i + 1]; ++e)
        {
            if (cells[e] < nCells && weights[e] > 0) dragged[cells[e]] = true;
        }
    }
    const scalar dense = 0.5*(1 - voidFraction_.alphaMin());
    label nDense = 0, nBare = 0;
    forAll(alphaP, c)
    {
        if (alphaP[c] <= dense) continue;
        ++nDense;
        if (!dragged[c]) ++nBare;
    }
    reduce(nDense, sumOp<label>());
    reduce(nBare, sumOp<label>());
    nDenseCells_ = nDense;          // reported with the time of the count (report)
    nDenseCellsNoDrag_ = nBare;
    denseCountTime_ = mesh_.time().timeName();
    const scalar bare = nDense > 0 ? scalar(nBare)/nDense : 0;
    if (warnedDragCoverage_ || bare <= maxDragFreeDenseFraction) return;
    WarningInFunction
        << nBare << " of the " << nDense << " dense cells (alpha_p > " << dense << ") get no drag at time "
        << mesh_.time().timeName() << " (" << 100*bare << " %): " << dict_.name() << " smooths alpha_p ("
        << "smoothingModel " << voidFraction_.smoothingName() << ") but the drag stays in the cells of the"
        << " voidFractionModel " << voidFraction_.method() << " kernels, and the gas bypasses the particles"
        << " through the others (on particles as large as the cells: a packed bed's drag far below Ergun's,"
        << " or a run that diverges)" << nl << "    "
        << (voidFraction_.smoothingName() == "diffusion"
            ? "set smoothExchangeFields true in diffusionProps (the drag smoothed alike), or"
            : "use smoothingModel diffusion with smoothExchangeFields true in diffusionProps (the drag"
              " smoothed alike), or")
        << " backgroundFields on with backgroundFieldsProps { reactionKernel background; } (the drag in the"
        << " expanded kernels' cells), or a method that spreads a particle over several cells (bigParticle,"
        << " twoGrid, gaussian)" << endl;
    warnedDragCoverage_ = true;
}

void coarseDemCoupling::report(Ostream& os) const
{
    const scalar volErr = solidVolumeParticles_ > 0
        ? mag(solidVolumeCells_ - solidVolumeParticles_)/solidVolumeParticles_ : 0;
    os  << "Coupling: particles " << nParticles_
        << ", solid volume particles " << solidVolumeParticles_ << " cells " << solidVolumeCells_
        << " (rel. err " << volErr << ")"
        << ", momentum imbalance " << momentumImbalance_ << " N of " << forceScale_ << " N"
        << ", limiter moved " << returnReduce(voidFraction_.movedVolume(), sumOp<scalar>()) << " m3 in "
        << returnReduce(voidFraction_.nLimitedCells(), sumOp<label>()) << " cells"
        << ", drag dt K/m max " << particleDragRatio_ << " (" << nParticlesBeyond_ << " particles > 1)";
    if (alphaRelaxationTime_ > 0)
    {
        os  << ", alpha relaxed over " << alphaRelaxationTime_ << " s: solid volume 1 - alpha "
            << solidVolumeAlpha_ << " (rel. err " << (solidVolumeParticles_ > 0
               ? mag(solidVolumeAlpha_ - solidVolumeParticles_)/solidVolumeParticles_ : 0) << ")";
    }
    if (needs_ & forceModel::needDvDt)
    {
        // particles without a velocity of the last coupling (at the start or restart: all; later:
        // inserted ones) get dv/dt = 0 for that step
        os  << ", dv/dt unknown for " << firstDvDt_ << " particles at the first coupling, "
            << unknownDvDt_ << " since";
    }
    if (!implicitDrag_)
    {
        os  << ", explicit fluid drag dt Ksl/alpha max " << fluidDragRatio_ << " (" << nCellsBeyond_
            << " cells > 1)";
    }
    if (nDenseCells_ >= 0)
    {
        // smoothed alpha_p, unsmoothed drag: the gas streams through the dense cells the drag misses
        os  << ", dense cells without drag " << nDenseCellsNoDrag_ << " of " << nDenseCells_ << " at t = "
            << denseCountTime_;
    }
    os  << endl;
    const scalar weightBuoyant = returnReduce(weightBuoyant_, sumOp<scalar>());
    if (weightBuoyant > 0)
    {
        // averaged over the couplings since the last report; in a fluidized bed the fluid carries
        // the whole buoyant weight (the pressure drop equals it), and what it does not carry rests
        // on the walls through the contacts (or accelerates the particles)
        const scalar share = returnReduce(weightCarried_, sumOp<scalar>())/weightBuoyant;
        os  << "Weight: the fluid carries " << 100*share << " % of the particles' buoyant weight (mean of "
            << nWeightSamples_ << " couplings since the last report)";
        if (share < 0.97)
        {
            os  << "; " << 100*(1 - share) << " % rests on walls through the contacts (a packed or"
                << " jammed bed, particles on a distributor) or accelerates the particles";
        }
        os  << endl;
    }
    weightBuoyant_ = weightCarried_ = 0;
    nWeightSamples_ = 0;
    if (inventory_.open() || inventory_.nChanged() > 0) inventory_.report(os);
    os  << "Exchange in time: " << nExchangesCompared_ << " couplings compared";
    if (nExchangesSkipped_ > 0) os << " (" << nExchangesSkipped_ << " with particles entering or leaving not)";
    os  << ", |particles' + fluid's"
        << " impulse| of a coupling step last " << exchangeLastRel_ << " max " << exchangeMaxRel_
        << " x exchange; since the start net " << exchangeNet_ << " N s of " << exchangeGross_
        << " N s" << endl;

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
        const scalar deepest = returnReduce(scalar(depth), maxOp<scalar>());
        const scalar idDeepest = returnReduce(depth == deepest ? scalar(id) : scalar(-1), maxOp<scalar>());
        os  << "Particles partly outside the mesh: " << nOutAll << ", the deepest reaches " << 100*deepest
            << " % of its radius beyond it (particle " << std::to_string(std::llround(idDeepest)).c_str() << ")" << endl;
    }
}

} // End namespace Foam
