/*---------------------------------------------------------------------------*\
    couplingBalances: see couplingBalances.H.
\*---------------------------------------------------------------------------*/
#include "couplingBalances.H"

namespace Foam
{

void couplingBalances::reportWeight(Ostream& os)
{
    const scalar buoyant = returnReduce(weightBuoyant, sumOp<scalar>());
    if (buoyant > 0)
    {
        // averaged over the couplings since the last report; in a fluidized bed the fluid carries
        // the whole buoyant weight (the pressure drop equals it), and what it does not carry rests
        // on the walls through the contacts (or accelerates the particles)
        const scalar share = returnReduce(weightCarried, sumOp<scalar>())/buoyant;
        os  << "Weight: the fluid carries " << 100*share << " % of the particles' buoyant weight (mean of "
            << nWeightSamples << " couplings since the last report)";
        if (share < 0.97)
        {
            os  << "; " << 100*(1 - share) << " % rests on walls through the contacts (a packed or"
                << " jammed bed, particles on a distributor) or accelerates the particles";
        }
        os  << endl;
    }
    weightBuoyant = weightCarried = 0;
    nWeightSamples = 0;
}

} // End namespace Foam
