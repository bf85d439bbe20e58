#!/bin/bash
# bench/cases/run.sh -- what a validation run costs per simulated second, with the tutorial's settings
# against the baseline ones, measured side by side in one run.
#
# Each case runs a fixed stretch of simulated time from a state of a developed bed, once with the
# settings of the tutorial as it is (tutorial) and once with the settings it had before issue 44
# (baseline, listed below), serial and on 2 ranks:
#   muller  tutorials/fluidizedBedMuller -mode demo: 0.1 s of the bubbling bed from the shipped state
#           (bigParticle, dx/d 1, 0.9 m/s), the tutorial's own demo with its sampling
#   khan    tutorials/binaryBedKhan, short mode at E = 1e5 Pa (-young 1e5: the validation runs'
#           contacts), divided, 0.015 m/s: STRETCH s (default 0.1) from a state at KHAN_T s (default
#           3: the small layer has come down onto the big one), made once with the tutorial's
#           settings on 2 ranks (about 20 min) and kept in bench/cases/work/khan_state
# Written: bench/cases/results/runs.csv (a row per run: case, settings, np, simulated s, wall s of
# the time loop, wall s per simulated s, the stage timers' seconds: DEM, fluid, coupling (every other
# stage but the output-only fields), the build: the commit of the tree whose binaries ran it), cases.csv (a row per case and rank count: the baseline's and
# the tutorial's wall s per simulated s (medians), their ratio (the median of the pairs'), each one's
# DEM / fluid / coupling shares, the number of pairs and the smallest and largest pair's ratio),
# ratios.md (the same as tables, with the 2-rank speed-ups of the run, of its DEM stage and of its
# fluid stage) and run_info.txt (command, commit, load).
#
#   bench/cases/run.sh [-cases "muller khan"] [-np "1 2"] [-pairs N] [-stretch S] [-khanState T] [-baselineTree DIR]
#   bench/cases/run.sh -methods "centre divided bigParticle ..." [-cases ...] [-np ...] [-pairs N] ...
#
# -methods LIST: instead of the baseline-tutorial pairs, each method of LIST with the tutorial's
#   settings, on the same state, in rounds (each round every method once; -pairs N rounds): what a
#   method costs against centre's run (PCM), the measure Zhang et al. (2023, §V.C) give ("the total
#   computation costs increase by no more than 5% compared with the PCM"). Written:
#   results/methods.csv (a row per run, as runs.csv with the method for the settings) and
#   results/methods.md (ratios.py -methods: per case, rank count and method the median cost per
#   simulated s, its ratio to centre's in the same round, the coupling share and what the method's
#   coupling adds to centre's, as a share of centre's run). LIST must hold centre.
#
# -pairs N: N baseline-tutorial pairs per case and rank count, run in turn (baseline, tutorial,
#   baseline, ...; default 1): the ratio is taken pair by pair and its median reported with the
#   smallest and largest, because on a shared machine one pair's ratio can move by 0.1 or more
#   (2026-12-07: 0.52, 0.62 and 0.37 for the Mueller demo on 2 ranks within ten minutes)
#
# -baselineTree DIR: the baseline rows run with the binaries of another built tree (a clone at the
#   commit before a code change), the tutorial rows with this tree's: the ratio is then the cost
#   before issue 44's settings and code against after, not the settings alone
#
# The baseline (the settings before issue 44, bench/cases/README.md says why each changed):
#   muller  DEM step 3e-6 s with couplingInterval 60 (CFD step 1.8e-4 s); p and pFinal to an
#           absolute 1e-8, U to 1e-8 (relTol 0; the tutorial: p to 1e-4, U to 1e-6 since issue 44)
#   khan    DEM step 1e-5 s with couplingInterval 100 (CFD step 1e-3 s)
# Run it on a quiet machine: on 2 cores anything else running makes the 2-rank runs wait for each
# other (MPI ranks poll).
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$top/etc/bashrc" || exit 1
. "$here/../solverLog.sh"   # run_solver, stage timers, loop wall time
cases="muller khan"; nps="1 2"; pairs=1; stretch=0.1; khan_t=3; baseline_tree=; methods=
while [ $# -gt 0 ]; do
    case "$1" in -cases|-np|-pairs|-stretch|-khanState|-baselineTree|-methods)
        [ $# -ge 2 ] || { echo "bench/cases: $1 needs a value (see -h)" >&2; exit 2; } ;;
    esac
    case "$1" in
        -cases) cases="$2"; shift 2 ;;
        -np) nps="$2"; shift 2 ;;
        -pairs) pairs="$2"; shift 2 ;;
        -stretch) stretch="$2"; shift 2 ;;
        -khanState) khan_t="$2"; shift 2 ;;
        -baselineTree) baseline_tree="$2"; shift 2 ;;
        -methods) methods="$2"; shift 2 ;;
        -h|--help) sed -n '2,/^set -uo/{/^#/p}' "$0"; exit 0 ;;
        *) echo "bench/cases: unknown option '$1' (see -h)" >&2; exit 2 ;;
    esac
done
for c in $cases; do
    case "$c" in muller|khan) ;; *) echo "bench/cases: unknown case '$c' (muller khan)" >&2; exit 2 ;; esac
done
for np in $nps; do
    case "$np" in 1|2) ;; *) echo "bench/cases: np $np: 1 or 2 ranks" >&2; exit 2 ;; esac
done
if [ -n "$methods" ]; then
    # the methods each tutorial takes (fluidizedBedMuller -model, binaryBedKhan -method)
    for c in $cases; do
        case "$c" in muller) known="centre divided bigParticle twoGrid gaussian diffusion diffusionSources" ;;
                     khan) known="centre divided bigParticle diffusion diffusionSources sizeAwareDiffusion" ;; esac
        for m in $methods; do
            [[ " $known " == *" $m "* ]] || { echo "bench/cases: unknown method '$m' for $c (known: $known)" >&2; exit 2; }
        done
    done
    [[ " $methods " == *" centre "* ]] || { echo "bench/cases: -methods needs centre (each method's cost is taken against it)" >&2; exit 2; }
    [ -z "$baseline_tree" ] || { echo "bench/cases: -methods runs the tutorial's settings only (no -baselineTree)" >&2; exit 2; }
fi
[[ "$pairs" =~ ^[1-9][0-9]*$ ]] || { echo "bench/cases: -pairs '$pairs' must be a whole number >= 1" >&2; exit 2; }
if [ -n "$baseline_tree" ]; then
    [ -x "$baseline_tree/platforms/$WM_OPTIONS/bin/coarseDemFoam" ] && [ -f "$baseline_tree/etc/bashrc" ] ||
        { echo "bench/cases: -baselineTree $baseline_tree is not a built tree (no platforms/$WM_OPTIONS/bin/coarseDemFoam)" >&2; exit 2; }
    baseline_tree="$(cd "$baseline_tree" && pwd)"
fi
for v in "$stretch" "$khan_t"; do
    /usr/bin/python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) > 0 else 1)" "$v" 2> /dev/null ||
        { echo "bench/cases: '$v' must be a time in s > 0" >&2; exit 2; }
done

work="$here/work"; results="$here/results"
mkdir -p "$work" "$results"
code_version=$("$top/etc/codeVersion"); started=$(date -u '+%Y-%m-%d %H:%M UTC')
# each tree's build for runs.csv, taken once before anything under results/ is written: the tree's
# commit, -dirty when its code (not its results) has uncommitted changes
code_paths="src liggghts-fix etc wmake Allwmake"
# shellcheck disable=SC2086
build_top=$(cd "$top" && etc/codeVersion $code_paths)
# shellcheck disable=SC2086
build_baseline=$([ -n "$baseline_tree" ] && cd "$baseline_tree" && etc/codeVersion $code_paths)
log() { echo "bench/cases: $*"; }
add() { /usr/bin/python3 -c "import sys; print('%.10g' % (float(sys.argv[1]) + float(sys.argv[2])))" "$1" "$2"; }

# ---- settings
# muller_baseline DIR: the Mueller case files DIR as they were before issue 44
muller_baseline() {
    sed -i "s|^timestep .*|timestep        3e-6|" "$1/DEM/materials.liggghts"
    sed -i "s|^couplingInterval .*|couplingInterval    60;|" "$1/constant/couplingProperties"
    cat > "$1/system/fvSolution" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object fvSolution; }
solvers
{
    p     { solver GAMG; smoother GaussSeidel; tolerance 1e-8; relTol 0.01; }
    pFinal { $p; relTol 0; }
    "(U|UFinal)" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-8; relTol 0; }
}
PIMPLE
{
    nOuterCorrectors 1;
    nCorrectors      2;
    nNonOrthogonalCorrectors 0;
    momentumPredictor yes;
    pRefCell 0;
    pRefValue 0;
}
EOF
}
# khan_baseline DIR: the binary bed's case files (E = 1e5 Pa) as they were before issue 44; the
# DEM dump keeps its interval in simulated time
khan_baseline() {
    local old new
    old=$(awk '/^timestep/ {print $2}' "$1/DEM/in.liggghts")
    sed -i "s|^timestep .*|timestep        1e-5|" "$1/DEM/in.liggghts"
    sed -i "s|^couplingInterval .*|couplingInterval    100;|" "$1/constant/couplingProperties"
    new=$(awk -v o="$old" '/^dump / {printf "%d", $5 * o / 1e-5 + 0.5}' "$1/DEM/in.liggghts")
    sed -i -E "s|^(dump +dmp +all +custom +)[0-9]+|\1$new|" "$1/DEM/in.liggghts"
}

# ---- running one case: the solver from the state, its time loop's wall time and stage timers
csv="$results/runs.csv"
[ -z "$methods" ] || csv="$results/methods.csv"

# binaries SETTINGS: the tree whose build runs these settings (the baseline's own with -baselineTree)
binaries() { [ "$1" = baseline ] && [ -n "$baseline_tree" ] && echo "$baseline_tree" || echo "$top"; }
# rows of earlier runs are kept for the cases and rank counts this run does not measure (np 1 and 2
# may be measured apart, each on a quiet machine); run_info.txt gets a line per run
header="case,settings,np,simulated_s,wall_s,wall_per_simulated_s,dem_s,fluid_s,coupling_s,build"
[ -z "$methods" ] || header="case,method,np,simulated_s,wall_s,wall_per_simulated_s,dem_s,fluid_s,coupling_s,build"
if [ -f "$csv" ] && [ "$(head -1 "$csv")" = "$header" ]; then
    awk -F, -v cs=" $cases " -v ns=" $nps " 'NR == 1 || index(cs, " " $1 " ") == 0 || index(ns, " " $3 " ") == 0' "$csv" > "$csv.kept"
    mv "$csv.kept" "$csv"
else
    echo "$header" > "$csv"
fi
record() { # case settings-or-method np simulated log
    local w build=$build_top
    [ "$(binaries "$2")" = "$top" ] || build=$build_baseline
    w=$(loop_wall "$5")
    [ -n "$w" ] || { echo "bench/cases: no Progress line in $5" >&2; return 1; }
    echo "$1,$2,$3,$4,$w,$(/usr/bin/python3 -c "import sys; print('%.6g' % (float(sys.argv[1]) / float(sys.argv[2])))" "$w" "$4"),$(stage "$5" DEM),$(stage "$5" fluid),$(coupling_seconds "$5"),$build" >> "$csv"
}

# the Mueller demo in a copy of the tutorial (its own Allrun: the state, the sampling, the demo's 0.1 s)
muller() { # settings np [method: the tutorial's bigParticle; given, it is recorded instead of the settings]
    local m="${3:-bigParticle}" d="$work/muller_$1_np$2${3:+_$3}"
    rm -rf "$d"; mkdir -p "$d"
    cp -r "$top/tutorials/fluidizedBedMuller" "$d/"
    rm -rf "$d/fluidizedBedMuller/runs"
    [ "$1" = baseline ] && muller_baseline "$d/fluidizedBedMuller"
    log "muller $1 np $2 $m: the demo's 0.1 s"
    local bin; bin=$(binaries "$1")
    ( . "$bin/etc/bashrc" && cd "$d/fluidizedBedMuller" && COARSEDEM_DIR="$bin" ./Allrun -mode demo -model "$m" -np "$2" > "$d/log.Allrun" 2>&1 ) ||
        { echo "bench/cases: the Mueller demo failed ($d/log.Allrun)" >&2; return 1; }
    record muller "${3:-$1}" "$2" 0.1 "$d/fluidizedBedMuller/runs/${m}_dx1_U0.9_demo/log.coarseDemFoam"
}

# the binary bed: a state made once with the tutorial's settings, then STRETCH s from it
khan_state="$work/khan_state"
khan_make_state() {
    local tut="$top/tutorials/binaryBedKhan" name=bench_cases_khan_state
    if [ "$(cat "$khan_state/requested" 2>/dev/null)" = "$khan_t" ] && [ -f "$khan_state/$(cat "$khan_state/state_time")/dem.restart" ]; then
        return 0
    fi
    log "making the binary bed's state: divided, 0.015 m/s, E = 1e5 Pa, to t = $khan_t s on 2 ranks (once; $khan_state)"
    ( cd "$tut" && ./Allrun -mode short -young 1e5 -method divided -U 0.015 -np 2 -endTime "$khan_t" -name "$name" > "$work/log.khan_state" 2>&1 ) ||
        { echo "bench/cases: the state run failed ($work/log.khan_state)" >&2; return 1; }
    rm -rf "$khan_state"
    mv "$tut/runs/$name" "$khan_state"
    ( cd "$khan_state" && reconstructPar -latestTime > log.reconstructPar 2>&1 ) ||
        { echo "bench/cases: reconstructPar of the state failed ($khan_state/log.reconstructPar)" >&2; return 1; }
    local last
    last=$(cd "$khan_state" && ls -d [0-9]* | sort -g | tail -1)
    [ -f "$khan_state/$last/dem.restart" ] || [ -f "$khan_state/processor0/$last/dem.restart" ] ||
        { echo "bench/cases: no DEM restart at the state's last time $last" >&2; return 1; }
    echo "$last" > "$khan_state/state_time"
    echo "$khan_t" > "$khan_state/requested"
}
khan() { # settings np [method: the tutorial's divided; given, it is recorded instead of the settings]
    local m="${3:-divided}" d="$work/khan_$1_np$2${3:+_$3}" t0 tend
    t0=$(cat "$khan_state/state_time")
    tend=$(add "$t0" "$stretch")
    rm -rf "$d"; mkdir -p "$d"
    # the case files as the tutorial makes them now (with its decomposeParDict for np > 1), the mesh
    # and fields of the state
    "$top/tutorials/binaryBedKhan/Allrun" -mode short -young 1e5 -method "$m" -U 0.015 -np "$2" -makeCase "$d" ||
        { echo "bench/cases: the tutorial did not make the binary bed's case" >&2; return 1; }
    rm -rf "$d/0"
    cp -r "$khan_state/constant/polyMesh" "$d/constant/"
    cp -r "$khan_state/$t0" "$d/"
    [ -f "$d/$t0/dem.restart" ] || cp "$khan_state/processor0/$t0/dem.restart" "$d/$t0/"
    mkdir -p "$d/post"
    [ "$1" = baseline ] && khan_baseline "$d"
    sed -i "s/^endTime .*/endTime         $tend;/" "$d/system/controlDict"
    if [ "$2" -gt 1 ]; then (cd "$d" && decomposePar -force > log.decomposePar 2>&1) || return 1; fi
    log "khan $1 np $2 $m: $stretch s from t = $t0 s"
    local bin; bin=$(binaries "$1")
    ( . "$bin/etc/bashrc" && run_solver "$d" "$2" ) || { echo "bench/cases: the binary bed failed ($d/log.coarseDemFoam)" >&2; return 1; }
    record khan "${3:-$1}" "$2" "$stretch" "$d/log.coarseDemFoam"
    rm -rf "$d"/post/dump* "$d"/processor*/[0-9]*
}

# the binary bed's neighbour lists: LIGGGHTS alone from the state (the coupling forces stored in its
# restart, frozen), 1000 DEM steps of the tutorial's step per setting, serial: the skin at d_min/6,
# d_min/3 (the tutorial's) and d_min/2, and the bins at a third of the largest cutoff instead of
# LIGGGHTS' half (results/neighbour.csv: LIGGGHTS' loop time, its pair and neighbour shares, the
# list builds). What demNeighbourCheck's warning quotes.
khan_neighbour() {
    local d="$work/khan_neighbour" t0 skin bin out="$results/neighbour.csv"
    t0=$(cat "$khan_state/state_time")
    rm -rf "$d"; mkdir -p "$d/post" "$d/$t0"
    "$top/tutorials/binaryBedKhan/Allrun" -mode short -young 1e5 -method divided -U 0.015 -makeCase "$d/case" || return 1
    cp -r "$d/case/DEM" "$d/"
    cp "$khan_state/$t0/dem.restart" "$d/$t0/" 2>/dev/null || cp "$khan_state/processor0/$t0/dem.restart" "$d/$t0/"
    echo "skin_m,binsize_m,steps,loop_s,pair_s,neigh_s,other_s,list_builds" > "$out"
    for setting in "0.00005 0" "0.0001 0" "0.00015 0" "0.0001 0.00037"; do
        read -r skin bin <<< "$setting"
        printf 'include DEM/in.liggghts\nundump dmp\nneighbor %s bin\nneigh_modify delay 0%s\nrun 1000\n' \
            "$skin" "$([ "$bin" != 0 ] && echo " binsize $bin")" > "$d/in.alone"
        ( cd "$d" && liggghts -in in.alone -var restarting 1 -var restart "$t0/dem.restart" -log log.$skin.$bin \
              -screen none > /dev/null ) || { echo "bench/cases: DEM alone failed ($d/log.$skin.$bin)" >&2; return 1; }
        awk -v s="$skin" -v b="$bin" '/^Loop time of/ {loop = $4} /^Pair  *time/ {pair = $5} /^Neigh  *time/ {neigh = $5}
            /^Other  *time/ {other = $5} /^Neighbor list builds/ {builds = $5}
            END {printf "%s,%s,1000,%s,%s,%s,%s,%s\n", s, b, loop, pair, neigh, other, builds}' "$d/log.$skin.$bin" >> "$out"
    done
    log "khan neighbour lists: $out"
}

for c in $cases; do
    if [ "$c" = khan ]; then
        khan_make_state || exit 1
        # serial, so with the serial runs
        if [ -z "$methods" ] && [[ " $nps " == *" 1 "* ]]; then khan_neighbour || exit 1; fi
    fi
    for np in $nps; do
        for ((i = 1; i <= pairs; ++i)); do
            if [ -n "$methods" ]; then
                for m in $methods; do "$c" tutorial "$np" "$m" || exit 1; done
            else
                for s in baseline tutorial; do "$c" "$s" "$np" || exit 1; done
            fi
        done
    done
done

if [ -n "$methods" ]; then
    /usr/bin/python3 "$here/ratios.py" -methods "$csv" > "$results/methods.md" || exit 1
    table="$results/methods.md"
else
    /usr/bin/python3 "$here/ratios.py" "$csv" "$results/cases.csv" > "$results/ratios.md" || exit 1
    table="$results/ratios.md"
fi
{
    echo "command: bench/cases/run.sh -cases \"$cases\" -np \"$nps\" -pairs $pairs -stretch $stretch -khanState $khan_t${baseline_tree:+ -baselineTree $baseline_tree}${methods:+ -methods \"$methods\"}"
    echo "commit: $code_version"
    [ -n "$baseline_tree" ] && echo "baseline rows: the binaries of $baseline_tree at $build_baseline"
    # which binaries ran (checksum, build time, path): a tree's commit need not be the one it was built at
    "$top/etc/codeVersion" -binaries | sed 's/^/binaries: /'
    [ -n "$baseline_tree" ] && "$baseline_tree/etc/codeVersion" -binaries | sed 's/^/baseline binaries: /'
    echo "date: $started (start) to $(date -u '+%H:%M UTC')"
    echo "machine: $(nproc) cores; load average at the end $(cut -d' ' -f1-3 /proc/loadavg)"
    echo
} >> "$results/run_info.txt"
cat "$table"
