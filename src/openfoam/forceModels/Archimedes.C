/*---------------------------------------------------------------------------*\
    Archimedes: buoyancy f = -rho V g (Weaver & Miskovic 2023, eq. 14), for
    modelType B without gradPForce (CFDEM's modelType B): the drag, divided by
    the fluid fraction there, carries the dynamic part of the pressure gradient.
    With gradPForce (which holds the buoyancy) it is refused.
\*---------------------------------------------------------------------------*/
#include "forceModel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{

class Archimedes : public forceModel
{
public:
    TypeName("Archimedes");
    Archimedes(const word& name, const dictionary& props) : forceModel(name, props) {}
    bool reactsOnFluid(bool modelB) const override { return modelB; }
    bool carriesBuoyancy() const override { return true; }

    void force(const particleFluidState& s, const fluidProperties& fl, scalarField&, vectorField& f) const override
    {
        for (label i = 0; i < s.n; ++i) f[i] -= fl.rho*s.volume[i]*fl.g;
    }
};

defineTypeNameAndDebug(Archimedes, 0);
addToRunTimeSelectionTable(forceModel, Archimedes, dictionary);

} // End namespace Foam
