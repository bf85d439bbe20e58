/*---------------------------------------------------------------------------*\
    virtualMassForce: added mass f = Cvm rho V (DU/Dt - dv/dt), Cvm = 0.5 by
    default (Zhang et al. 2023, eq. A8; the sign printed there is that of the
    force on the fluid). DU/Dt is the fluid's material derivative at the
    particle; dv/dt the particle's acceleration over the last coupling
    interval. Explicit: for light particles (rho_p/rho_f < ~0.5) it can be
    unstable.
        virtualMassForceProps { Cvm 0.5; }
\*---------------------------------------------------------------------------*/
#include "forceModel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{

class virtualMassForce : public forceModel
{
    scalar Cvm_;

public:
    TypeName("virtualMassForce");
    virtualMassForce(const word& name, const dictionary& props)
    :
        forceModel(name, props),
        Cvm_(props.lookupOrDefault<scalar>("Cvm", 0.5))
    {}
    int needs() const override { return needDUfDt | needDvDt; }
    wordList propsKeys() const override { return {"Cvm"}; }

    void force(const particleFluidState& s, const fluidProperties& fl, scalarField&, vectorField& f) const override
    {
        for (label i = 0; i < s.n; ++i) f[i] += Cvm_*fl.rho*s.volume[i]*(s.DUfDt[i] - s.dvdt[i]);
    }
};

defineTypeNameAndDebug(virtualMassForce, 0);
addToRunTimeSelectionTable(forceModel, virtualMassForce, dictionary);

} // End namespace Foam
