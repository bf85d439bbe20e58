#!/bin/bash
# bench/coupled/run.sh -- a coupled run at the cost of its parts, measured side by side in one run.
#
# The Mueller bed (tutorials/fluidizedBedMuller, dx/d = 1, 0.9 m/s) from a bubbling state (made once at
# t = STATE s after start-up and reused: the measurement is of a fluidized bed, not of a settling one),
# run for a fixed number of couplings with each method, serial and on 2 ranks, and in the same run:
#   dem_alone    LIGGGHTS alone: the tutorial's DEM script from the state's DEM restart for the same
#                DEM steps, fix couple/coarse applying the coupling forces stored in the restart (the
#                drag as K (u_f - v) with the particle's velocity of each step): frozen, not updated
#   fluid_alone  coarseDemFoam -frozenParticles: the same case, one coupling at the start, then the fluid
#                alone with alpha and the exchange fields frozen (its "fluid" stage timer)
#   pimpleFoam   OpenFOAM's pimpleFoam on the same mesh, schemes and solver settings, alpha = 1, from
#                the inlet velocity everywhere (time per step after its first step)
# Written: bench/coupled/results/coupled.csv, ratios.md, run_info.txt (command, commit, machine load).
#
#   bench/coupled/run.sh [-couplings N] [-methods "centre divided ..."] [-np "1 2"] [-state T]
#
# Methods: centre divided bigParticle twoGrid gaussian diffusion (as the tutorial's -model: bigParticle
# n = 5 and twoGrid wall-mirrored, gaussian b = 3 d, diffusion b = 6 d). Defaults: 150 couplings, all
# six methods, np 1 and 2, state at 0.4 s (the bed has expanded and bubbles). The state is kept in
# bench/coupled/work/state (git-ignored) and made when missing (about 8 minutes on one core).
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$top/etc/bashrc" || exit 1
. "$here/../solverLog.sh"   # run_solver, stage timers, loop wall time
tut="$top/tutorials/fluidizedBedMuller"
couplings=150; methods="centre divided bigParticle twoGrid gaussian diffusion"; nps="1 2"; state_t=0.4
while [ $# -gt 0 ]; do
    case "$1" in -couplings|-methods|-np|-state)
        [ $# -ge 2 ] || { echo "bench/coupled: $1 needs a value (see -h)" >&2; exit 2; } ;;
    esac
    case "$1" in
        -couplings) couplings="$2"; shift 2 ;;
        -methods) methods="$2"; shift 2 ;;
        -np) nps="$2"; shift 2 ;;
        -state) state_t="$2"; shift 2 ;;
        -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
        *) echo "bench/coupled: unknown option '$1' (see -h)" >&2; exit 2 ;;
    esac
done
known="centre divided bigParticle twoGrid gaussian diffusion"
for m in $methods; do
    [[ " $known " == *" $m "* ]] || { echo "bench/coupled: unknown method '$m' (known: $known)" >&2; exit 2; }
done
for np in $nps; do
    case "$np" in 1|2) ;; *) echo "bench/coupled: np $np: the Mueller case splits in 1 or 2 parts only (decomposeParDict (1 2 1))" >&2; exit 2 ;; esac
done
case "$couplings" in ''|*[!0-9]*|0) echo "bench/coupled: -couplings needs a positive number" >&2; exit 2 ;; esac
python3 -c "import sys; t = float(sys.argv[1]); sys.exit(0 if t > 0 else 1)" "$state_t" 2> /dev/null ||
    { echo "bench/coupled: -state $state_t: needs a time in s after the start, > 0" >&2; exit 2; }

work="$here/work"; results="$here/results"
mkdir -p "$work" "$results"
# the code's version before this run writes its own results (tracked files: they would read as -dirty)
code_version=$("$top/etc/codeVersion"); started=$(date -u '+%Y-%m-%d %H:%M UTC')
log() { echo "bench/coupled: $*"; }
# the case files of a method, made by the tutorial itself (no copy of its method table here)
make_case() { # dir method
    rm -rf "$1"
    "$tut/Allrun" -model "$2" -makeCase "$1" > /dev/null || return 1
    # no sampling function objects: the solver is measured, not the tutorial's profile sampling
    foamDictionary -entry functions -remove "$1/system/controlDict" > /dev/null 2>&1
    sed -i 's/^purgeWrite .*/purgeWrite 0;/' "$1/system/controlDict"
}

# ---- the bubbling state: bigParticle from the settled bed to state_t (serial: a loaded machine makes
#      MPI ranks wait for each other)
state="$work/state"
# the state's own time: the CFD steps need not land on -state exactly (0.4 s is 2222 steps of 1.8e-4 s)
if [ "$(cat "$state/requested" 2>/dev/null)" != "$state_t" ] || [ ! -f "$state/$(cat "$state/state_time" 2>/dev/null)/dem.restart" ]; then
    log "making the bubbling state: bigParticle to t = $state_t s (once; $state)"
    make_case "$state" bigParticle || exit 1
    (cd "$state" && blockMesh > log.blockMesh 2>&1) || { echo "bench/coupled: blockMesh failed" >&2; exit 1; }
    if [ ! -f "$tut/DEM/init.restart" ]; then
        (cd "$tut" && liggghts -in DEM/in.init > log.init 2>&1) || { echo "bench/coupled: DEM settling failed" >&2; exit 1; }
    fi
    cp "$tut/DEM/init.restart" "$state/DEM/"
    sed -i "s/^endTime .*/endTime $state_t;/; s/^writeInterval .*/writeInterval $state_t;/; s/^writePrecision .*/writePrecision 17;/" \
        "$state/system/controlDict"
    run_solver "$state" 1 || { echo "bench/coupled: the state run failed ($state/log.coarseDemFoam)" >&2; exit 1; }
    last=$(cd "$state" && ls -d [0-9]* | sort -g | tail -1)
    [ -f "$state/$last/dem.restart" ] || { echo "bench/coupled: no dem.restart at the state's last time $last" >&2; exit 1; }
    echo "$last" > "$state/state_time"
    echo "$state_t" > "$state/requested"
fi
state_t=$(cat "$state/state_time")
dem_dt=$(awk '/^timestep/ {print $2}' "$tut"/DEM/*.liggghts | head -1)
interval=$(awk '/^couplingInterval/ {gsub(";","",$2); print $2}' "$tut/constant/couplingProperties")
[ -n "$dem_dt" ] && [ -n "$interval" ] || { echo "bench/coupled: cannot read the DEM step or couplingInterval" >&2; exit 1; }
end_t=$(python3 -c "print('%.10g' % ($state_t + $couplings*$interval*$dem_dt))")
dem_steps=$((couplings*interval))

# a case at the state for method m (mesh, fields and DEM restart of the state)
case_at_state() { # dir method np
    make_case "$1" "$2" || return 1
    cp -r "$state/constant/polyMesh" "$1/constant/"
    cp -r "$state/$state_t" "$1/"
    rm -rf "$1/0"
    sed -i "s/^endTime .*/endTime $end_t;/; s/^writeInterval .*/writeInterval $end_t;/" "$1/system/controlDict"
    if [ "$3" -gt 1 ]; then (cd "$1" && decomposePar -force -time "$state_t" > log.decomposePar 2>&1) || return 1; fi
}
csv="$results/coupled.csv"
echo "method,np,couplings,total_s,dem_s,fluid_s,coupling_s,dem_alone_s,fluid_alone_s,pimpleFoam_s" > "$csv"

# ---- pimpleFoam on the same mesh and settings (alpha = 1), on np ranks: time per step after the first,
#      for the same number of steps
pimple_run() { # np -> seconds for $couplings steps
    local np="$1" pim="$work/pimpleFoam_np$1" dt
    rm -rf "$pim"; mkdir -p "$pim/constant" "$pim/0"
    cp -r "$state/system" "$pim/"
    cp -r "$state/constant/polyMesh" "$state/constant/transportProperties" "$state/constant/turbulenceProperties" "$pim/constant/"
    cp "$tut/0.orig/U" "$tut/0.orig/p" "$pim/0/"
    sed -i "s/INLET_VELOCITY/0.9/; s/^internalField .*/internalField uniform (0 0 0.9);/" "$pim/0/U"
    dt=$(python3 -c "print('%.10g' % ($interval*$dem_dt))")
    sed -i "s/^application .*/application pimpleFoam;/; s/^startFrom .*/startFrom startTime;/; s/^deltaT .*/deltaT $dt;/; s/^writeInterval .*/writeInterval 1;/; s/^endTime .*/endTime $(python3 -c "print('%.10g' % ($couplings*$dt))");/" "$pim/system/controlDict"
    ( cd "$pim" || exit 1
      if [ "$np" -gt 1 ]; then
          decomposePar -force > log.decomposePar 2>&1 || exit 1
          mpirun --allow-run-as-root --oversubscribe -np "$np" pimpleFoam -parallel > log.pimpleFoam 2>&1
      else
          pimpleFoam > log.pimpleFoam 2>&1
      fi ) || { echo "bench/coupled: pimpleFoam failed ($pim/log.pimpleFoam)" >&2; return 1; }
    awk '/^ExecutionTime/ {n++; t[n]=$3} END {if (n > 1) printf "%.6g", (t[n]-t[1])*n/(n-1); else print "nan"}' "$pim/log.pimpleFoam"
}

for np in $nps; do
    log "pimpleFoam np $np: $couplings steps"
    pimple_s=$(pimple_run "$np") || exit 1
    # ---- DEM alone from the state (frozen coupling forces), on np ranks
    dd="$work/demAlone_np$np"
    rm -rf "$dd"; mkdir -p "$dd"
    cp -r "$state/DEM" "$dd/"; mkdir -p "$dd/$state_t"; cp "$state/$state_t/dem.restart" "$dd/$state_t/"
    printf 'include DEM/in.liggghts\nrun %s\n' "$dem_steps" > "$dd/in.alone"
    if [ "$np" -gt 1 ]; then
        (cd "$dd" && mpirun --allow-run-as-root --oversubscribe -np "$np" liggghts -in in.alone -var restarting 1 \
            -var restart "$state_t/dem.restart" -log log.liggghts -screen none > /dev/null) || { echo "bench/coupled: DEM alone failed ($dd)" >&2; exit 1; }
    else
        (cd "$dd" && liggghts -in in.alone -var restarting 1 -var restart "$state_t/dem.restart" -log log.liggghts \
            -screen none > /dev/null) || { echo "bench/coupled: DEM alone failed ($dd)" >&2; exit 1; }
    fi
    dem_alone=$(grep "^Loop time of" "$dd/log.liggghts" | tail -1 | awk '{print $4}')
    for m in $methods; do
        # ---- the coupled run
        d="$work/${m}_np$np"
        case_at_state "$d" "$m" "$np" || { echo "bench/coupled: case for $m failed" >&2; exit 1; }
        log "$m np $np: $couplings couplings from t = $state_t s"
        run_solver "$d" "$np" || { echo "bench/coupled: $m np $np failed ($d/log.coarseDemFoam)" >&2; exit 1; }
        lg="$d/log.coarseDemFoam"
        total=$(loop_wall "$lg")
        demS=$(stage "$lg" DEM); fluidS=$(stage "$lg" fluid)
        coup=$(coupling_seconds "$lg")
        # ---- the fluid alone, same case, frozen particles
        f="$work/${m}_np${np}_fluidAlone"
        case_at_state "$f" "$m" "$np" || exit 1
        run_solver "$f" "$np" -frozenParticles || { echo "bench/coupled: fluid alone failed ($f/log.coarseDemFoam)" >&2; exit 1; }
        fluidAlone=$(stage "$f/log.coarseDemFoam" fluid)
        echo "$m,$np,$couplings,$total,$demS,$fluidS,$coup,$dem_alone,$fluidAlone,$pimple_s" >> "$csv"
        rm -rf "$d"/processor*/[0-9]* "$f"   # keep the coupled run's log and case, not its fields
    done
done

python3 "$here/ratios.py" "$csv" > "$results/ratios.md" || exit 1
{
    echo "command: bench/coupled/run.sh -couplings $couplings -methods \"$methods\" -np \"$nps\" -state $state_t"
    echo "commit: $code_version"
    echo "date: $started (start) to $(date -u '+%H:%M UTC')"
    echo "machine: $(nproc) cores; load average at the end $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$results/run_info.txt"
cat "$results/ratios.md"
