/*---------------------------------------------------------------------------*\
    DiFeliceDrag: Di Felice (1994) drag with the voidage function, as in
    Zhang et al., Phys. Fluids 35, 113330 (2023), eqs. A4-A7:
        f = pi/8 Cd rho d^2 alpha^(2-chi) |u_r| u_r,
        Cd = (0.63 + 4.8/sqrt(Re))^2,  chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2/2),
        Re = |u_r| d / nu                       (eq. A7 as printed)
    so K = pi/8 rho d^2 alpha^(2-chi) (0.63 sqrt|u_r| + 4.8 sqrt(nu/d))^2,
    finite as |u_r| -> 0. Coarse graining: the grain gets (its volume / the
    real particle's volume) times the force of one real particle.
\*---------------------------------------------------------------------------*/
#include "forceModel.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{

class DiFeliceDrag : public forceModel
{
public:
    TypeName("DiFeliceDrag");
    DiFeliceDrag(const word& name, const dictionary& props) : forceModel(name, props) {}
    bool isDrag() const override { return true; }

    void dragCoefficient(const particleFluidState& s, const fluidProperties& fl, scalarField& K) const override
    {
        const scalar pi = constant::mathematical::pi;
        for (label i = 0; i < s.n; ++i)
        {
            const scalar d = s.d[i];
            const scalar ur = mag(s.Uf[i] - s.v[i]);
            const scalar Re = max(ur*d/fl.nu, SMALL);
            const scalar chi = 3.7 - 0.65*exp(-sqr(1.5 - log10(Re))/2);
            const scalar nReal = s.volume[i]/(pi/6*d*d*d);
            K[i] = nReal*pi/8*fl.rho*d*d*pow(s.alphaf[i], 2 - chi)*sqr(0.63*sqrt(ur) + 4.8*sqrt(fl.nu/d));
        }
    }
};

defineTypeNameAndDebug(DiFeliceDrag, 0);
addToRunTimeSelectionTable(forceModel, DiFeliceDrag, dictionary);

} // End namespace Foam
