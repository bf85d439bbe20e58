#!/bin/bash
# The force models that are not drag laws, evaluated as the solver selects them: forceModels/
# forceModelCheck (an OpenFOAM application linked with the coupling library) is built with wmake and
# fed particles; check_lift.py compares liftForce with Saffman's lift and Mei's correction.
#
#   tests/integration/run_force_models.sh        (after ./Allwmake)
# Exit status 0 only if everything passed; the last line is "N passed, N failed".
set -uo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
project="$(cd "$here/../.." && pwd)"
. "$here/result.sh"

# shellcheck source=../../etc/wmakeEnv
if ! . "$project/etc/wmakeEnv"; then
    result fail "etc/wmakeEnv: no OpenFOAM build environment (run ./Allwmake)"
    finish
fi
work="$project/platforms/tests/forceModels"
rm -rf "$work"
mkdir -p "$work/bin"
cp -r "$here/forceModels/forceModelCheck" "$work/"
export FOAM_USER_APPBIN="$work/bin"    # keep the check out of the project's bin/
if (cd "$work/forceModelCheck" && wmake) > "$work/log.wmake" 2>&1; then
    result ok "forceModelCheck compiled and linked with the coupling library"
else
    tail -n 30 "$work/log.wmake"
    result fail "wmake of forceModelCheck failed (see $work/log.wmake)"
    finish
fi
results_from < <(/usr/bin/python3 "$here/forceModels/check_lift.py" "$work/bin/forceModelCheck" 2>&1)
[ "$nread" -gt 0 ] || result fail "check_lift.py printed no result"
finish
