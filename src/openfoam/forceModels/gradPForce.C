/*---------------------------------------------------------------------------*\
    gradPForce: pressure-gradient force f = -V rho grad(p) (p kinematic),
    Weaver & Miskovic (2023) eq. 11. With p including the hydrostatic part it
    carries the buoyancy: do not combine with Archimedes.
\*---------------------------------------------------------------------------*/
#include "forceModel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{

class gradPForce : public forceModel
{
public:
    TypeName("gradPForce");
    gradPForce(const word& name, const dictionary& props) : forceModel(name, props) {}
    int needs() const override { return needGradP; }
    bool reactsOnFluid(bool modelB) const override { return modelB; }
    bool carriesPressureGradient() const override { return true; }
    bool carriesBuoyancy() const override { return true; }   // p holds the hydrostatic part

    void force(const particleFluidState& s, const fluidProperties& fl, scalarField&, vectorField& f) const override
    {
        for (label i = 0; i < s.n; ++i) f[i] -= s.volume[i]*fl.rho*s.gradP[i];
    }
};

defineTypeNameAndDebug(gradPForce, 0);
addToRunTimeSelectionTable(forceModel, gradPForce, dictionary);

} // End namespace Foam
