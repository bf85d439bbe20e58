// warnings.cpp -- tests/integration/run_two_step_oscillation.sh: feeds a Courant series (CSV: t_s,
// courant_max; '#' lines skipped) to the solver's twoStepOscillation and prints the times at which it
// would warn, one per line, then "steps N".
#include "twoStepOscillation.H"

#include <cstdio>
#include <iostream>
#include <string>

int main()
{
    twoStepOscillation watch;
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
