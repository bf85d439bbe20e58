/*---------------------------------------------------------------------------*\
    GidaspowDrag: Ergun for dense, Wen & Yu for dilute regions (Gidaspow 1994;
    Weaver & Miskovic, Fluids 8, 215 (2023), eqs. 18-21), f = K (u_f - v) with
        alpha <= 0.8:  K = V [150 (1-alpha) mu / (alpha d^2) + 1.75 rho |u_r| / d]
        alpha >  0.8:  K = V 0.75 Cd rho alpha |u_r| / d  alpha^-2.65,
                       Cd = 24/Re (1 + 0.15 Re^0.687) (Re < 1000), 0.44 above,
                       Re = alpha |u_r| d / nu
    Range: the dilute branch carries Schiller & Naumann's Cd, fitted for
    Re < 800 (Clift, Grace & Weber 1978, Table 5.1); above it the law warns once
    per run. V is the solid volume of the grain; d the real particle diameter
    (d_grain / coarse-graining factor, eqs. 19 and 21).
    In Model A's fluid equation (alpha grad p) the dense branch gives exactly
    Ergun's pressure drop for a fixed bed.
\*---------------------------------------------------------------------------*/
#include "forceModel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{

class GidaspowDrag : public forceModel
{
public:
    TypeName("GidaspowDrag");
    GidaspowDrag(const word& name, const dictionary& props) : forceModel(name, props) {}
    bool isDrag() const override { return true; }

    void force(const particleFluidState& s, const fluidProperties& fl, scalarField& K, vectorField&) const override
    {
        for (label i = 0; i < s.n; ++i)
        {
            const scalar d = s.d[i], a = s.alphaf[i];
            const scalar ur = mag(s.Uf[i] - s.v[i]);
            if (a <= 0.8)
            {
                K[i] = s.volume[i]*(150*(1 - a)*fl.nu*fl.rho/(a*d*d) + 1.75*fl.rho*ur/d);
            }
            else
            {
                const scalar Re = max(a*ur*d/fl.nu, SMALL);
                if (Re > 800)
                {
                    warnOutOfRange("Re", "particle Reynolds number alpha |u_r| d/nu (Wen-Yu branch)", Re,
                        "Re < 800 of its Schiller-Naumann Cd (Clift, Grace & Weber 1978, Table 5.1)");
                }
                // Cd*Re stays finite as Re -> 0: write Cd |u_r| = Cd Re nu/(alpha d)
                const scalar CdRe = Re < 1000 ? 24*(1 + 0.15*pow(Re, 0.687)) : 0.44*Re;
                K[i] = s.volume[i]*0.75*CdRe*fl.nu/(a*d)*fl.rho*a/d*pow(a, -2.65);
            }
        }
    }
};

defineTypeNameAndDebug(GidaspowDrag, 0);
addToRunTimeSelectionTable(forceModel, GidaspowDrag, dictionary);

} // End namespace Foam
