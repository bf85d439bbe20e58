/*---------------------------------------------------------------------------*\
    liftForce: the shear lift of Saffman (1965; 1968 corrigendum) with the
    correction of Mei (1992) for finite particle Reynolds numbers:

        F = 1.615 d^2 (rho mu)^1/2 |omega|^-1/2 C(Re_p, beta) (u_r x omega)

        u_r = u_f - v,  omega = curl(u_f),
        Re_p = |u_r| d/nu,  Re_s = |omega| d^2/nu,  beta = Re_s/(2 Re_p)
        C = (1 - 0.3314 beta^1/2) exp(-Re_p/10) + 0.3314 beta^1/2   Re_p <= 40
        C = 0.0524 (beta Re_p)^1/2                                  Re_p >  40

    C = 1 is Saffman's creeping-flow lift (Re_p -> 0 with Re_s^1/2 >> Re_p);
    the force points to the side where the fluid overtakes the particle
    faster. Mei fitted C to Dandy & Dwyer's (1990) computations for
    0.005 <= beta <= 0.4 and 0.1 <= Re_p <= 100: outside that a warning names
    the range once (per run and rank) and the formula is applied as written.
    The force on a coarse-grained parcel is that of one real particle times
    the number of real particles it carries.

    Zhang et al. (2023, eq. A9) use the Kurose & Komori (1999) lift
    coefficient; its fitted coefficients are not available to this project
    (doc/couplingProperties.md), so Saffman-Mei, the usual choice of CFD-DEM
    codes for spheres in shear, is the lift here.
\*---------------------------------------------------------------------------*/
#include "forceModel.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{

//- Mei's (1992) ratio of the lift to Saffman's at particle Reynolds number Rep and beta = Res/(2 Rep)
inline scalar meiLiftRatio(scalar Rep, scalar beta)
{
    const scalar sb = 0.3314*std::sqrt(beta);
    return Rep <= 40 ? (1 - sb)*std::exp(-Rep/10) + sb : 0.0524*std::sqrt(beta*Rep);
}

class liftForce : public forceModel
{
public:
    TypeName("liftForce");
    liftForce(const word& name, const dictionary& props)
    :
        forceModel(name, props)
    {}
    int needs() const override { return needVorticity; }

    void force(const particleFluidState& s, const fluidProperties& fl, scalarField&, vectorField& f) const override
    {
        const scalar pi = constant::mathematical::pi;
        const scalar mu = fl.rho*fl.nu;
        for (label i = 0; i < s.n; ++i)
        {
            const vector ur = s.Uf[i] - s.v[i];
            const scalar w = mag(s.vorticity[i]);
            const scalar urMag = mag(ur);
            if (w < VSMALL || urMag < VSMALL) continue;
            const scalar d = s.d[i];
            const scalar Rep = urMag*d/fl.nu;
            const scalar beta = 0.5*w*d*d/fl.nu/Rep;
            if (Rep < 0.1 || Rep > 100)
            {
                warnOutOfRange("Rep", "particle Reynolds number |u_r| d/nu", Rep, "0.1 <= Re_p <= 100 (Mei 1992)");
            }
            if (beta < 0.005 || beta > 0.4)
            {
                warnOutOfRange("beta", "shear parameter beta = Re_s/(2 Re_p)", beta, "0.005 <= beta <= 0.4 (Mei 1992)");
            }
            const scalar nReal = s.volume[i]/(pi/6*pow3(d));
            f[i] += nReal*1.615*d*d*std::sqrt(fl.rho*mu/w)*meiLiftRatio(Rep, beta)*(ur ^ s.vorticity[i]);
        }
    }
};

defineTypeNameAndDebug(liftForce, 0);
addToRunTimeSelectionTable(forceModel, liftForce, dictionary);

} // End namespace Foam
