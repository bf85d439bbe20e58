/*---------------------------------------------------------------------------*\
    KochHillDrag: drag from the lattice-Boltzmann fits of Hill, Koch & Ladd
    (J. Fluid Mech. 448, 2001; Koch & Hill, Annu. Rev. Fluid Mech. 33, 2001),
    in the form used by CFD-DEM codes, f = K (u_f - v) with
        K  = V 18 mu alpha^2 (F0(phi) + F3(phi) Re/2) / d^2,   phi = 1 - alpha,
        Re = alpha |u_r| d / nu,
        F0 = (1 + 3 sqrt(phi/2) + 135/64 phi ln(phi) + 16.14 phi)
             / (1 + 0.681 phi - 8.48 phi^2 + 8.16 phi^3)         (phi < 0.4)
           = 10 phi / (1 - phi)^3                                (phi >= 0.4)
        F3 = 0.0673 + 0.212 phi + 0.0232 / (1 - phi)^5.
    Range: these are fits to lattice-Boltzmann drag in arrays of spheres; below
    a solid fraction phi = 0.01 Benyahia et al. (Powder Technol. 162, 2006)
    replace them by the single-sphere F = 1 + 3/8 Re_r. Here phi < 0.01 warns
    once per run. A single sphere (its own phi about 0.008 through the
    background kernel) is outside it at every Re: at alpha = 1 the law is
    Cd = 24/Re (1 + 0.045 Re), 18 % below the standard drag curve at Re = 10 and
    136 % above it at Re = 1000 (tutorials/settlingTest/README.md).
    In the dilute limit K -> 3 pi mu d (Stokes). d is the real particle
    diameter, V the grain's solid volume (coarse graining as in GidaspowDrag).
\*---------------------------------------------------------------------------*/
#include "forceModel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{

class KochHillDrag : public forceModel
{
public:
    TypeName("KochHillDrag");
    KochHillDrag(const word& name, const dictionary& props) : forceModel(name, props) {}
    bool isDrag() const override { return true; }

    void force(const particleFluidState& s, const fluidProperties& fl, scalarField& K, vectorField&) const override
    {
        for (label i = 0; i < s.n; ++i)
        {
            const scalar d = s.d[i], a = s.alphaf[i], phi = max(1 - a, 0.0);
            if (phi < 0.01)
            {
                warnOutOfRange("phi", "solid volume fraction 1 - alpha", phi,
                    "phi >= 0.01 (Hill, Koch & Ladd 2001 arrays; Benyahia et al. 2006 use a single-sphere law below)");
            }
            const scalar Re = a*mag(s.Uf[i] - s.v[i])*d/fl.nu;
            const scalar F0 = phi < 0.4
                ? (1 + 3*sqrt(phi/2) + (phi > 0 ? 135.0/64*phi*log(phi) : 0) + 16.14*phi)
                 /(1 + 0.681*phi - 8.48*sqr(phi) + 8.16*pow3(phi))
                : 10*phi/pow3(1 - phi);
            const scalar F3 = 0.0673 + 0.212*phi + 0.0232/pow5(1 - phi);
            K[i] = s.volume[i]*18*fl.nu*fl.rho*sqr(a)*(F0 + 0.5*F3*Re)/sqr(d);
        }
    }
};

defineTypeNameAndDebug(KochHillDrag, 0);
addToRunTimeSelectionTable(forceModel, KochHillDrag, dictionary);

} // End namespace Foam
