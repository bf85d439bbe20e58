/*---------------------------------------------------------------------------*\
    sizeAwareDiffusion: the particles grouped in size classes (diameters within
    a factor classRatio), each class's alpha_p diffused with its own bandwidth
    bandwidthOverD x its diameter, then summed (src/core/diffusion_by_size.c).
    sizeAwareDiffusionProps: bandwidthOverD (required), classRatio (1.1),
    nSteps, tolerance. Its operator differs per class, so no other field is
    smoothed like alpha_p.
\*---------------------------------------------------------------------------*/
#include "smoothingModel.H"
#include "addToRunTimeSelectionTable.H"
#include "propsKeys.H"

namespace Foam
{

class sizeAwareDiffusionSmoothing : public smoothingModel
{
    cdc_diffusion_params diffusion_ = {};
    scalar bandwidthOverD_ = 0;
    scalar classRatio_ = 0;

public:
    TypeName("sizeAwareDiffusion");

    sizeAwareDiffusionSmoothing(const dictionary& couplingDict, const coarseDemMesh& mesh)
    :
        smoothingModel(mesh)
    {
        const dictionary& d = couplingDict.subDict("sizeAwareDiffusionProps");
        checkPropsKeys(d, {"bandwidthOverD", "classRatio", "nSteps", "tolerance"});
        bandwidthOverD_ = d.get<scalar>("bandwidthOverD");
        classRatio_ = d.lookupOrDefault<scalar>("classRatio", 1.1);
        diffusion_.n_steps = d.lookupOrDefault<label>("nSteps", 4);
        diffusion_.tolerance = readTolerance(couplingDict, d, "sizeAwareDiffusionProps");
        if (!(bandwidthOverD_ > 0) || !(classRatio_ > 1))
        {
            FatalIOErrorInFunction(couplingDict)
                << "entries bandwidthOverD " << bandwidthOverD_ << " and classRatio " << classRatio_
                << " in " << couplingDict.name() << "/sizeAwareDiffusionProps are invalid: need > 0 and > 1"
                << exit(FatalIOError);
        }
    }

    void alphaP(const cdc_kernels* k, const std::vector<double>& volumes, const std::vector<double>& radii,
                double* a) const override
    {
        int nClasses = 0;
        // the classes need every particle that has a kernel here: local ones and ghosts
        cdc_particles all = {int32_t(volumes.size()), nullptr, radii.data(), nullptr, nullptr};
        mesh_.check
        (
            cdc_alpha_p_diffused_by_size(mesh_.context(), k, &all, bandwidthOverD_, classRatio_, &diffusion_, a, &nClasses),
            "size-aware diffusion smoothing"
        );
    }

    bool canSmoothLikeAlpha() const override { return false; }
};

defineTypeNameAndDebug(sizeAwareDiffusionSmoothing, 0);
addToRunTimeSelectionTable(smoothingModel, sizeAwareDiffusionSmoothing, dictionary);

} // End namespace Foam
