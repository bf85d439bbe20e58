/*---------------------------------------------------------------------------*\
    diffusion: alpha_p spread by the kernels, then diffused over a bandwidth b
    (Zhang et al. 2020, eq. 7; src/core/diffusion.c), diffusionProps:
    bandwidth (required; b = 6 d recommended), nSteps, tolerance, DRule,
    particleDiameter, smoothExchangeFields (default false, Zhang et al.'s
    method, which smooths alpha_p only): the fluid's momentum sources (drag,
    the other reacting forces, the implicit drag coefficient) smoothed with the
    same operator, as Sun & Xiao (2015, IJMF 72) smooth every exchange field,
    so a coarse particle's force is not concentrated in its host cell.
\*---------------------------------------------------------------------------*/
#include "smoothingModel.H"
#include "addToRunTimeSelectionTable.H"
#include "propsKeys.H"
#include "Switch.H"

namespace Foam
{

class diffusionSmoothing : public smoothingModel
{
    cdc_diffusion_params diffusion_ = {};
    bool smoothExchange_ = false;

public:
    TypeName("diffusion");

    diffusionSmoothing(const dictionary& couplingDict, const coarseDemMesh& mesh)
    :
        smoothingModel(mesh)
    {
        const dictionary& d = couplingDict.subDict("diffusionProps");
        checkPropsKeys(d, {"bandwidth", "nSteps", "tolerance", "DRule", "particleDiameter", "smoothExchangeFields"});
        diffusion_.bandwidth = d.get<scalar>("bandwidth");
        diffusion_.n_steps = d.lookupOrDefault<label>("nSteps", 4);
        diffusion_.tolerance = readTolerance(couplingDict, d, "diffusionProps");
        diffusion_.d_rule = d.lookupOrDefault<Switch>("DRule", false) ? 1 : 0;
        diffusion_.particle_diameter = d.lookupOrDefault<scalar>("particleDiameter", 0);
        smoothExchange_ = d.lookupOrDefault<Switch>("smoothExchangeFields", false);
        if (!(diffusion_.bandwidth > 0))
        {
            FatalIOErrorInFunction(couplingDict)
                << "entry bandwidth " << diffusion_.bandwidth << " in " << couplingDict.name()
                << "/diffusionProps is invalid: must be > 0 (metres; b = 6 d is recommended)"
                << exit(FatalIOError);
        }
    }

    void alphaP(const cdc_kernels* k, const std::vector<double>& volumes, const std::vector<double>&,
                double* a) const override
    {
        mesh_.check(cdc_spread(k, volumes.data(), 1, a), "alpha_p");
        mesh_.check(cdc_diffuse(mesh_.context(), &diffusion_, a), "diffusion smoothing");
    }

    void smoothLikeAlpha(double* field, int ncomp) const override
    {
        // the components together: the same values as one by one, in fewer passes over the mesh
        mesh_.check(cdc_diffuse_fields(mesh_.context(), &diffusion_, field, ncomp), "diffusion smoothing");
    }

    bool smoothsExchangeFields() const override { return smoothExchange_; }
};

defineTypeNameAndDebug(diffusionSmoothing, 0);
addToRunTimeSelectionTable(smoothingModel, diffusionSmoothing, dictionary);

} // End namespace Foam
