#!/bin/bash
# The solver's warning of a two-step oscillation (src/solvers/coarseDemFoam/twoStepOscillation.H) on
# Courant series of real runs (courantSeries/*.csv, each naming its run):
#   diverged  bigParticle at 0.010 m/s in the binary bed, unrelaxed: diverged at 3.728 s. The warning
#             must come in its last 0.2 s, at least 20 CFD steps before the end, and not before
#   relaxed   the same bed with alphaRelaxationTime 0.003 s (ran to 6 s): no warning
#   bubbling  the Mueller demo (bigParticle, a bubbling bed whose Courant number jumps with the
#             bubbles): no warning
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$here/result.sh"
work=$(mktemp -d /tmp/coarsedem-oscillation.XXXXXX)
trap 'rm -rf "$work"' EXIT
series="$here/courantSeries"
if ! g++ -std=c++11 -O1 -Wall -Werror -I"$top/src/solvers/coarseDemFoam" "$series/warnings.cpp" -o "$work/warnings" 2> "$work/log.build"; then
    result fail "two-step oscillation: the driver did not build ($(head -3 "$work/log.build"))"
    finish
fi
warnings() { "$work/warnings" < "$series/$1.csv"; }

out=$(warnings diverged_bigParticle_U0.010)
steps=$(echo "$out" | awk '/^steps/ {print $2}')
first=$(echo "$out" | awk '/^warn/ {print $2; exit}')
n=$(echo "$out" | grep -c '^warn')
echo "    diverged: $steps steps, $n warnings, the first at t = ${first:-none} s (the run stopped at 3.728 s)"
if [ -n "$first" ] && /usr/bin/python3 -c "import sys; t = float(sys.argv[1]); sys.exit(0 if 3.528 <= t <= 3.728 - 0.020 else 1)" "$first"; then
    result ok "two-step oscillation: the diverging run is warned about at t = $first s, $(/usr/bin/python3 -c "import sys; print(round((3.728 - float(sys.argv[1])) / 1e-3))" "$first") CFD steps before it stopped"
else
    result fail "two-step oscillation: the diverging run's first warning at ${first:-none} (wanted in 3.528..3.708 s)"
fi
for c in relaxed_bigParticle_U0.010 muller_demo; do
    out=$(warnings "$c")
    n=$(echo "$out" | grep -c '^warn')
    steps=$(echo "$out" | awk '/^steps/ {print $2}')
    if [ "$n" -eq 0 ] && [ "${steps:-0}" -gt 500 ]; then
        result ok "two-step oscillation: no warning in $c ($steps CFD steps)"
    else
        result fail "two-step oscillation: $n warnings in $c ($steps CFD steps): $(echo "$out" | head -2 | tr '\n' ' ')"
    fi
done
finish
