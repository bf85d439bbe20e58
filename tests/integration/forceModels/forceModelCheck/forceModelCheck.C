/*---------------------------------------------------------------------------*\
    forceModelCheck: evaluates one of the coupling's non-drag force models, as
    the solver selects it (forceModel::New), on particles read from standard
    input, one per line:

        d volume  vx vy vz  Ux Uy Uz  wx wy wz

    (diameter, DEM solid volume, particle and fluid velocity, fluid vorticity;
    SI units), and prints each particle's force "fx fy fz" on standard output.
    The fluid is water-like unless -rho / -nu say otherwise. Warnings of the
    model go to standard error. Built and run by
    tests/integration/run_force_models.sh, which compares the forces with
    published limits.

        forceModelCheck liftForce [-rho 1000] [-nu 1e-6] < particles.txt
\*---------------------------------------------------------------------------*/
#include "argList.H"
#include "IOstreams.H"
#include "forceModel.H"
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote("Evaluate a force model of the coupling on particles read from standard input");
    argList::noParallel();
    argList::noBanner();
    argList::noCheckProcessorDirectories();
    argList::addArgument("model");
    argList::addOption("rho", "scalar", "fluid density (default 1000)");
    argList::addOption("nu", "scalar", "kinematic viscosity (default 1e-6)");
    argList args(argc, argv, false, false, false);   // no case directory needed

    const word name(args[1]);
    fluidProperties fl{args.opt<scalar>("rho", 1000), args.opt<scalar>("nu", 1e-6), vector(0, 0, -9.81)};

    dictionary couplingDict;
    couplingDict.name() = "forceModelCheck";
    autoPtr<forceModel> model(forceModel::New(name, couplingDict));
    if (model->isDrag())
    {
        FatalErrorInFunction << name << " is a drag model: this check evaluates other forces" << exit(FatalError);
    }

    std::vector<scalar> d, vol;
    std::vector<vector> v, U, w;
    std::string line;
    while (std::getline(std::cin, line))
    {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream is(line);
        scalar a[11];
        for (scalar& x : a) is >> x;
        if (!is)
        {
            FatalErrorInFunction << "line '" << line.c_str() << "': expected 11 numbers" << exit(FatalError);
        }
        d.push_back(a[0]); vol.push_back(a[1]);
        v.push_back(vector(a[2], a[3], a[4])); U.push_back(vector(a[5], a[6], a[7]));
        w.push_back(vector(a[8], a[9], a[10]));
    }
    const label n = d.size();
    particleFluidState s;
    s.n = n;
    s.v = v.data();
    s.d = d.data();
    s.volume = vol.data();
    s.Uf = vectorField(n);
    s.alphaf = scalarField(n, 1.0);
    s.vorticity = vectorField(n);
    s.gradP = vectorField(n, Zero);
    s.divTau = vectorField(n, Zero);
    s.DUfDt = vectorField(n, Zero);
    s.dvdt = vectorField(n, Zero);
    for (label i = 0; i < n; ++i)
    {
        s.Uf[i] = U[i];
        s.vorticity[i] = w[i];
    }
    scalarField K(n, 0);
    vectorField f(n, Zero);
    model->force(s, fl, K, f);   // K stays 0: not a drag law
    std::cout.precision(12);
    for (label i = 0; i < n; ++i)
    {
        std::cout << f[i].x() << ' ' << f[i].y() << ' ' << f[i].z() << '\n';
    }
    return 0;
}
