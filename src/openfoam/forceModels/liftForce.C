/*---------------------------------------------------------------------------*\
    liftForce: shear lift f = pi d^2/4 rho CL |u_r| (u_r x omega/|omega|),
    omega = curl(U) (Zhang et al. 2023, eq. A9). The lift coefficient is a
    constant here (liftForceProps { CL 0.5; }); the Kurose & Komori (1999)
    correlation the paper uses is not implemented yet.
\*---------------------------------------------------------------------------*/
#include "forceModel.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{

class liftForce : public forceModel
{
    scalar CL_;

public:
    TypeName("liftForce");
    liftForce(const word& name, const dictionary& props)
    :
        forceModel(name, props),
        CL_(props.lookupOrDefault<scalar>("CL", 0.5))
    {}
    int needs() const override { return needVorticity; }
    wordList propsKeys() const override { return {"CL"}; }

    void addForce(const particleFluidState& s, const fluidProperties& fl, vectorField& f) const override
    {
        const scalar pi = constant::mathematical::pi;
        for (label i = 0; i < s.n; ++i)
        {
            const vector ur = s.Uf[i] - s.v[i];
            const scalar w = mag(s.vorticity[i]);
            if (w < VSMALL) continue;
            const scalar nReal = s.volume[i]/(pi/6*pow3(s.d[i]));
            f[i] += nReal*pi/4*sqr(s.d[i])*fl.rho*CL_*mag(ur)*(ur ^ (s.vorticity[i]/w));
        }
    }
};

defineTypeNameAndDebug(liftForce, 0);
addToRunTimeSelectionTable(forceModel, liftForce, dictionary);

} // End namespace Foam
