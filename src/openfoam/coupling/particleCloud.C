/*---------------------------------------------------------------------------*\
    writeParticleCloud: see particleCloud.H.
\*---------------------------------------------------------------------------*/
#include "particleCloud.H"
#include "passiveParticleCloud.H"
#include "IOField.H"

namespace Foam
{

void writeParticleCloud
(
    const fvMesh& mesh, const word& name, const demParticles& p, const int32_t* hosts,
    const scalarField& d, const vectorField& f
)
{
    const label n = p.size();
    passiveParticleCloud cloud(mesh, name, IDLList<passiveParticle>());
    for (label i = 0; i < n; ++i)
    {
        // the host cell is known: the particle is placed in it, not searched for
        const point x(p.x[3*i], p.x[3*i + 1], p.x[3*i + 2]);
        cloud.addParticle(new passiveParticle(mesh, x, label(hosts[i])));
    }
    IOField<scalar> dField(cloud.fieldIOobject("d", IOobject::NO_READ), d);
    IOField<vector> UField(cloud.fieldIOobject("U", IOobject::NO_READ), n);
    IOField<vector> fField(cloud.fieldIOobject("f", IOobject::NO_READ), f);
    IOField<label> idField(cloud.fieldIOobject("id", IOobject::NO_READ), n);
    for (label i = 0; i < n; ++i)
    {
        UField[i] = vector(p.v[3*i], p.v[3*i + 1], p.v[3*i + 2]);
        idField[i] = label(p.id[i]);
    }
    cloud.write();
    dField.write();
    UField.write();
    fField.write();
    idField.write();
}

} // End namespace Foam
