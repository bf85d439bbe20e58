#include "kernelCoverage.H"
#include "error.H"
#include "largestOnRanks.H"

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

// A particle whose kernel puts more than the packing limit 1 - alphaMin into one cell by itself (a
// grain larger than the cells with the centre method, or a coarse-grained parcel): the limiter then
// moves the excess at every step, and alpha_p no longer says where the solid is. Smoothing spreads
// alpha_p after the kernels, so the check is for unsmoothed fields only.
void kernelCoverage::checkParcelFill
(
    const voidFraction& vf, const std::vector<double>& volume, const demParticles& particles,
    const scalarField& V, scalar cgFactor, const fileName& dictName, const word& time
)
{
    if (warnedParcelFill_ || vf.smoothingName() != "off") return;
    const cdc_kernels* k = vf.kernels();
    const int32_t* offsets = cdc_kernels_offsets(k);
    const int32_t* cells = cdc_kernels_cells(k);
    const double* weights = cdc_kernels_weights(k);
    scalar worst = 0;
    label worstId = -1;
    for (label i = 0; i < particles.size(); ++i)
    {
        for (int32_t e = offsets[i]; e < offsets[i + 1]; ++e)
        {
            if (cells[e] >= V.size()) continue;   // a cell of another rank: checked there
            const scalar fill = volume[i]*weights[e]/V[cells[e]];
            if (fill > worst) { worst = fill; worstId = label(particles.id[i]); }
        }
    }
    scalar rec[2] = {worst, scalar(worstId)};
    largestOnRanks(rec);
    const scalar worstAll = rec[0];
    const scalar limit = 1 - vf.alphaMin();
    if (worstAll <= limit) return;
    const label id = label(rec[1]);
    WarningInFunction
        << "particle " << id << " alone fills " << worstAll << " of a cell's volume at time "
        << time << ", beyond the packing limit 1 - alphaMin = " << limit << " ("
        << dictName << ": voidFractionModel " << vf.method() << ", coarseGrainingFactor "
        << cgFactor << ")" << nl
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
void kernelCoverage::checkDragCoverage
(
    const voidFraction& vf, const cdc_kernels* k, const volScalarField& alphaP, const fileName& dictName,
    const word& time
)
{
    if (vf.smoothingName() == "off" || vf.smoothing().smoothsExchangeFields())
    {
        return;
    }
    const int32_t* offsets = cdc_kernels_offsets(k);
    const int32_t* cells = cdc_kernels_cells(k);
    const double* weights = cdc_kernels_weights(k);
    const label nCells = alphaP.size();
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
    const scalar dense = 0.5*(1 - vf.alphaMin());
    label nDense = 0, nBare = 0;
    forAll(alphaP, c)
    {
        if (alphaP[c] <= dense) continue;
        ++nDense;
        if (!dragged[c]) ++nBare;
    }
    reduce(nDense, sumOp<label>());
    reduce(nBare, sumOp<label>());
    nDense_ = nDense;          // reported with the time of the count (report)
    nDenseNoDrag_ = nBare;
    countTime_ = time;
    const scalar bare = nDense > 0 ? scalar(nBare)/nDense : 0;
    if (warnedDragCoverage_ || bare <= maxDragFreeDenseFraction) return;
    WarningInFunction
        << nBare << " of the " << nDense << " dense cells (alpha_p > " << dense << ") get no drag at time "
        << time << " (" << 100*bare << " %): " << dictName << " smooths alpha_p ("
        << "smoothingModel " << vf.smoothingName() << ") but the drag stays in the cells of the"
        << " voidFractionModel " << vf.method() << " kernels, and the gas bypasses the particles"
        << " through the others (on particles as large as the cells: a packed bed's drag far below Ergun's,"
        << " or a run that diverges)" << nl << "    "
        << (vf.smoothingName() == "diffusion"
            ? "set smoothExchangeFields true in diffusionProps (the drag smoothed alike), or"
            : "use smoothingModel diffusion with smoothExchangeFields true in diffusionProps (the drag"
              " smoothed alike), or")
        << " backgroundFields on with backgroundFieldsProps { reactionKernel background; } (the drag in the"
        << " expanded kernels' cells), or a method that spreads a particle over several cells (bigParticle,"
        << " twoGrid, gaussian)" << endl;
    warnedDragCoverage_ = true;
}

void kernelCoverage::report(Ostream& os) const
{
    if (nDense_ < 0) return;
    // smoothed alpha_p, unsmoothed drag: the gas streams through the dense cells the drag misses
    os  << ", dense cells without drag " << nDenseNoDrag_ << " of " << nDense_ << " at t = " << countTime_;
}

} // End namespace Foam
