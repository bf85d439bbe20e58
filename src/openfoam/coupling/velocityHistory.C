#include "velocityHistory.H"

namespace Foam
{

void velocityHistory::accelerations(const demParticles& particles, const vector* v, scalar dt, vectorField& dvdt)
{
    const label n = particles.size();
    Map<vector> current(2*n);
    for (label i = 0; i < n; ++i) current.set(label(particles.id[i]), v[i]);
    if (Pstream::parRun())
    {
        // A particle that changed rank since the last coupling left its velocity on the old rank:
        // every rank shares the velocities of its particles that are gone (few: those that crossed).
        List<labelList> goneIds(Pstream::nProcs());
        List<vectorField> goneVelocities(Pstream::nProcs());
        DynamicList<label> ids;
        DynamicList<vector> velocities;
        forAllConstIters(previous_, iter)
        {
            if (!current.found(iter.key()))
            {
                ids.append(iter.key());
                velocities.append(iter.val());
            }
        }
        goneIds[Pstream::myProcNo()] = ids;
        goneVelocities[Pstream::myProcNo()] = velocities;
        Pstream::gatherList(goneIds);
        Pstream::scatterList(goneIds);
        Pstream::gatherList(goneVelocities);
        Pstream::scatterList(goneVelocities);
        forAll(goneIds, proci)
        {
            if (proci == Pstream::myProcNo()) continue;
            forAll(goneIds[proci], k)
            {
                if (current.found(goneIds[proci][k])) previous_.set(goneIds[proci][k], goneVelocities[proci][k]);
            }
        }
    }
    dvdt.setSize(n);
    label nNew = 0;
    for (label i = 0; i < n; ++i)
    {
        const auto iter = previous_.cfind(label(particles.id[i]));
        dvdt[i] = iter.found() ? (v[i] - *iter)/dt : Zero;
        if (!iter.found()) ++nNew;
    }
    reduce(nNew, sumOp<label>());
    if (first_ < 0) first_ = nNew;
    else later_ += nNew;
    previous_.transfer(current);
}

void velocityHistory::report(Ostream& os) const
{
    // particles without a velocity of the last coupling (at the start or restart: all; later:
    // inserted ones) get dv/dt = 0 for that step
    os  << ", dv/dt unknown for " << first_ << " particles at the first coupling, " << later_ << " since";
}

} // End namespace Foam
