#include "faceCrossings.H"
#include "PstreamReduceOps.H"

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
    forAll(Uf, i)
    {
        track& t = tracks_[id[i]];   // a new particle: no host yet
        const int32_t host = hosts[i];
        if (t.host >= 0 && host >= 0 && host != t.host)
        {
            ++nCrossings_;
            // back to the cell it left at the coupling before: across the same face and back
            if (host == t.previousHost) { ++nReversals_; ++t.reversals; }
            const scalar slip = mag(t.slip);
            if (slip > VSMALL)
            {
                const scalar jump = mag(Uf[i] - t.Uf)/slip;
                if (jump > jumpFraction) ++nJumps_;
                if (jump > largestJump_)
                {
                    largestJump_ = jump;
                    largestJumpId_ = id[i];
                    largestJumpTime_ = time;
                }
            }
        }
        // a coupling in the same cell ends a back-and-forth run
        t.previousHost = host != t.host ? t.host : -1;
        t.host = host;
        t.Uf = Uf[i];
        t.slip = Uf[i] - v[i];
        ++t.couplings;
        t.lastUpdate = nUpdates_;
    }
}

void faceCrossings::limiter(scalar moved, scalar solid)
{
    if (solid <= 0) return;
    ++nLimited_;
    limitedShare_ += moved/solid;
    if (moved > 0.5*solid) ++nLimitedMost_;
}

void faceCrossings::report(Ostream& os, const word& method, scalar time)
{
    // this interval's particles held at a face; the one held longest (share of its couplings)
    label nHeld = 0;
    scalar held[3] = {-GREAT, 0, 0};   // share, id, couplings
    for (const auto& entry : tracks_)
    {
        const long long pid = entry.first;
        const track& t = entry.second;
        if (t.couplings < heldMinCouplings || t.reversals <= heldShare*t.couplings) continue;
        ++nHeld;
        heldIds_.insert(pid);
        const scalar share = scalar(t.reversals)/t.couplings;
        if (share > held[0]) { held[0] = share; held[1] = scalar(pid); held[2] = scalar(t.couplings); }
    }
    nHeld = returnReduce(nHeld, sumOp<label>());
    if (nHeld > 0)
    {
        const scalar best = returnReduce(held[0], maxOp<scalar>());
        const bool mine = held[0] == best;
        heldLast_ = {best, returnReduce(mine ? held[1] : -GREAT, maxOp<scalar>()),
                     returnReduce(mine ? held[2] : -GREAT, maxOp<scalar>()), intervalStart_, time};
    }
    const label nCrossings = returnReduce(nCrossings_, sumOp<label>());
    const label nReversals = returnReduce(nReversals_, sumOp<label>());
    const label nJumps = returnReduce(nJumps_, sumOp<label>());
    const scalar largest = returnReduce(largestJump_, maxOp<scalar>());
    const bool mine = largest > 0 && largestJump_ == largest;
    const scalar largestId = returnReduce(mine ? scalar(largestJumpId_) : scalar(-1), maxOp<scalar>());
    const scalar largestTime = returnReduce(mine ? largestJumpTime_ : -GREAT, maxOp<scalar>());
    const label runHeld = returnReduce(label(heldIds_.size()), sumOp<label>());
    runLimited_ += nLimited_;
    runLimitedMost_ += nLimitedMost_;

    const auto pct = [](label n, label of) { return of > 0 ? 100.0*n/of : 0.0; };
    const auto id = [](scalar x) { return std::to_string(std::llround(x)); };
    os  << "Face crossings since t = " << intervalStart_ << ": " << nCrossings << ", back and forth across the"
        << " same face " << nReversals << " (" << pct(nReversals, nCrossings) << " %), the sampled fluid"
        << " velocity jumping by more than " << jumpFraction << " of the slip " << nJumps << " ("
        << pct(nJumps, nCrossings) << " %)";
    if (largest > 0)
    {
        os  << ", the largest " << largest << " of the slip (particle " << id(largestId).c_str()
            << " at t = " << largestTime << ")";
    }
    os  << "; limiter moved " << (nLimited_ > 0 ? limitedShare_/nLimited_ : 0) << " of the solid volume"
        << " per coupling; since the start: " << runHeld << " particle(s) held at a face, the limiter"
        << " moving over half the solid in " << runLimitedMost_ << " of " << runLimited_ << " couplings" << endl;

    // said at every report from the first time on, so that a run's last lines say it
    if (runHeld > 0)
    {
        os  << "Warning: particles held at a cell face: particle " << id(heldLast_[1]).c_str()
            << " crossed the same face back and forth in " << 100*heldLast_[0] << " % of its "
            << label(heldLast_[2]) << " couplings from t = " << heldLast_[3] << " to " << heldLast_[4]
            << ". A particle larger than its cells samples its own wake with " << method
            << " alone: set backgroundFields on (doc/couplingProperties.md)" << endl;
    }
    if (runLimited_ > 0 && runLimitedMost_ > runLimited_/2)
    {
        os  << "Warning: the packing limiter moved more than half of the solid volume in " << runLimitedMost_
            << " of " << runLimited_ << " couplings since the start: the " << method << " kernel is narrower"
            << " than the particles (a kernel that spreads them, e.g. bigParticle, or background fields;"
            << " doc/methods.md)" << endl;
    }

    // a new interval
    nCrossings_ = nReversals_ = nJumps_ = 0;
    largestJump_ = 0;
    largestJumpId_ = -1;
    largestJumpTime_ = 0;
    nLimited_ = nLimitedMost_ = 0;
    limitedShare_ = 0;
    // particles that left this rank or the DEM are forgotten
    for (auto it = tracks_.begin(); it != tracks_.end(); )
    {
        if (it->second.lastUpdate != nUpdates_) { it = tracks_.erase(it); continue; }
        it->second.couplings = it->second.reversals = 0;
        ++it;
    }
    intervalStart_ = time;
}

} // End namespace Foam
