#include "setupAdvice.H"
#include "voidFraction.H"
#include "error.H"
#include "PstreamReduceOps.H"

namespace Foam
{

//- Cells narrower than this many particle diameters: the centre kernel leaves dense cells without a
//  particle centre, so without drag unless the smoothing spreads the drag too
static const scalar coarseCellsPerDiameter = 3;

//- Particles this many cells across or more sample mostly the cells they fill themselves
static const scalar selfSamplingDiameterPerCell = 1.5;

void adviseOnSetup(const dictionary& dict, const voidFraction& vf, const scalarField& V, const std::vector<double>& radius)
{
    scalar dMax = 0;
    for (const double r : radius) dMax = max(dMax, 2*r);
    dMax = returnReduce(dMax, maxOp<scalar>());
    const scalar nCells = returnReduce(scalar(V.size()), sumOp<scalar>());
    const scalar dx = cbrt(returnReduce(sum(V), sumOp<scalar>())/max(nCells, scalar(1)));   // the mean cell's edge
    if (dMax <= 0 || dx <= 0) return;

    // centre + smoothing with the drag left in the particle-centre cells (the smoothing spreads
    // alpha_p only): measured on tutorials/packedBedCylinder (d/dx = 1.3, results/methods.csv at
    // 4612905): centre + diffusion b = 12 mm, alpha only, -89.33 % against Ergun; with
    // smoothExchangeFields true -6.11 %
    if
    (
        vf.method() == "centre" && vf.smoothingName() == "diffusion" && !vf.smoothing().smoothsExchangeFields()
     && dx < coarseCellsPerDiameter*dMax
    )
    {
        WarningInFunction
            << dict.name() << ": voidFractionModel centre with smoothingModel diffusion and the drag left in the cells of the particle centres, on cells " << dx/dMax
            << " particle diameters wide (mean cell " << dx << " m, largest particle " << dMax << " m; below "
            << coarseCellsPerDiameter << ")" << nl
            << "    the smoothing spreads alpha_p but not the drag: the fluid bypasses the particles through the"
            << " dense cells that hold no particle centre (measured: a packed bed's pressure drop 89 % below"
            << " Ergun's, tutorials/packedBedCylinder/results/methods.csv)" << nl
            << "    set smoothExchangeFields true in diffusionProps (-6.1 % there), or use a method that spreads"
            << " a particle over several cells (bigParticle, twoGrid)" << endl;
    }

    // centre or divided, the fluid sampled with the alpha_p kernels, particles larger than the cells:
    // a particle on its own reads the fluid fraction it makes itself. Measured with
    // tutorials/settlingTest -coarse (d/dx = 2, at f16b5e5): divided 29.6 % slower than its drag law's
    // terminal velocity, its velocity jumping by up to 9.3 % of it across the faces; centre 5.3 % fast
    // on average, jumping by up to 32 %; bigParticle n = 5 with background fields 0.61 %, 0.04 %
    if
    (
        (vf.method() == "centre" || vf.method() == "divided")
     && !dict.lookupOrDefault<Switch>("backgroundFields", false)
     && dMax >= selfSamplingDiameterPerCell*dx
    )
    {
        WarningInFunction
            << dict.name() << ": voidFractionModel " << vf.method() << " with backgroundFields off, and particles"
            << " up to " << dMax/dx << " cells across (largest particle " << dMax << " m, mean cell " << dx << " m)"
            << nl << "    a particle away from others samples the fluid fraction and velocity of the cells it fills"
            << " itself: a single sphere of d/dx = 2 settled 29.6 % slower than its drag law with divided, its"
            << " velocity jumping by up to 32 % across the cell faces with centre"
            << " (tutorials/settlingTest/Allrun -coarse -method " << vf.method() << " -background off)" << nl
            << "    set backgroundFields on (the fluid sampled over n = 5 radii: within 0.61 % there, smooth to"
            << " 0.04 %); in a dense bed, where each cell's fraction is the bed's, this matters less" << endl;
    }
}

} // End namespace Foam
