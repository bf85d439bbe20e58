#include "demTimeStepCheck.H"
#include "error.H"
#include "messageStream.H"
#include "Switch.H"
#include "mathematicalConstants.H"

#include <mpi.h>
#include <cmath>
#include <vector>

#include "lammps.h"
#include "atom.h"
#include "update.h"
#include "modify.h"
#include "fix_property_global.h"

namespace Foam
{

// values of a peratomtype property/global fix (nullptr if there is none)
static const double* perTypeProperty(LAMMPS_NS::LAMMPS* lmp, const char* name)
{
    const int ntypes = lmp->atom->ntypes;
    LAMMPS_NS::Fix* f = lmp->modify->find_fix_property
    (
        name, "property/global", "peratomtype", ntypes, 0, "coarseDemFoam (DEM time-step check)", false
    );
    LAMMPS_NS::FixPropertyGlobal* p = dynamic_cast<LAMMPS_NS::FixPropertyGlobal*>(f);
    return p ? p->get_values() : nullptr;
}

// Stiffest effective modulus of each type against any type: E*_ij = 1/((1-nu_i^2)/E_i + (1-nu_j^2)/E_j)
static std::vector<double> stiffestModulus(int ntypes, const double* Y, const double* nu)
{
    std::vector<double> EstarMax(ntypes + 1, 0.0);
    for (int i = 1; i <= ntypes; ++i)
    {
        for (int j = 1; j <= ntypes; ++j)
        {
            const double Es =
                1.0/((1 - nu[i - 1]*nu[i - 1])/Y[i - 1] + (1 - nu[j - 1]*nu[j - 1])/Y[j - 1]);
            EstarMax[i] = std::max(EstarMax[i], Es);
        }
    }
    return EstarMax;
}

// The particles' radius, density and modulus extremes, the largest speed and the smallest Rayleigh
// time over every rank, into e.
static void particleExtremes(LAMMPS_NS::LAMMPS* lmp, const double* Y, const double* nu, demTimestepEstimate& e)
{
    const scalar pi = constant::mathematical::pi;
    const LAMMPS_NS::Atom* atom = lmp->atom;
    const double* r = atom->radius;
    const double* rmass = atom->rmass;
    const double* dens = atom->density_flag ? atom->density : nullptr;
    double** v = atom->v;
    // 0 rMin, 1 rhoMin, 2 EMin, 3 tR; max: rMax, rhoMax, EMax, vmax
    double mins[4] = {1e300, 1e300, 1e300, 1e300};
    double maxs[4] = {0, 0, 0, 0};
    for (int i = 0; i < atom->nlocal; ++i)
    {
        const double ri = r[i];
        const double vol = 4.0/3.0*pi*ri*ri*ri;
        const double rho = dens ? dens[i] : (rmass ? rmass[i]/vol : 0);
        const double E = Y[atom->type[i] - 1], nui = nu[atom->type[i] - 1];
        // Zhang et al. (2023) eq. 20 with d = 2 r
        const double tR = 0.5*pi*(2*ri)/(0.163*nui + 0.8766)*std::sqrt(2*rho*(1 + nui)/E);
        mins[0] = std::min(mins[0], ri);
        mins[1] = std::min(mins[1], rho);
        mins[2] = std::min(mins[2], E);
        mins[3] = std::min(mins[3], tR);
        maxs[0] = std::max(maxs[0], ri);
        maxs[1] = std::max(maxs[1], rho);
        maxs[2] = std::max(maxs[2], E);
        maxs[3] = std::max(maxs[3], std::sqrt(v[i][0]*v[i][0] + v[i][1]*v[i][1] + v[i][2]*v[i][2]));
    }
    double gmins[4], gmaxs[4];
    MPI_Allreduce(mins, gmins, 4, MPI_DOUBLE, MPI_MIN, lmp->world);
    MPI_Allreduce(maxs, gmaxs, 4, MPI_DOUBLE, MPI_MAX, lmp->world);
    e.rMin = gmins[0]; e.rhoMin = gmins[1]; e.EMin = gmins[2]; e.tRayleigh = gmins[3];
    e.rMax = gmaxs[0]; e.rhoMax = gmaxs[1]; e.EMax = gmaxs[2]; e.maxParticleSpeed = gmaxs[3];
}

// The smallest Hertz contact time over every rank: each particle against an identical partner
// (m* = m/2, R* = r/2) of the stiffest type, at the impact velocity vImp.
static double hertzTime(LAMMPS_NS::LAMMPS* lmp, const std::vector<double>& EstarMax, double vImp)
{
    const scalar pi = constant::mathematical::pi;
    const LAMMPS_NS::Atom* atom = lmp->atom;
    double tH = 1e300;
    for (int i = 0; i < atom->nlocal; ++i)
    {
        const double ri = atom->radius[i];
        const double vol = 4.0/3.0*pi*ri*ri*ri;
        const double m = atom->rmass ? atom->rmass[i] : (atom->density_flag ? atom->density[i]*vol : 0);
        const double mStar = 0.5*m, RStar = 0.5*ri, Es = EstarMax[atom->type[i]];
        tH = std::min(tH, 2.87*std::pow(mStar*mStar/(RStar*Es*Es*vImp), 0.2));
    }
    double global = 0;
    MPI_Allreduce(&tH, &global, 1, MPI_DOUBLE, MPI_MIN, lmp->world);
    return global;
}

demTimestepEstimate estimateDemTimestep(LAMMPS_NS::LAMMPS* lmp, scalar maxImpactVelocity)
{
    demTimestepEstimate e;
    e.dt = lmp->update->dt;
    const LAMMPS_NS::Atom* atom = lmp->atom;
    const double* Y = perTypeProperty(lmp, "youngsModulus");
    const double* nu = perTypeProperty(lmp, "poissonsRatio");

    long long nLocal = atom->nlocal, nAll = 0;
    MPI_Allreduce(&nLocal, &nAll, 1, MPI_LONG_LONG, MPI_SUM, lmp->world);
    e.nParticles = label(nAll);
    if (!Y || !nu)
    {
        e.reason = "the DEM script defines no fix property/global youngsModulus and poissonsRatio (peratomtype)";
        return e;
    }
    if (nAll == 0)
    {
        e.reason = "no particles in the DEM yet";
        return e;
    }
    if (!atom->radius)
    {
        e.reason = "the DEM atom style has no radius (atom_style granular/sphere is needed)";
        return e;
    }
    particleExtremes(lmp, Y, nu, e);
    e.impactVelocity = std::max(double(maxImpactVelocity), 2*e.maxParticleSpeed);
    e.tHertz = hertzTime(lmp, stiffestModulus(atom->ntypes, Y, nu), e.impactVelocity);
    if (!(e.rMin > 0) || !(e.rhoMin > 0))
    {
        e.reason = "a particle has a radius or density <= 0";
        return e;
    }
    e.valid = true;
    return e;
}

demTimestepEstimate checkDemTimestep(LAMMPS_NS::LAMMPS* lmp, const dictionary& dict)
{
    const scalar warnFraction = dict.lookupOrDefault<scalar>("demTimeStepWarnFraction", 0.1);
    const scalar maxFraction = dict.lookupOrDefault<scalar>("demTimeStepMaxFraction", 0.3);
    const Switch force = dict.lookupOrDefault<Switch>("demTimeStepForce", false);
    const scalar vImpact = dict.lookupOrDefault<scalar>("demMaxImpactVelocity", 1.0);

    if (!(warnFraction > 0) || !(maxFraction > 0) || warnFraction > maxFraction)
    {
        FatalIOErrorInFunction(dict)
            << "entries demTimeStepWarnFraction " << warnFraction << " and demTimeStepMaxFraction "
            << maxFraction << " in " << dict.name() << " are invalid: need 0 < warn fraction <= max"
            << " fraction (defaults 0.1 and 0.3)" << exit(FatalIOError);
    }
    if (!(vImpact > 0))
    {
        FatalIOErrorInFunction(dict)
            << "entry demMaxImpactVelocity " << vImpact << " in " << dict.name()
            << " is invalid: must be > 0 (m/s, the largest expected relative impact speed; default 1)"
            << exit(FatalIOError);
    }

    const demTimestepEstimate e = estimateDemTimestep(lmp, vImpact);
    if (!e.valid)
    {
        WarningInFunction
            << "DEM time step " << e.dt << " s not checked against the Rayleigh and Hertz times: "
            << e.reason << endl;
        return e;
    }

    const scalar fR = e.dt/e.tRayleigh, fH = e.dt/e.tHertz, f = e.fraction();
    Info<< "DEM time-step check: dt = " << e.dt << " s, Rayleigh time " << e.tRayleigh << " s (dt = "
        << 100*fR << " %), Hertz time " << e.tHertz << " s at impact speed " << e.impactVelocity
        << " m/s (dt = " << 100*fH << " %); " << e.nParticles << " particles, radius ["
        << e.rMin << ", " << e.rMax << "] m, density [" << e.rhoMin << ", " << e.rhoMax
        << "] kg/m3, Young's modulus [" << e.EMin << ", " << e.EMax << "] Pa; warn above "
        << 100*warnFraction << " %, stop above " << 100*maxFraction << " %" << endl;

    const word which = e.tRayleigh <= e.tHertz ? "Rayleigh" : "Hertz";
    if (f > maxFraction && !force)
    {
        FatalIOErrorInFunction(dict)
            << "the DEM time step " << e.dt << " s is " << 100*f << " % of the " << which << " time "
            << e.tCritical() << " s (Rayleigh " << e.tRayleigh << " s, Hertz " << e.tHertz
            << " s at " << e.impactVelocity << " m/s), above demTimeStepMaxFraction " << maxFraction
            << " in " << dict.name() << nl
            << "    reduce the DEM timestep (in the DEM script " << dict.lookupOrDefault<fileName>("demScript", "")
            << ") to at most " << warnFraction*e.tCritical() << " s (demTimeStepWarnFraction "
            << warnFraction << "), or set demTimeStepForce yes in " << dict.name()
            << " to run anyway" << exit(FatalIOError);
    }
    if (f > warnFraction)
    {
        WarningInFunction
            << "the DEM time step " << e.dt << " s is " << 100*f << " % of the " << which << " time "
            << e.tCritical() << " s, above demTimeStepWarnFraction " << warnFraction << " in "
            << dict.name() << (f > maxFraction ? " and demTimeStepMaxFraction (demTimeStepForce yes)" : "")
            << ": contacts may be under-resolved (energy gain, particles passing through each other)."
            << " Recommended DEM timestep <= " << warnFraction*e.tCritical() << " s" << endl;
    }
    return e;
}

} // End namespace Foam
