/*---------------------------------------------------------------------------*\
    noAliasFvc: see noAliasFvc.H for why each operand is a named field.
\*---------------------------------------------------------------------------*/
#include "noAliasFvc.H"
#include "fvcGrad.H"
#include "fvcSurfaceIntegrate.H"
#include "extrapolatedCalculatedFvPatchFields.H"
#include "MeshObject.H"

namespace Foam
{
namespace noAliasFvc
{

// The geometric half of reconstruct, the faces' unit normals n_f and (sum_f n_f S_f)^-1 per cell:
// it depends on the mesh only, so it is made once and kept with the mesh (a GeometricMeshObject:
// dropped when the mesh moves or changes). The solver reconstructs twice per CFD step; rebuilding
// these each time (face loops, outer products, a sum, an inverse) was most of reconstruct's cost.
class reconstructInverse
:
    public MeshObject<fvMesh, GeometricMeshObject, reconstructInverse>
{
    const surfaceVectorField SfHat_;
    const volTensorField invNSf_;

    static tmp<volTensorField> make(const surfaceVectorField& SfHat)
    {
        const volTensorField nSf(fvc::surfaceSum(SfHat*SfHat.mesh().Sf()));
        return inv(nSf);
    }

public:

    TypeName("noAliasFvcReconstructInverse");

    explicit reconstructInverse(const fvMesh& mesh)
    :
        MeshObject<fvMesh, GeometricMeshObject, reconstructInverse>(mesh),
        SfHat_(mesh.Sf()/mesh.magSf()),
        invNSf_
        (
            IOobject
            (
                "noAliasFvcReconstructInverse", mesh.time().timeName(), mesh,
                IOobject::NO_READ, IOobject::NO_WRITE, false
            ),
            make(SfHat_)
        )
    {}

    const surfaceVectorField& SfHat() const { return SfHat_; }
    const volTensorField& invNSf() const { return invNSf_; }
};

defineTypeNameAndDebug(reconstructInverse, 0);

} // End namespace noAliasFvc
} // End namespace Foam


Foam::tmp<Foam::volVectorField> Foam::noAliasFvc::reconstruct(const surfaceScalarField& ssf)
{
    const fvMesh& mesh = ssf.mesh();
    const reconstructInverse& geometry = reconstructInverse::New(mesh);
    const volTensorField& invNSf = geometry.invNSf();
    const volVectorField nPhi(fvc::surfaceSum(geometry.SfHat()*ssf));

    tmp<volVectorField> tU
    (
        new volVectorField
        (
            IOobject("volIntegrate(" + ssf.name() + ')', ssf.instance(), mesh),
            invNSf & nPhi,
            extrapolatedCalculatedFvPatchField<vector>::typeName
        )
    );
    tU.ref().correctBoundaryConditions();
    return tU;
}

Foam::tmp<Foam::volTensorField> Foam::noAliasFvc::dev2GradUT(const volVectorField& U)
{
    // held as the tmp: with grad(U) cached (fvSolution cache) it refers to the stored field, not a copy
    const tmp<volTensorField> tgradU(fvc::grad(U));
    const volTensorField& gradU = tgradU();
    const volTensorField gradUT(T(gradU));
    return dev2(gradUT);
}

Foam::tmp<Foam::volVectorField> Foam::noAliasFvc::curl(const volVectorField& U)
{
    const tmp<volTensorField> tgradU(fvc::grad(U));
    const volTensorField& gradU = tgradU();
    const volTensorField skewGradU(skew(gradU));
    tmp<volVectorField> tcurl(2.0*(*skewGradU));
    tcurl.ref().rename("curl(" + U.name() + ')');
    return tcurl;
}
