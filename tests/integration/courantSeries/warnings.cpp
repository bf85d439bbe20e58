// warnings.cpp -- tests/integration/run_growing_oscillation.sh: feeds a Courant series (CSV: t_s,
// courant_max; '#' lines skipped) to the solver's growingOscillation and prints the times at which it
// would warn ("warn t ratio mean"), then "steps N". Argument: the warm-up in steps (the solver's 200
// for a start from rest, 20 for a continued run); default 200. Floating-point traps on, as in the solver.
#ifndef _GNU_SOURCE
#define _GNU_SOURCE   // feenableexcept
#endif
#include <fenv.h>

#include "growingOscillation.H"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char** argv)
{
    // as OpenFOAM's FOAM_SIGFPE: an invalid operation or a division by zero stops the program
    feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
    growingOscillation watch(argc > 1 ? std::atoi(argv[1]) : 200);
    std::string line;
    long steps = 0;
    while (std::getline(std::cin, line))
    {
        double t, co;
        if (line.empty() || line[0] == '#' || std::sscanf(line.c_str(), "%lf,%lf", &t, &co) != 2) continue;
        ++steps;
        if (watch.update(co)) std::printf("warn %.6g %.4g %.4g\n", t, watch.ratio(), watch.baseline());
    }
    std::printf("steps %ld\n", steps);
    return 0;
}
