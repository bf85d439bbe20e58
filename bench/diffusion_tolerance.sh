#!/bin/bash
# bench/diffusion_tolerance.sh -- does the CG tolerance of the diffusion smoothing change a result?
#
# Runs the Mueller demo (tutorials/fluidizedBedMuller -mode demo -model diffusion -np 1: 0.1 s of the
# bubbling bed, b = 6 d) once per tolerance, each in its own copy of the tutorial under
# bench/work/diffusionTolerance/<tol>/, and compares the depth-averaged, binned profiles (gas
# fraction and particle v_z at the six MR heights) of each with those of the reference tolerance
# (the first of the list). The bed is chaotic: any difference in the smoothing, however small, grows
# until the runs are different samples of the same bed. A tolerance is harmless when its profiles
# differ from the reference's no more than those of a tighter tolerance do.
#
#   bench/diffusion_tolerance.sh [-tolerances "1e-10 1e-12 1e-6"]   (the first is the reference)
#
# Written: bench/results/diffusion_tolerance.csv (per tolerance, quantity and height: the RMS over the
# profile of its difference from the reference), diffusion_tolerance_timers.csv (the smoothing's
# share of each run: the solver's alphaP stage timer) and diffusion_tolerance_info.txt (command, commit).
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
tols="1e-10 1e-12 1e-6"
while [ $# -gt 0 ]; do
    case "$1" in
        -tolerances) tols="$2"; shift 2 ;;
        *) echo "usage: $0 [-tolerances \"REF T2 T3 ...\"]" >&2; exit 2 ;;
    esac
done
for t in $tols; do
    /usr/bin/python3 -c "import sys; t = float(sys.argv[1]); sys.exit(0 if 0 < t < 1 else 1)" "$t" 2> /dev/null ||
        { echo "bench/diffusion_tolerance: tolerance '$t' must be a number in (0, 1)" >&2; exit 2; }
done
work="$here/work/diffusionTolerance"
mkdir -p "$work" "$here/results"
for t in $tols; do
    d="$work/$t"
    rm -rf "$d"
    mkdir -p "$d/tutorials"
    cp -r "$root/tutorials/fluidizedBedMuller" "$d/tutorials/"
    rm -rf "$d/tutorials/fluidizedBedMuller/runs"
    sed -i "s|^diffusionProps .*|diffusionProps      { bandwidth 7.2e-3; tolerance $t; }   // b = 6 d|" \
        "$d/tutorials/fluidizedBedMuller/constant/couplingProperties"
    echo "bench/diffusion_tolerance: tolerance $t"
    ( cd "$d/tutorials/fluidizedBedMuller" &&
      COARSEDEM_DIR="$root" ./Allrun -mode demo -model diffusion -np 1 > "$d/log.Allrun" 2>&1 ) ||
        { echo "bench/diffusion_tolerance: the demo failed with tolerance $t ($d/log.Allrun)" >&2; exit 1; }
done
# shellcheck disable=SC2086
/usr/bin/python3 "$here/diffusion_tolerance.py" "$work" "$here/results" $tols || exit 1
{
    echo "command: bench/diffusion_tolerance.sh -tolerances \"$tols\""
    echo "commit: $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)$([ -n "$(git -C "$root" status --porcelain --untracked-files=no 2>/dev/null)" ] && echo -dirty)"
    echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
    echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$here/results/diffusion_tolerance_info.txt"
cat "$here/results/diffusion_tolerance.csv" "$here/results/diffusion_tolerance_timers.csv"
