#!/bin/bash
# validation/khan/runMatrix.sh -- the binary bed as the paper ran it (issue 41): methods x velocities
# in binaryBedKhan's long mode (3 s + 10 s window) at E = 1e5 Pa, one run after the other, each
# continued where it stopped (a session's end stops a run at any moment: run the same command again;
# a run stopped on purpose with Allrun's -endTime, e.g. at 6 s for a first look, goes on as well).
# Finished runs (a write at the long mode's 13 s) are skipped. At the end, compare.py over every
# finished long run into validation/khan/results/long/.
# The runs that diverged without relaxation (validation/khan/results/README.md: bigParticle and
# diffusion at 0.010 m/s) relax the fluid fraction over 3 ms (Allrun -alphaRelax 0.003, the name ends in
# _relax0.003); -relax names them ("method:U ...", "" for none).
#
#   validation/khan/runMatrix.sh [-methods "divided bigParticle diffusion"] [-U "0.010 0.015 0.020 0.025"] [-np N]
#                                [-relax "bigParticle:0.010 diffusion:0.010"]
#   validation/khan/runMatrix.sh -compare      only the comparison of the finished runs
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
tut="$top/tutorials/binaryBedKhan"
methods="divided bigParticle diffusion"; us="0.010 0.015 0.020 0.025"; np=2; compare_only=0
relax="bigParticle:0.010 diffusion:0.010"
while [ $# -gt 0 ]; do
    case "$1" in
        -methods|-U|-np|-relax) [ $# -ge 2 ] || { echo "runMatrix.sh: $1 needs a value" >&2; exit 2; } ;;
    esac
    case "$1" in
        -methods) methods="$2"; shift 2 ;;
        -U) us="$2"; shift 2 ;;
        -np) np="$2"; shift 2 ;;
        -relax) relax="$2"; shift 2 ;;
        -compare) compare_only=1; shift ;;
        -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
        *) echo "runMatrix.sh: unknown option '$1' (see -h)" >&2; exit 2 ;;
    esac
done
tau_of() { # method U: 0.003 when the pair is in -relax
    case " $relax " in *" $1:$2 "*) echo 0.003 ;; esac
}
name_of() { # method U
    local tau
    tau=$(tau_of "$1" "$2")
    echo "${1}_U${2}_long$([ "$np" -gt 1 ] && echo "_np$np")_E1e5${tau:+_relax$tau}"
}
finished() { # run directory: a write at the window's end, 13 s
    [ -d "$1/13" ] || [ -d "$1/processor0/13" ]
}
status=0
if [ $compare_only -eq 0 ]; then
    for u in $us; do
        for m in $methods; do
            run="$tut/runs/$(name_of "$m" "$u")"
            if finished "$run"; then
                echo "runMatrix.sh: $(basename "$run") finished (a write at 13 s): skipped"
                continue
            fi
            echo "runMatrix.sh: $(date -u +%T) $(basename "$run")"
            tau=$(tau_of "$m" "$u")
            "$tut/Allrun" -mode long -young 1e5 -method "$m" -U "$u" -np "$np" ${tau:+-alphaRelax "$tau"} -continue || status=1
        done
    done
fi
done_runs=()
for d in "$tut"/runs/*_long*_E1e5*; do
    finished "$d" && [ -f "$d/results/bed.csv" ] && done_runs+=("$d")
done
if [ ${#done_runs[@]} -gt 0 ]; then
    /usr/bin/python3 "$here/compare.py" "$here/results/long" "${done_runs[@]}" || status=1
else
    echo "runMatrix.sh: no finished long run to compare yet"
fi
exit $status
