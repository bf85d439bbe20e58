#!/bin/bash
# The solver's warning of a growing oscillation of the Courant number (src/solvers/coarseDemFoam/
# growingOscillation.H), fed the Courant series of real runs (courantSeries/*.csv, each naming its run)
# and made-up ones:
#   diverged     bigParticle at 0.010 m/s in the binary bed, unrelaxed, diverged at 3.728 s: warned in its
#                last 0.2 s, at least 20 CFD steps before the end, and not before; the same from 3.5 s
#                as a continued run (warm-up 20 steps). diffusion at 0.010 m/s, diverged at 5.615 s
#                (an oscillation of about five steps, growing within 50): warned before the end, not
#                before 5.5 s
#   relaxed      the bigParticle bed with alphaRelaxationTime 0.003 s (ran to 6 s): no warning
#   muller       the Mueller demo (bigParticle, bubbling): no warning, from rest or continued
#   made-up      after 300 steps at 0.2 +- 2 %: a growth to 5.8 times with no oscillation (no warning);
#                the same growth swinging +-40 % from step to step, or with a period of four steps
#                (warned within 45 steps); a long alternating growth (warned again, at least 100 steps
#                apart); an alternating growth inside the warm-up (no warning); a fluid at rest, then
#                flowing (no floating-point trap: the solver traps 0/0 and stopped on it)
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$here/result.sh"
work=$(mktemp -d /tmp/coarsedem-oscillation.XXXXXX)
trap 'rm -rf "$work"' EXIT
series="$here/courantSeries"
if ! g++ -std=c++11 -O1 -Wall -Werror -I"$top/src/solvers/coarseDemFoam" "$series/warnings.cpp" -o "$work/warnings" 2> "$work/log.build"; then
    result fail "growing oscillation: the driver did not build ($(head -3 "$work/log.build"))"
    finish
fi
# warnings FILE [WARMUP] [FROM_T]: the driver's output for the series in FILE from time FROM_T on
warnings() { awk -F, -v t0="${3:-0}" '/^#/ || /^t_s/ || $1 + 0 >= t0 + 0' "$1" | "$work/warnings" "${2:-200}"; }
first_warning() { echo "$1" | awk '/^warn/ {print $2; exit}'; }
count() { echo "$1" | grep -c '^warn'; }
steps() { echo "$1" | awk '/^steps/ {print $2}'; }
in_range() { /usr/bin/python3 -c "import sys; t = float(sys.argv[1]); sys.exit(0 if float(sys.argv[2]) <= t <= float(sys.argv[3]) else 1)" "$@"; }

# the diverged run, from its start and continued from 3.5 s: the first warning in 3.528..3.708 s
for how in "200 0 from its start" "20 3.4995 continued from 3.5 s"; do
    set -- $how
    out=$(warnings "$series/diverged_bigParticle_U0.010.csv" "$1" "$2")
    first=$(first_warning "$out")
    what="${*:3}"
    echo "    diverged ($what): $(steps "$out") steps, $(count "$out") warnings, the first at t = ${first:-none} s (the run stopped at 3.728 s)"
    if [ -n "$first" ] && in_range "$first" 3.528 3.708; then
        result ok "growing oscillation: the diverging run ($what) is warned about at t = $first s, $(/usr/bin/python3 -c "import sys; print(round((3.728 - float(sys.argv[1])) / 1e-3))" "$first") CFD steps before it stopped"
    else
        result fail "growing oscillation: the diverging run ($what): first warning at ${first:-none} (wanted in 3.528..3.708 s)"
    fi
done
out=$(warnings "$series/diverged_diffusion_U0.010.csv")
first=$(first_warning "$out")
echo "    diverged diffusion: $(steps "$out") steps, $(count "$out") warnings, the first at t = ${first:-none} s (the run stopped at 5.615 s)"
if [ -n "$first" ] && in_range "$first" 5.5 5.614; then
    result ok "growing oscillation: the diverging diffusion run is warned about at t = $first s, $(/usr/bin/python3 -c "import sys; print(round((5.615 - float(sys.argv[1])) / 1e-3))" "$first") CFD steps before it stopped"
else
    result fail "growing oscillation: the diverging diffusion run: first warning at ${first:-none} (wanted in 5.5..5.614 s)"
fi
for c in "relaxed_bigParticle_U0.010 200" "muller_demo 200" "muller_demo 20"; do
    set -- $c
    out=$(warnings "$series/$1.csv" "$2")
    n=$(count "$out"); s=$(steps "$out")
    if [ "$n" -eq 0 ] && [ "${s:-0}" -gt 500 ]; then
        result ok "growing oscillation: no warning in $1 (warm-up $2, $s CFD steps)"
    else
        result fail "growing oscillation: $n warnings in $1 (warm-up $2, ${s:-no} CFD steps): $(echo "$out" | head -2 | tr '\n' ' ')"
    fi
done

# made-up series: 300 steps at 0.2 (+-2 % alternating), then from step START 45 steps of growth by 4 %
# a step (to 5.8 times), about which the Courant number alternates +-40 % from step to step (two),
# with a period of four steps (four), or not at all (none); then 600 steps at 0.2 again
made_up() { # name start pattern [growth steps]
    /usr/bin/python3 - "$@" > "$work/$1.csv" <<'PY'
import sys
name, start, pattern = sys.argv[1], int(sys.argv[2]), sys.argv[3]
growth, steps = (float(sys.argv[4]), int(sys.argv[5])) if len(sys.argv) > 5 else (1.04, 45)
swing = {"two": lambda k: 0.4 * (-1) ** k, "four": lambda k: 0.4 * (1 if k % 4 < 2 else -1), "none": lambda k: 0.0}[pattern]
print("t_s,courant_max")
for i in range(start + steps + 600):
    c = 0.2 * (1 + 0.02 * (-1) ** i)
    if start <= i < start + steps:
        k = i - start
        c = 0.2 * growth ** k * (1 + swing(k))
    print("%.3f,%.6g" % (i * 1e-3, c))
PY
}
made_up growing 300 none
out=$(warnings "$work/growing.csv")
if [ "$(count "$out")" -eq 0 ]; then
    result ok "growing oscillation: no warning for a growth to 5.8 times that does not oscillate"
else
    result fail "growing oscillation: a growth without oscillation warned: $(echo "$out" | head -1)"
fi
for p in two four; do
    made_up "swinging_$p" 300 "$p"
    out=$(warnings "$work/swinging_$p.csv")
    first=$(first_warning "$out")
    what=$([ $p = two ] && echo "alternating from step to step" || echo "swinging with a period of four steps")
    if [ -n "$first" ] && in_range "$first" 0.300 0.345; then
        result ok "growing oscillation: a growth $what is warned about $(/usr/bin/python3 -c "import sys; print(round(float(sys.argv[1]) / 1e-3) - 300)" "$first") steps after it begins"
    else
        result fail "growing oscillation: a growth $what from t = 0.300 s: first warning at ${first:-none} (wanted by 0.345 s)"
    fi
done
# a long oscillation: 400 steps of alternating growth at 1 % a step
made_up sustained 300 two 1.01 400
out=$(warnings "$work/sustained.csv")
n=$(count "$out")
gaps=$(echo "$out" | awk '/^warn/ { if (n++) { g = ($2 - last) / 1e-3; if (min == "" || g < min) min = g } last = $2 } END { print (min == "" ? "none" : int(min + 0.5)) }')
if [ "$n" -ge 2 ] && [ "$gaps" != none ] && [ "$gaps" -ge 100 ]; then
    result ok "growing oscillation: a long oscillation is warned about again, $n times, at least $gaps steps apart"
else
    result fail "growing oscillation: a long oscillation: $n warnings, the closest ${gaps} steps apart (wanted >= 2, >= 100 apart)"
fi
# a fluid at rest (Courant number 0) for 250 steps, then flowing at 0.5 +- 30 % from step to step:
# no trap, no warning (the warm-up starts when the fluid moves)
/usr/bin/python3 -c "
print('t_s,courant_max')
for i in range(800):
    print('%.3f,%.6g' % (i * 1e-3, 0 if i < 250 else 0.5 * (1 + 0.3 * (-1) ** i)))" > "$work/rest.csv"
out=$(warnings "$work/rest.csv" 2>&1); rc=$?
if [ $rc -eq 0 ] && [ "$(steps "$out")" = 800 ] && [ "$(count "$out")" -eq 0 ]; then
    result ok "growing oscillation: a fluid at rest, then flowing: no floating-point trap, no warning from the detector"
else
    result fail "growing oscillation: a fluid at rest, then flowing: exit $rc, $(echo "$out" | head -2 | tr '\n' ' ')"
fi
made_up early 50 two
out=$(warnings "$work/early.csv")
first=$(first_warning "$out")
if [ -z "$first" ]; then
    result ok "growing oscillation: no warning for an alternating growth inside the 200-step warm-up of a start from rest"
else
    result fail "growing oscillation: an alternating growth in steps 50-95 warned at t = $first s"
fi
finish
