#!/bin/bash
# Open systems (tutorials/feedAndDrain): particles inserted by LIGGGHTS and deleted at a drain plane
# are counted by the coupling where they entered and left (openSystem in couplingProperties):
#   - serial, on 2 ranks split across the fall (particles change rank: not counted as entering or
#     leaving) and stopped at 0.3 s then continued (the totals are kept over the restart): the
#     inventory equals LIGGGHTS' own counts (check.py) and the mass balance holds to round-off;
#   - a drain box that misses the drain plane: the run stops at the first particle that leaves,
#     naming it and openSystem;
#   - the DEM not deleting at the drain (delete_atoms no): warned once, naming the outlet;
#   - an outlet box outside the mesh, and a misspelt entry of a region: errors naming the entry;
#   - the water's RAS k-epsilon model (Allrun -kEpsilon) runs with the coupling.
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$top/etc/bashrc" || exit 1
. "$here/result.sh"
work=/tmp/coarsedem-feedAndDrain
exec 9> "$work.lock"
flock 9
rm -rf "$work"; mkdir -p "$work"
# variant NAME: a copy of the tutorial (without its run products) in $work/NAME
variant() {
    mkdir -p "$work/$1"
    (cd "$top/tutorials/feedAndDrain" && cp -r 0.orig DEM constant system Allrun Allclean check.py "$work/$1/")
    rm -f "$work/$1"/system/*.orig "$work/$1"/constant/*.orig
    rm -rf "$work/$1/constant/polyMesh"
}
# check DIR: check.py's lines, counted
check() { results_from < <(/usr/bin/python3 "$1/check.py" "$1"); }
cp_box() { sed -i "s|outlets { drain { box [^;]*; } }|outlets { drain { $2 } }|" "$work/$1/constant/couplingProperties"; }

for v in serial np2; do
    variant $v
    np=1; [ $v = np2 ] && np=2
    "$work/$v/Allrun" -np $np > "$work/$v.log" 2>&1 || result fail "feedAndDrain $v: Allrun failed (see $work/$v.log)"
    check "$work/$v"
done

# the water's k-epsilon model (the round-jet constants of Weaver & Miskovic 2023) runs with the
# coupling: selected as in OpenFOAM, its coefficients as given, the same inventory
variant kEpsilon
if "$work/kEpsilon/Allrun" -kEpsilon > "$work/kEpsilon.log" 2>&1 &&
   grep -q "Selecting RAS turbulence model kEpsilon" "$work/kEpsilon/log.coarseDemFoam" &&
   grep -A3 "^kEpsilonCoeffs" "$work/kEpsilon/log.coarseDemFoam" | grep -q "C1 *1.52;"; then
    result ok "feedAndDrain -kEpsilon: coarseDemFoam ran with RAS kEpsilon, C1 1.52 C2 1.90"
else
    result fail "feedAndDrain -kEpsilon: the run failed or did not use kEpsilon with C1 1.52 (see $work/kEpsilon/log.coarseDemFoam)"
fi
check "$work/kEpsilon"

variant restart
if "$work/restart/Allrun" -endTime 0.3 > "$work/restart.log" 2>&1 &&
   "$work/restart/Allrun" -continue > "$work/restart2.log" 2>&1; then
    result ok "feedAndDrain restart: stopped at 0.3 s and continued from there to the end"
    # the totals of 0.3 s were read: every particle entered before the stop, and the check holds
    check "$work/restart"
else
    result fail "feedAndDrain restart: a run failed (see $work/restart.log, $work/restart2.log)"
fi

variant loss
cp_box loss "box (0 0 0.050) (0.020 0.020 0.060);"
if ! "$work/loss/Allrun" > "$work/loss.log" 2>&1 &&
   grep -q "particle(s) left the DEM between time .* outside every outlet of openSystem in .*couplingProperties.* (the first: particle [0-9]*, last seen at" "$work/loss/log.coarseDemFoam"; then
    result ok "feedAndDrain: a particle leaving outside every outlet stops the run, naming it: $(grep -o 'the first: particle [0-9]*' "$work/loss/log.coarseDemFoam" | head -1)"
else
    result fail "feedAndDrain: a particle leaving outside every outlet did not stop the run with its message (see $work/loss/log.coarseDemFoam)"
fi

variant pileup
sed -i 's/delete_atoms yes/delete_atoms no/' "$work/pileup/DEM/in.liggghts"
"$work/pileup/Allrun" -endTime 0.5 > "$work/pileup.log" 2>&1
n=$(grep -c "outlet openSystem/outlets/drain of .* has removed no particle since the run started, while the particles inside its box" "$work/pileup/log.coarseDemFoam")
[ "$n" = 1 ] && result ok "feedAndDrain: an outlet where the DEM removes nothing while particles pile up is warned once, naming it" ||
    result fail "feedAndDrain: the pile-up warning was printed $n times, not once (see $work/pileup/log.coarseDemFoam)"

variant outside
cp_box outside "box (0 0 -0.2) (0.020 0.020 -0.1);"
(cd "$work/outside" && cp -r 0.orig 0 && mkdir -p post && blockMesh > log.blockMesh 2>&1 && coarseDemFoam > log.coarseDemFoam 2>&1)
grep -q "openSystem/outlets/drain/box (0 0 -0.2) (0.02 0.02 -0.1) in .*couplingProperties.* lies outside the mesh" "$work/outside/log.coarseDemFoam" &&
    result ok "feedAndDrain: an outlet box outside the mesh is refused, naming openSystem/outlets/drain/box" ||
    result fail "feedAndDrain: an outlet box outside the mesh was not refused by name (see $work/outside/log.coarseDemFoam)"

variant misspelt
sed -i 's|outlets { drain { box|outlets { drain { boxx|' "$work/misspelt/constant/couplingProperties"
(cd "$work/misspelt" && cp -r 0.orig 0 && mkdir -p post && blockMesh > log.blockMesh 2>&1 && coarseDemFoam > log.coarseDemFoam 2>&1)
grep -q "unknown entry boxx in .*couplingProperties.openSystem.outlets.drain" "$work/misspelt/log.coarseDemFoam" &&
    result ok "feedAndDrain: a misspelt entry of an outlet is refused, naming it" ||
    result fail "feedAndDrain: a misspelt entry of an outlet was not refused by name (see $work/misspelt/log.coarseDemFoam)"
finish
