#!/bin/bash
# Link check of the build spine: an OpenFOAM application (wmake_link/coarseDemLinkCheck) that
# includes and links OpenFOAM (Debian v1912), LIGGGHTS with fix couple/coarse and the C core,
# built with the project's wmake environment (etc/wmakeEnv) and run serially.
# Its Make/options is the reference for the solvers' include and library lines.
#
#   tests/integration/run_wmake_link.sh        (after ./Allwmake)
# Exit status 0 only if everything passed; the last line is "N passed, N failed".
set -uo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
project="$(cd "$here/../.." && pwd)"
. "$here/result.sh"

. "$here/wmake_app.sh"
work="$project/platforms/tests/wmake_link"
wmake_app "$here/wmake_link/coarseDemLinkCheck" "$work" "OpenFOAM + LIGGGHTS + core"
for f in "$COARSEDEM_LIGGGHTS_DIR/lib/libliggghts.so" "$project/src/core/build/libcoarsedem.a"; do
    [ -f "$f" ] || { result fail "missing $f (run ./Allwmake)"; finish; }
done

cd "$work" || exit 1
if "$work/bin/coarseDemLinkCheck" -help > log.help 2>&1 && grep -q 'Usage: coarseDemLinkCheck' log.help; then
    result ok "coarseDemLinkCheck -help (OpenFOAM argList and etc/ found)"
else
    result fail "coarseDemLinkCheck -help (see $work/log.help)"
fi
if "$work/bin/coarseDemLinkCheck" > log.run 2>&1 && grep -q 'coarseDemLinkCheck: OK' log.run; then
    result ok "coarseDemLinkCheck ran OpenFOAM, the core and LIGGGHTS (fix couple/coarse) in one process"
else
    tail -n 20 log.run
    result fail "coarseDemLinkCheck run (see $work/log.run)"
fi
finish
