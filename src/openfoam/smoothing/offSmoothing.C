/*---------------------------------------------------------------------------*\
    off: alpha_p as the kernels spread the particles' volumes, unsmoothed.
\*---------------------------------------------------------------------------*/
#include "smoothingModel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{

class offSmoothing : public smoothingModel
{
public:
    TypeName("off");
    offSmoothing(const dictionary&, const coarseDemMesh& mesh) : smoothingModel(mesh) {}

    void alphaP(const cdc_kernels* k, const std::vector<double>& volumes, const std::vector<double>&,
                double* a) const override
    {
        mesh_.check(cdc_spread(k, volumes.data(), 1, a), "alpha_p");
    }
};

defineTypeNameAndDebug(offSmoothing, 0);
addToRunTimeSelectionTable(smoothingModel, offSmoothing, dictionary);

} // End namespace Foam
