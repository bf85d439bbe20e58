/*---------------------------------------------------------------------------*\
    coarseDemCoupling, the particle-fluid exchange: the fluid sampled at the
    particles (gather, background kernels, dv/dt) and the fluid's sources from
    the particles' forces (src/core/exchange.c). Values of ghosts come from
    their owners (particleHalo).
\*---------------------------------------------------------------------------*/
#include "coarseDemCoupling.H"
#include "fvc.H"
#include "noAliasFvc.H"
#include "zeroGradientFvPatchFields.H"

#include <cmath>

namespace Foam
{

// Model A's fluid carries -alpha_f grad p, and each particle -V_p grad p gathered at it. Summed over the
// particles, V_p times a field gathered with kernels K is the field integrated against K's alpha_p, and
// the fluid's alpha_p is the void-fraction kernels' spread, smoothed: gathered with other kernels
// (backgroundFields) or unsmoothed (diffusion), the particles and the fluid describe different solids
// and the pressure drop no longer carries the bed (the liquid bed with diffusion in Model A: dp plus the
// walls' support 4-14 % short of the weight, Model B within 1.5 %). So in Model A grad p is gathered
// with the void-fraction kernels after smoothing it as alpha_p: the smoothing is self-adjoint in the
// cells' volumes (implicit diffusion, src/core/diffusion.c), so sum V_p S(f)_p = (alpha_k, S f)_V =
// (S alpha_k, f)_V, the integral over the fluid's own alpha_p. div tau the same way: the fluid's
// div(alpha_f tau) = alpha_f div tau + tau . grad(alpha_f), whose first part this matches.
// sizeAwareDiffusion (an operator per size class) cannot smooth another field: gathered unsmoothed.
vectorField coarseDemCoupling::asAlphaSees(const vectorField& field) const
{
    vectorField seen(field);
    const smoothingModel& smoothing = voidFraction_.smoothing();
    if (smoothing.canSmoothLikeAlpha())
    {
        smoothing.smoothLikeAlpha(reinterpret_cast<double*>(seen.data()), 3);
    }
    return seen;
}

void coarseDemCoupling::sampleFluid
(
    const volVectorField& U, const volScalarField& alpha, const volScalarField& p,
    const volScalarField& nuEff, const volVectorField* DUDt
)
{
    const cdc_kernels* k = averaging_->sample();
    particleFluidState& state = forces_->state();
    const label n = state.n;
    // Every field the forces need, gathered in one pass over the kernels and one halo exchange
    std::vector<kernelTransfer::field> fields;
    auto addVector = [&](const vectorField& field, vectorField& out)
    {
        out.setSize(n);
        fields.push_back({reinterpret_cast<const double*>(field.cdata()), 3, reinterpret_cast<double*>(out.data())});
    };
    addVector(U.primitiveField(), state.Uf);
    state.alphaf.setSize(n);
    fields.push_back({alpha.primitiveField().cdata(), 1, state.alphaf.data()});
    tmp<volVectorField> gradP, divTau, vorticity;
    // Model A's grad p and div tau as alpha_p sees them (asAlphaSees), gathered with the void-fraction
    // kernels: with the others when those sample the fluid, apart when background kernels do
    const cdc_kernels* kAlpha = voidFraction_.kernels();
    std::vector<kernelTransfer::field> alphaFields;
    vectorField gradPSeen, divTauSeen;
    auto addAlphaTerm = [&](const vectorField& field, vectorField& seen, vectorField& out)
    {
        if (modelB_)
        {
            addVector(field, out);
            return;
        }
        seen = asAlphaSees(field);
        out.setSize(n);
        (k == kAlpha ? fields : alphaFields).push_back
        (
            {reinterpret_cast<const double*>(seen.cdata()), 3, reinterpret_cast<double*>(out.data())}
        );
    };
    // With no particle on any rank (an open system before its first particle, a gas-only run) the
    // derived fields would be computed for nobody: the stress divergence alone cost 14 % of the
    // particleJet gas run
    const int needs = nParticles_ > 0 ? forces_->needs() : 0;
    if (needs & forceModel::needGradP)
    {
        gradP = fvc::grad(p);
        addAlphaTerm(gradP().primitiveField(), gradPSeen, state.gradP);
    }
    if (needs & forceModel::needDivTau)
    {
        divTau = fvc::laplacian(nuEff, U) + fvc::div(nuEff*noAliasFvc::dev2GradUT(U));
        addAlphaTerm(divTau().primitiveField(), divTauSeen, state.divTau);
    }
    if ((needs & forceModel::needDUfDt) && DUDt)
    {
        addVector(DUDt->primitiveField(), state.DUfDt);
    }
    if (needs & forceModel::needVorticity)
    {
        vorticity = noAliasFvc::curl(U);
        addVector(vorticity().primitiveField(), state.vorticity);
    }

    transfer_.gatherTogether(k, mesh_.nCells(), fields);
    if (!alphaFields.empty()) transfer_.gatherTogether(kAlpha, mesh_.nCells(), alphaFields);
}

// The fluid's sources from the particles' forces, with the void-fraction kernels (src/core/exchange.c:
// Newton's third law between the phases to round-off, for every method). Implicit drag: Ksl, KslUs and
// the other reacting forces in fFluid, with the background-fields correction K (u_f - u_k) (the
// implicit sink takes K u_k with U gathered by these kernels, the particles got K u_f). Explicit drag,
// and smoothExchangeFields: the whole reaction in fFluid; with smoothExchangeFields and implicit drag
// the smoothed Ksl enters as -Ksl (U_new - U) (KslUs = Ksl U), zero at the current U, which keeps the
// fluid's response to a large dt Ksl/alpha stable (CFDEM's implicit/explicit split of the drag).
void coarseDemCoupling::fluidSources(const volVectorField& U)
{
    const label n = particles_.size();
    const bool smooth = voidFraction_.smoothing().smoothsExchangeFields();
    const bool implicit = switches_.implicitDrag && !smooth;
    const cdc_kernels* k = averaging_->reaction();
    // local particles' values followed by the ghosts'
    std::vector<double> exchangeK, exchangeV, exchangeUf, exchangeUk, exchangeF;
    transfer_.withGhosts(forces_->K().cdata(), 1, exchangeK);
    transfer_.withGhosts(reinterpret_cast<const double*>(forces_->state().v), 3, exchangeV);
    transfer_.withGhosts(reinterpret_cast<const double*>(forces_->state().Uf.cdata()), 3, exchangeUf);
    transfer_.withGhosts(reinterpret_cast<const double*>(forces_->fReact().cdata()), 3, exchangeF);
    // the drag's fluid velocity came from other kernels than the reaction's: the difference explicit
    const bool correct = implicit && k != averaging_->sample();
    if (correct)
    {
        vectorField uKernel(n);
        transfer_.gather(k, reinterpret_cast<const double*>(U.primitiveField().cdata()), 3, reinterpret_cast<double*>(uKernel.data()));
        transfer_.withGhosts(reinterpret_cast<const double*>(uKernel.cdata()), 3, exchangeUk);
    }
    const cdc_exchange_in in =
    {
        int32_t(exchangeK.size()), exchangeK.data(), exchangeV.data(), exchangeUf.data(),
        correct ? exchangeUk.data() : nullptr, exchangeF.data(), fluid_.rho,
        implicit ? CDC_EXCHANGE_IMPLICIT : CDC_EXCHANGE_EXPLICIT
    };
    double* f = reinterpret_cast<double*>(fFluid.primitiveFieldRef().data());
    demMesh_.check
    (
        cdc_exchange_sources(k, &in, Ksl.primitiveFieldRef().data(),
                             reinterpret_cast<double*>(KslUs.primitiveFieldRef().data()), f),
        "momentum exchange"
    );
    if (smooth)
    {
        // diffusion in flux form keeps sum(f V), so the balance holds as spread
        if (!switches_.implicitDrag)
        {
            voidFraction_.smoothing().smoothLikeAlpha(f, 3);
            return;
        }
        // K of the local particles and ghosts, already gathered above: no second halo exchange
        std::vector<double> smoothedK(exchangeK.begin(), exchangeK.end());
        for (double& x : smoothedK) x /= fluid_.rho;
        scalarField& ksl = Ksl.primitiveFieldRef();
        demMesh_.check(cdc_spread(k, smoothedK.data(), 1, ksl.data()), "spread");
        // fFluid and Ksl smoothed together, side by side per cell
        const label nCells = mesh_.nCells();
        std::vector<double> both(size_t(nCells)*4);
        for (label c = 0; c < nCells; ++c)
        {
            for (int d = 0; d < 3; ++d) both[size_t(c)*4 + d] = f[size_t(c)*3 + d];
            both[size_t(c)*4 + 3] = ksl[c];
        }
        voidFraction_.smoothing().smoothLikeAlpha(both.data(), 4);
        for (label c = 0; c < nCells; ++c)
        {
            for (int d = 0; d < 3; ++d) f[size_t(c)*3 + d] = both[size_t(c)*4 + d];
            ksl[c] = both[size_t(c)*4 + 3];
        }
        KslUs.primitiveFieldRef() = Ksl.primitiveField()*U.primitiveField();
    }
}

} // End namespace Foam
