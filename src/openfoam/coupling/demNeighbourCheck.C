#include "demNeighbourCheck.H"
#include "error.H"
#include "messageStream.H"

#include "lammps.h"
#include "neighbor.h"

namespace Foam
{

void checkDemNeighbours(LAMMPS_NS::LAMMPS* lmp, const dictionary& dict, const demTimestepEstimate& e)
{
    const LAMMPS_NS::Neighbor* neigh = lmp->neighbor;
    const fileName script = dict.lookupOrDefault<fileName>("demScript", "");
    static const char* styles[] = {"nsq", "bin", "multi"};
    const int style = neigh->style;
    const char* styleName = (style >= 0 && style <= 2) ? styles[style] : "unknown";
    if (style == 2)
    {
        FatalErrorInFunction
            << "the DEM script " << script << " sets 'neighbor ... multi': LIGGGHTS 3.8.0 builds"
            << " no granular contacts with it (its granular multi list is an empty function,"
            << " neigh_dummy.h), so the particles would pass through each other" << nl
            << "    use 'neighbor <skin> bin'" << exit(FatalError);
    }
    // the particle radii: the time-step check's extremes (none when it could not measure)
    if (!e.valid || e.rMin <= 0)
    {
        return;
    }
    const scalar dMin = 2*e.rMin, dMax = 2*e.rMax, skin = neigh->skin;
    Info<< "DEM neighbour lists: " << styleName << ", skin " << skin << " m (" << skin/dMin
        << " of the smallest diameter " << dMin << " m), size ratio " << dMax/dMin << endl;
    if (5*skin < dMin*(1 - 1e-9))   // below d_min/5 (d_min/5 itself, as ErgunTest has, is not warned)
    {
        WarningInFunction
            << "the DEM script " << script << " sets a neighbour skin of " << skin << " m, "
            << skin/dMin << " of the smallest diameter " << dMin << " m: the lists are rebuilt"
            << " every few steps (measured in the binary bed, bench/cases/README.md: a skin of"
            << " d_min/6 cost 1.28 times the DEM time of d_min/3). A skin of d_min/3 to d_min/2"
            << " is usually cheaper" << endl;
    }
    if (style == 1 && dMax > 2*dMin)
    {
        Info<< "    the bins and their stencil are sized by the largest particles (size ratio "
            << dMax/dMin << " > 2): the small ones scan more candidates; LIGGGHTS 3.8.0 has no"
            << " working 'multi' lists, and smaller bins cost more in the binary bed"
            << " (bench/cases/README.md)" << endl;
    }
}

} // End namespace Foam
