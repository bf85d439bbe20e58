#include "faceCrossings.H"
#include "largestOnRanks.H"

#include <cmath>
#include <string>

namespace Foam
{

void faceCrossings::update
(
    const std::vector<long long>& id, const int32_t* hosts, const vectorField& Uf, const vector* v,
    scalar time
)
{
    if (intervalStart_ < 0) intervalStart_ = time;
    ++nUpdates_;
    ++nCouplings_;
    // the weight of the latest coupling in the back-and-forth share: an average over ~heldMinCouplings
    const scalar w = 1.0/heldMinCouplings;
    forAll(Uf, i)
    {
        track& t = tracks_[id[i]];
        // not seen at the last coupling (new, or back from another rank or from outside the DEM):
        // its last host and velocities are not this coupling's predecessors
        if (t.lastUpdate != nUpdates_ - 1) t = track();
        const int32_t host = hosts[i];
        bool reversal = false;
        if (t.host >= 0 && host >= 0 && host != t.host)
        {
            ++nCrossings_[0];
            // back to the cell it left at the coupling before: across the same face and back
            reversal = host == t.previousHost;
            if (reversal) ++nReversals_[0];
            const scalar slip = mag(t.slip);
            if (slip > VSMALL)
            {
                const scalar jump = mag(Uf[i] - t.Uf)/slip;
                if (jump > jumpFraction) ++nJumps_[0];
                if (jump > largestJump_[0])
                {
                    largestJump_[0] = jump;
                    largestJump_[1] = scalar(id[i]);
                    largestJump_[2] = time;
                }
            }
        }
        t.backAndForth += w*((reversal ? 1 : 0) - t.backAndForth);
        // a coupling in the same cell ends a back-and-forth run
        t.previousHost = host != t.host ? t.host : -1;
        t.host = host;
        t.Uf = Uf[i];
        t.slip = Uf[i] - v[i];
        ++t.couplings;
        t.lastUpdate = nUpdates_;
        if (t.couplings >= heldMinCouplings && t.backAndForth > heldShare)
        {
            heldIds_.insert(id[i]);
            if (t.backAndForth > held_[0])
            {
                held_[0] = t.backAndForth;
                held_[1] = scalar(id[i]);
                held_[2] = time;
            }
        }
    }
}

void faceCrossings::limiter(scalar moved, scalar solid)
{
    if (solid <= 0) return;
    ++nLimited_[0];
    limitedShare_ += moved/solid;
    if (moved > 0.5*solid) ++nLimitedMost_[0];
}

void faceCrossings::report(Ostream& os, const word& method, scalar time)
{
    reduce(nCrossings_[0], sumOp<label>());
    reduce(nReversals_[0], sumOp<label>());
    reduce(nJumps_[0], sumOp<label>());
    largestOnRanks(largestJump_);
    largestOnRanks(held_);
    if (held_[0] > heldShare) heldLast_ = {held_[0], held_[1], held_[2]};
    const label runHeld = returnReduce(label(heldIds_.size()), sumOp<label>());
    for (label* n : {nCrossings_, nReversals_, nJumps_, nLimited_, nLimitedMost_}) n[1] += n[0];

    const auto pct = [](label n, label of) { return of > 0 ? 100.0*n/of : 0.0; };
    const auto id = [](scalar x) { return std::to_string(std::llround(x)); };
    // an interval without couplings (the end, right after a write) has only the totals
    if (nCouplings_ > 0)
    {
        os  << "Face crossings since t = " << intervalStart_ << ": " << nCrossings_[0] << ", back and forth"
            << " across the same face " << nReversals_[0] << " (" << pct(nReversals_[0], nCrossings_[0])
            << " %), the sampled fluid velocity jumping by more than " << jumpFraction << " of the slip "
            << nJumps_[0] << " (" << pct(nJumps_[0], nCrossings_[0]) << " %)";
        if (largestJump_[0] > 0)
        {
            os  << ", the largest " << largestJump_[0] << " of the slip (particle " << id(largestJump_[1]).c_str()
                << " at t = " << largestJump_[2] << ")";
        }
        os  << "; limiter moved " << (nLimited_[0] > 0 ? limitedShare_/nLimited_[0] : 0)
            << " of the solid volume per coupling" << endl;
    }
    os  << "Face crossings since the start: " << nCrossings_[1] << ", back and forth " << nReversals_[1]
        << ", jumping " << nJumps_[1] << "; " << runHeld << " particle(s) held at a face; the limiter moving"
        << " over half the solid in " << nLimitedMost_[1] << " of " << nLimited_[1] << " couplings" << endl;

    // said at every report from the first time on, so that a run's last lines say it
    if (runHeld > 0)
    {
        os  << "Warning: particles held at a cell face: particle " << id(heldLast_[1]).c_str()
            << " went back across the same face at " << 100*heldLast_[0] << " % of its recent couplings"
            << " (t = " << heldLast_[2] << "). A particle larger than its cells samples its own wake with "
            << method << " alone: set backgroundFields on (doc/couplingProperties.md)" << endl;
    }
    if (nLimited_[1] > 0 && nLimitedMost_[1] > nLimited_[1]/2)
    {
        os  << "Warning: the packing limiter moved more than half of the solid volume in " << nLimitedMost_[1]
            << " of " << nLimited_[1] << " couplings since the start: the " << method << " kernel is narrower"
            << " than the particles (a kernel that spreads them, e.g. bigParticle, or background fields;"
            << " doc/methods.md)" << endl;
    }

    // a new interval; particles that left this rank or the DEM are forgotten
    nCouplings_ = 0;
    nCrossings_[0] = nReversals_[0] = nJumps_[0] = nLimited_[0] = nLimitedMost_[0] = 0;
    largestJump_[0] = 0;
    held_[0] = 0;
    limitedShare_ = 0;
    for (auto it = tracks_.begin(); it != tracks_.end(); )
    {
        it = it->second.lastUpdate == nUpdates_ ? std::next(it) : tracks_.erase(it);
    }
    intervalStart_ = time;
}

} // End namespace Foam
