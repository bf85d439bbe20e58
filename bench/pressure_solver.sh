#!/bin/bash
# bench/pressure_solver.sh -- the pressure equation's linear solver in the Mueller tutorial: the same
# tolerances (the tutorial's p tolerance, with relTol 0.01 for p and 0 for pFinal), other solvers and
# GAMG settings.
#
# Each setting reaches the same residual, so the fields it gives differ from the tutorial's by what the
# tolerance leaves, which the pressure tolerance study shows the bed does not notice (1e-6 against 1e-8
# and 1e-10: bench/README.md "Solver tolerances"). What differs is the work: this measures it. From the
# demo's state (the Mueller demo run once, serial), 0.02 s of coupled steps (111 CFD steps) per setting,
# the settings taken in turn ROUNDS times (so a slow minute of the machine falls on all of them); per run
# the CPU seconds of the solver process (user + system), the p solves per step, their mean GAMG/PCG
# iterations and the largest final residual. The rest of system/fvSolution is the tutorial's as it is.
# Serial, on a quiet machine.
#
#   bench/pressure_solver.sh [-rounds N] [-settings "NAME ..."] [-name NAME]
#
# settings (the p entry; pFinal is $p with relTol 0):
#   tutorial    GAMG, smoother GaussSeidel (the tutorial's)
#   DICGS       GAMG, smoother DICGaussSeidel
#   DIC         GAMG, smoother DIC
#   coarse100   GAMG, GaussSeidel, nCellsInCoarsestLevel 100 (10 by default)
#   post1       GAMG, GaussSeidel, nPostSweeps 1 (2 by default)
#   PCG         PCG, preconditioner DIC
#   algebraic   GAMG, GaussSeidel, agglomerator algebraicPair (cells paired by the size of the matrix's
#               coefficients, not by face area: Dp varies by orders between the bed and the freeboard)
# Written: bench/results/pressure_solver.csv (a row per run) and pressure_solver_info.txt; with -name NAME,
# bench/results/NAME.csv and NAME_info.txt instead (a measurement kept beside the main one).
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/.." && pwd)"
rounds=3
settings="tutorial DICGS DIC coarse100 post1 PCG"
name=pressure_solver
while [ $# -gt 0 ]; do
    case "$1" in
        -rounds) rounds="$2"; shift 2 ;;
        -settings) settings="$2"; shift 2 ;;
        -name) name="$2"; shift 2 ;;
        *) echo "usage: $0 [-rounds N] [-settings \"NAME ...\"] [-name NAME]" >&2; exit 2 ;;
    esac
done
[[ "$name" =~ ^[A-Za-z0-9_]+$ ]] || { echo "bench/pressure_solver: -name must be letters, digits and _ (got '$name')" >&2; exit 2; }
[[ "$rounds" =~ ^[1-9][0-9]*$ ]] || { echo "bench/pressure_solver: -rounds must be a whole number (got '$rounds')" >&2; exit 2; }
# the tutorial's p tolerance, which every setting solves to
tol=$(sed -n 's/^ *p  *{ solver GAMG; smoother GaussSeidel; tolerance \([0-9.eE+-]*\); relTol 0.01; }.*/\1/p' \
      "$root/tutorials/fluidizedBedMuller/system/fvSolution")
[ -n "$tol" ] || { echo "bench/pressure_solver: the tutorial's p entry is not 'solver GAMG; smoother GaussSeidel; tolerance T; relTol 0.01;': update the script" >&2; exit 1; }
entry() { # setting: the p entry's contents
    case "$1" in
        tutorial) echo "solver GAMG; smoother GaussSeidel; tolerance $tol; relTol 0.01;" ;;
        DICGS) echo "solver GAMG; smoother DICGaussSeidel; tolerance $tol; relTol 0.01;" ;;
        DIC) echo "solver GAMG; smoother DIC; tolerance $tol; relTol 0.01;" ;;
        coarse100) echo "solver GAMG; smoother GaussSeidel; tolerance $tol; relTol 0.01; nCellsInCoarsestLevel 100;" ;;
        post1) echo "solver GAMG; smoother GaussSeidel; tolerance $tol; relTol 0.01; nPostSweeps 1;" ;;
        PCG) echo "solver PCG; preconditioner DIC; tolerance $tol; relTol 0.01;" ;;
        algebraic) echo "solver GAMG; smoother GaussSeidel; tolerance $tol; relTol 0.01; agglomerator algebraicPair;" ;;
        *) return 1 ;;
    esac
}
for s in $settings; do entry "$s" > /dev/null || { echo "bench/pressure_solver: unknown setting '$s' (see the script's head)" >&2; exit 2; }; done
. "$root/etc/bashrc" || exit 1
work="$here/work/pressure_solver"
state="$work/state/fluidizedBedMuller/runs/bigParticle_dx1_U0.9_demo"
if [ ! -f "$state/log.coarseDemFoam" ] || ! grep -q '^End' "$state/log.coarseDemFoam"; then
    echo "bench/pressure_solver: the demo's state (the Mueller demo, serial, once)"
    rm -rf "$work/state"; mkdir -p "$work/state"
    cp -r "$root/tutorials/fluidizedBedMuller" "$work/state/"
    rm -rf "$work/state/fluidizedBedMuller/runs"
    ( cd "$work/state/fluidizedBedMuller" && ./Allrun -mode demo -model bigParticle -np 1 > "$work/state/log.Allrun" 2>&1 ) ||
        { echo "bench/pressure_solver: the demo failed ($work/state/log.Allrun)" >&2; exit 1; }
fi
last=$(cd "$state" && ls -d [0-9]* | sort -g | tail -1)
end=$(/usr/bin/python3 -c "import sys; print('%.6g' % (float(sys.argv[1]) + 0.02))" "$last")
csv="$here/results/$name.csv"
mkdir -p "$here/results"
echo "setting,round,cpu_s,p_solves_per_step,p_iterations_mean,max_final_residual,steps" > "$csv"
for r in $(seq 1 "$rounds"); do
    for s in $settings; do
        d="$work/$s"
        rm -rf "$d"; mkdir -p "$d"
        cp -r "$state/constant" "$state/system" "$state/DEM" "$state/$last" "$d/"
        mkdir -p "$d/post"   # the DEM script writes the wall forces there
        cp "$root/tutorials/fluidizedBedMuller/system/fvSolution" "$d/system/"   # the tutorial's as it is now
        sed -i "s|^ *p  *{.*|    p     { $(entry "$s") }|" "$d/system/fvSolution"
        sed -i "s|^endTime .*|endTime         $end;|; s|^writeInterval .*|writeInterval   5;|" "$d/system/controlDict"
        ( cd "$d" && /usr/bin/time -f "%U %S" -o time.txt coarseDemFoam > log 2>&1 ) ||
            { echo "bench/pressure_solver: $s failed ($d/log)" >&2; exit 1; }
        row=$(awk '/Solving for p/ { n++; it += $NF; r = $(NF-3); sub(",", "", r); if (r + 0 > m) m = r + 0 }
                   END { printf "%.3f,%.3f,%.3g", n / s, it / n, m }' s="$(grep -c '^Time =' "$d/log")" "$d/log")
        cpu=$(awk '{ printf "%.2f", $1 + $2 }' "$d/time.txt")
        echo "$s,$r,$cpu,$row,$(grep -c '^Time =' "$d/log")" >> "$csv"
        echo "bench/pressure_solver: round $r $s: $cpu s of CPU, p solves per step, their mean iterations, the largest final residual: $row"
    done
done
{
    echo "command: bench/pressure_solver.sh -rounds $rounds -settings \"$settings\" -name $name"
    echo "commit: $("$root/etc/codeVersion")"
    echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
    echo "state: the Mueller demo's last write ($last s), 0.02 s from it; p solved to the tutorial's $tol"
    echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$here/results/${name}_info.txt"
/usr/bin/python3 - "$csv" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
ref = statistics.median(float(r["cpu_s"]) for r in rows if r["setting"] == "tutorial") if any(r["setting"] == "tutorial" for r in rows) else None
for s in dict.fromkeys(r["setting"] for r in rows):
    c = [float(r["cpu_s"]) for r in rows if r["setting"] == s]
    print("%-10s median CPU %.2f s%s (runs: %s)" % (s, statistics.median(c),
          "" if ref is None else ", %.3f of the tutorial's" % (statistics.median(c) / ref), " ".join("%.2f" % x for x in c)))
PY
