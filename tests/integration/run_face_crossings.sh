#!/bin/bash
# A coarse sphere (d = 2 mm in 1 mm cells) set up as a new user might (issue 45 item 10): runs that
# end with status 0 must say in their last lines what went wrong (the solver's faceCrossings report).
#   limiter   centre without background fields: the packing limiter moves most of the sphere's
#             volume at every coupling
#   held      the sphere driven across one cell face and back at every coupling (the DEM's fix move,
#             standing in for a sphere trapped at a face by its own wake)
#   quiet     the shipped set-up (bigParticle n = 5, background fields) settling freely: neither
# Each case: a copy of tutorials/settlingTest, 0.05 s (50 couplings, reports at 0.025 s and at the end).
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$top/etc/bashrc" || exit 1
. "$here/result.sh"
work=$(mktemp -d /tmp/coarsedem-faces.XXXXXX)
trap 'rm -rf "$work"' EXIT

base="$work/base"
cp -r "$top/tutorials/settlingTest" "$base"
(cd "$base" && ./Allclean > /dev/null && cp -r 0.orig 0 && mkdir -p post &&
 sed -i 's/^endTime .*/endTime         0.05;/; s/^writeInterval .*/writeInterval   0.025;/' system/controlDict &&
 sed -i '/^blocks/s/(10 10 100)/(20 20 200)/' system/blockMeshDict &&
 blockMesh > log.blockMesh 2>&1) || { result fail "face crossings: could not prepare the base case"; finish; }

# run NAME 'sed on couplingProperties' ['sed on DEM/in.liggghts']: the case's log in $work/NAME/log
run() {
    local c="$work/$1"
    cp -r "$base" "$c"
    [ -n "$2" ] && sed -i "$2" "$c/constant/couplingProperties"
    [ -n "${3:-}" ] && sed -i "$3" "$c/DEM/in.liggghts"
    (cd "$c" && timeout 300 coarseDemFoam > log 2>&1)
}
# the lines after the solver's End: what a user reads last
last_lines() { sed -n '/^End: /,$p' "$work/$1/log"; }

no_background='s/^voidFractionModel .*/voidFractionModel   centre;/; s/^backgroundFields .*/backgroundFields    off;/'

run limiter "$no_background"
rc=$?
if [ $rc -eq 0 ] && last_lines limiter | grep -q "^Warning: the packing limiter moved more than half of the solid volume in 51 of 51 couplings since the start: the centre kernel is narrower than the particles"; then
    result ok "limiter: centre at d/dx = 2 ends saying the limiter moved most of the solid at every coupling"
else
    result fail "limiter: exit $rc, last lines: $(last_lines limiter | tr '\n' ' ' | cut -c1-400)"
fi

# z = 0.1 m +- 0.1 mm at the couplings (every 200 DEM steps): the face at z = 0.1 m, crossed each time
held_dem='s|^fix             integr all nve/sphere|variable zheld equal -0.07+1e-4*cos(PI*step/200)\nfix             integr all move variable NULL NULL v_zheld NULL NULL NULL|'
run held "$no_background" "$held_dem"
rc=$?
if [ $rc -eq 0 ] && last_lines held | grep -q "^Warning: particles held at a cell face: particle 1 went back across the same face at [0-9.]* % of its recent couplings"; then
    result ok "held: a sphere crossing one face at every coupling ends saying it was held there, with the particle"
else
    result fail "held: exit $rc, last lines: $(last_lines held | tr '\n' ' ' | cut -c1-400)"
fi
if grep -q "^Face crossings since t = 0.025: 25, back and forth across the same face 25 (100 %)" "$work/held/log"; then
    result ok "held: each of the 25 crossings of the second interval counted as back and forth"
else
    result fail "held: the second interval's line: $(grep '^Face crossings since t = 0.025' "$work/held/log")"
fi

run quiet ''
rc=$?
if [ $rc -eq 0 ] && grep -q "^End: " "$work/quiet/log" && ! grep -q "^Warning: particles held\|^Warning: the packing limiter" "$work/quiet/log" &&
   last_lines quiet | grep -q "^Face crossings since the start: .*; 0 particle(s) held at a face; the limiter moving over half the solid in 0 of 51 couplings"; then
    result ok "quiet: the shipped set-up settles without either warning"
else
    result fail "quiet: exit $rc, warnings: $(grep '^Warning: \(particles held\|the packing\)' "$work/quiet/log" | head -2)"
fi
finish
