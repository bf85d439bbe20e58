/*---------------------------------------------------------------------------*\
    noAliasFvc: see noAliasFvc.H for why each operand is a named field.
\*---------------------------------------------------------------------------*/
#include "noAliasFvc.H"
#include "fvcGrad.H"
#include "fvcSurfaceIntegrate.H"
#include "extrapolatedCalculatedFvPatchFields.H"

Foam::tmp<Foam::volVectorField> Foam::noAliasFvc::reconstruct(const surfaceScalarField& ssf)
{
    const fvMesh& mesh = ssf.mesh();
    const surfaceVectorField SfHat(mesh.Sf()/mesh.magSf());
    const volTensorField nSf(fvc::surfaceSum(SfHat*mesh.Sf()));
    const volTensorField invNSf(inv(nSf));
    const volVectorField nPhi(fvc::surfaceSum(SfHat*ssf));

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
    const volTensorField gradU(fvc::grad(U));
    const volTensorField gradUT(T(gradU));
    return dev2(gradUT);
}

Foam::tmp<Foam::volVectorField> Foam::noAliasFvc::curl(const volVectorField& U)
{
    const volTensorField gradU(fvc::grad(U));
    const volTensorField skewGradU(skew(gradU));
    tmp<volVectorField> tcurl(2.0*(*skewGradU));
    tcurl.ref().rename("curl(" + U.name() + ')');
    return tcurl;
}
