/*---------------------------------------------------------------------------*\
    SchillerNaumannDrag: single-sphere drag, no voidage correction
    (Schiller & Naumann 1933): f = pi/8 Cd rho d^2 |u_r| u_r with
    Cd = 24/Re (1 + 0.15 Re^0.687) for Re < 1000 and 0.44 above, Re = |u_r| d/nu.
    Range: Re < 800, where it stays within +5/-4 % of the standard drag curve
    (Clift, Grace & Weber 1978, Table 5.1; tutorials/settlingTest/README.md has
    it against their Table 5.2 curve: -6.6 % in Cd at Re = 1000). Above 800 the
    law warns once per run.
\*---------------------------------------------------------------------------*/
#include "forceModel.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{

class SchillerNaumannDrag : public forceModel
{
public:
    TypeName("SchillerNaumannDrag");
    SchillerNaumannDrag(const word& name, const dictionary& props) : forceModel(name, props) {}
    bool isDrag() const override { return true; }

    void force(const particleFluidState& s, const fluidProperties& fl, scalarField& K, vectorField&) const override
    {
        const scalar pi = constant::mathematical::pi;
        for (label i = 0; i < s.n; ++i)
        {
            const scalar d = s.d[i];
            const scalar Re = max(mag(s.Uf[i] - s.v[i])*d/fl.nu, SMALL);
            if (Re > 800)
            {
                warnOutOfRange("Re", "particle Reynolds number |u_r| d/nu", Re,
                    "Re < 800 (Schiller & Naumann 1933; Clift, Grace & Weber 1978, Table 5.1)");
            }
            const scalar CdRe = Re < 1000 ? 24*(1 + 0.15*pow(Re, 0.687)) : 0.44*Re;
            // pi/8 Cd rho d^2 |u_r| = pi/8 (Cd Re) rho d nu
            const scalar nReal = s.volume[i]/(pi/6*d*d*d);
            K[i] = nReal*pi/8*CdRe*fl.rho*d*fl.nu;
        }
    }
};

defineTypeNameAndDebug(SchillerNaumannDrag, 0);
addToRunTimeSelectionTable(forceModel, SchillerNaumannDrag, dictionary);

} // End namespace Foam
