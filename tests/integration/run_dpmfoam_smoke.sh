#!/bin/bash
# Smoke test of the DPMFoam baseline chain (validation/muller/dpmFoam): Debian's DPMFoam, the
# profile and comparison scripts, and restarts that change the number of ranks.
#
#   tests/integration/run_dpmfoam_smoke.sh       (after ./Allwmake; about a minute)
#
# In a copy of validation/muller/dpmFoam under platforms/tests/ (a user's runs/ are left alone):
# 1. `Allrun -mode smoke` (serial) ends with exit 0, all 9240 particles in the samples and an
#    errors.csv with the gas-fraction and v_z rows;
# 2. with its last write removed, `-continue -np 2` decomposes the write before it (0.0005 s) for 2
#    ranks, which run to the end (0.001 s): exit 0, all particles;
# 3. `-continue -np 2` again, now from the ranks' own last write (which has no Uwall, the wall
#    velocity the collision model reads): Uwall is carried over and the run ends with exit 0;
# 4. a run whose ranks got further than its serial data is refused by a serial `-continue`, with a
#    message saying what to do.
# Exit status 0 only if everything passed; the last line is "N passed, N failed".
set -uo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
project="$(cd "$here/../.." && pwd)"
# shellcheck source=../../etc/bashrc
. "$project/etc/bashrc"
. "$here/result.sh"
command -v DPMFoam > /dev/null || { result fail "DPMFoam not found (Debian's openfoam package; ./Allwmake installs it)"; finish; }

work="$project/platforms/tests/dpmFoam"
rm -rf "$work"
mkdir -p "$(dirname "$work")"
cp -r "$project/validation/muller/dpmFoam" "$work"
rm -rf "$work/runs"
cd "$work" || exit 1
export COARSEDEM_DIR="$project"
run=runs/dpmFoam_WenYu_dx1_U0.9_smoke

./Allrun -mode smoke > log.serial 2>&1
rc=$?
parcels=$(grep -h 'Current number of parcels' "$run/log.DPMFoam" 2>/dev/null | tail -1 | awk '{print $NF}')
rows=$(grep -cE '^(void_fraction|vz_particle_m_per_s),' "$run/results/comparison/errors.csv" 2>/dev/null)
if [ $rc -eq 0 ] && [ "$parcels" = 9240 ] && [ "${rows:-0}" -ge 2 ]; then
    result ok "serial smoke: exit 0, 9240 parcels, errors.csv with $rows gas-fraction/v_z rows"
else
    result fail "serial smoke: exit $rc, parcels '${parcels:-none}', errors.csv rows ${rows:-0} (see $work/log.serial)"
fi

# the serial run's last write removed: the ranks must compute 0.0005 -> 0.001 themselves
rm -rf "$run/0.001"
./Allrun -mode smoke -continue -np 2 > log.np2 2>&1
rc=$?
n=$(ls -d "$run"/processor* 2>/dev/null | wc -l)
sub=$(sed -n 's/^numberOfSubdomains *\([0-9]*\);/\1/p' "$run/system/decomposeParDict")
parcels=$(grep -h 'Current number of parcels' "$run/log.DPMFoam" 2>/dev/null | tail -1 | awk '{print $NF}')
if [ $rc -eq 0 ] && [ "$n" -eq 2 ] && [ "$sub" = 2 ] && [ -d "$run/processor1/0.001" ] && [ "$parcels" = 9240 ]; then
    result ok "serial run continued with -np 2 from 0.0005 s: decomposed for 2 ranks, run to 0.001 s, 9240 parcels"
else
    result fail "continue with -np 2: exit $rc, $n processor directories, numberOfSubdomains '$sub'," \
        "parcels '${parcels:-none}' (see $work/log.np2)"
fi

# again on the same ranks, from their own last write (the solver writes no Uwall there)
./Allrun -mode smoke -continue -np 2 > log.np2again 2>&1
rc=$?
if [ $rc -eq 0 ] && [ -f "$run/processor0/0.001/Uwall" ] && [ -f "$run/processor1/0.001/Uwall" ]; then
    result ok "continued again on 2 ranks from their own write: Uwall carried over, exit 0"
else
    result fail "continue again with -np 2: exit $rc, Uwall in processor*/0.001: $(ls "$run"/processor*/0.001/Uwall 2>/dev/null | wc -l) of 2 (see $work/log.np2again)"
fi

# as if the ranks had got further than the serial data: a serial continue must stop and say why
mkdir -p "$run"/processor{0,1}/0.0015
./Allrun -mode smoke -continue > log.refused 2>&1
rc=$?
if [ $rc -ne 0 ] && grep -q 'continue with -np 2, or run reconstructPar' log.refused; then
    result ok "serial continue of a run that got further on 2 ranks: refused, saying what to do"
else
    result fail "serial continue of a run further on 2 ranks: exit $rc, message: $(tail -1 log.refused)"
fi
finish
