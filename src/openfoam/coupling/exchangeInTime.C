#include "exchangeInTime.H"

void Foam::exchangeInTime::compare(const vector& particleImpulse, const vector& fluidSource, scalar forceScale)
{
    const vector particles = particleImpulse - segmentSeconds_*nonReacting_;
    const vector fluid = cfdDt_*fluidSource;
    // relative to the larger of the step's exchange at the coupling (CFD step x sum |f|) and either
    // phase's impulse: at a start from rest the forces at the coupling are near zero while the fluid's
    // implicit drag at its new velocity is not, and the difference is then the whole impulse (1)
    const scalar exchanged = cfdDt_*forceScale;
    const scalar scale = max(exchanged, max(mag(particles), mag(fluid)));
    lastRel_ = scale > 0 ? mag(particles + fluid)/scale : 0;
    maxRel_ = max(maxRel_, lastRel_);
    net_ += particles + fluid;
    gross_ += exchanged;
    ++nCompared_;
}

void Foam::exchangeInTime::report(Ostream& os) const
{
    os  << "Exchange in time: " << nCompared_ << " couplings compared";
    if (nSkipped_ > 0) os << " (" << nSkipped_ << " with particles entering or leaving not)";
    os  << ", |particles' + fluid's"
        << " impulse| of a coupling step last " << lastRel_ << " max " << maxRel_
        << " x exchange; since the start net " << net_ << " N s of " << gross_
        << " N s" << endl;
}
