#!/bin/bash
# The binary bed's small species alone (issue 41): tutorials/liquidFluidizedBed -species small in its
# short mode (0.5 s + 0.3 s), divided, 0.015 m/s, in a 5 mm tube (10610 spheres of 0.3 mm: a quarter
# of Table III's, the same solid fraction; about 3-4 min on one core). The tutorial's own checks:
# particles kept, the pressure drop and the walls' share make up the buoyant weight, the walls carry
# under 2 %, the fluid carries the layer on the distributor, the bed expanded, the particles move (a
# frozen bed fails). Its voidage check is not counted: this bed stays about 0.07 denser than its drag
# law's equilibrium (the water circulates through looser columns and bypasses the dense ones:
# tutorials/liquidFluidizedBed/README.md, the small species alone: every cell-by-cell method, any mesh,
# walls or CFD step tried; the smoothed exchange removes the columns), a defect still open in issue 41;
# the line is printed as KNOWN with its numbers. Prints "N passed, N failed".
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$top/etc/bashrc" || exit 1
tut="$top/tutorials/liquidFluidizedBed"
log=$(mktemp /tmp/coarsedem-smallbed.XXXXXX)
trap 'rm -f "$log"' EXIT
"$tut/Allrun" -species small -mode short -U 0.015 -width 5 -method divided > "$log" 2>&1
. "$here/result.sh"   # result ok|fail, npass/nfail, finish
results_from -prefix "small species: " -quiet -known "FAIL: *bed voidage*" < "$log"
# the run and its checks must have happened: six counted checks (the seventh, the voidage, is KNOWN)
if [ $((npass + nfail)) -lt 6 ]; then
    result fail "small species: the short run printed $((npass + nfail)) counted checks, not 6:"; tail -15 "$log" | sed 's/^/    /'
fi
rm -rf "$tut/runs/divided_A_U0.015_short_small_w5"
finish
