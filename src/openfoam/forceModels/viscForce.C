/*---------------------------------------------------------------------------*\
    viscForce: viscous (stress divergence) force f = V rho div(tau),
    tau = nu_eff (grad U + grad U^T) (kinematic), Weaver & Miskovic (2023) eq. 13.
\*---------------------------------------------------------------------------*/
#include "forceModel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{

class viscForce : public forceModel
{
public:
    TypeName("viscForce");
    viscForce(const word& name, const dictionary& props) : forceModel(name, props) {}
    int needs() const override { return needDivTau; }
    bool reactsOnFluid(bool modelB) const override { return modelB; }

    void force(const particleFluidState& s, const fluidProperties& fl, scalarField&, vectorField& f) const override
    {
        for (label i = 0; i < s.n; ++i) f[i] += s.volume[i]*fl.rho*s.divTau[i];
    }
};

defineTypeNameAndDebug(viscForce, 0);
addToRunTimeSelectionTable(forceModel, viscForce, dictionary);

} // End namespace Foam
