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

. "$here/wmake_app.sh"
work="$project/platforms/tests/forceModels"
wmake_app "$here/forceModels/forceModelCheck" "$work" "the coupling library"
results_from < <(/usr/bin/python3 "$here/forceModels/check_lift.py" "$work/bin/forceModelCheck" 2>&1)
[ "$nread" -gt 0 ] || result fail "check_lift.py printed no result"
finish
