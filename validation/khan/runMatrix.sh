#!/bin/bash
# validation/khan/runMatrix.sh -- the binary bed as the paper ran it (issue 41): methods x velocities
# in binaryBedKhan's long mode (3 s + 10 s window) at E = 1e5 Pa, one run after the other, each
# continued where it stopped (a session's end stops a run at any moment: run the same command again).
# Finished runs (results/bed.csv there) are skipped. At the end, compare.py over every finished long
# run into validation/khan/results/long/.
#
#   validation/khan/runMatrix.sh [-methods "divided bigParticle diffusion"] [-U "0.010 0.015 0.020 0.025"] [-np N]
#   validation/khan/runMatrix.sh -compare      only the comparison of the finished runs
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
tut="$top/tutorials/binaryBedKhan"
methods="divided bigParticle diffusion"; us="0.010 0.015 0.020 0.025"; np=2; compare_only=0
while [ $# -gt 0 ]; do
    case "$1" in
        -methods|-U|-np) [ $# -ge 2 ] || { echo "runMatrix.sh: $1 needs a value" >&2; exit 2; } ;;
    esac
    case "$1" in
        -methods) methods="$2"; shift 2 ;;
        -U) us="$2"; shift 2 ;;
        -np) np="$2"; shift 2 ;;
        -compare) compare_only=1; shift ;;
        -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
        *) echo "runMatrix.sh: unknown option '$1' (see -h)" >&2; exit 2 ;;
    esac
done
name_of() { # method U
    echo "${1}_U${2}_long$([ "$np" -gt 1 ] && echo "_np$np")_E1e5"
}
status=0
if [ $compare_only -eq 0 ]; then
    for u in $us; do
        for m in $methods; do
            run="$tut/runs/$(name_of "$m" "$u")"
            if [ -f "$run/results/bed.csv" ]; then
                echo "runMatrix.sh: $(basename "$run") finished (results/bed.csv): skipped"
                continue
            fi
            echo "runMatrix.sh: $(date -u +%T) $(basename "$run")"
            "$tut/Allrun" -mode long -young 1e5 -method "$m" -U "$u" -np "$np" -continue || status=1
        done
    done
fi
finished=()
for d in "$tut"/runs/*_long*_E1e5; do
    [ -f "$d/results/bed.csv" ] && finished+=("$d")
done
if [ ${#finished[@]} -gt 0 ]; then
    /usr/bin/python3 "$here/compare.py" "$here/results/long" "${finished[@]}" || status=1
else
    echo "runMatrix.sh: no finished long run to compare yet"
fi
exit $status
