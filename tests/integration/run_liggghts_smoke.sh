#!/bin/bash
# Smoke test of the in-process DEM (LIGGGHTS as a library + fix couple/coarse).
#
#   tests/integration/run_liggghts_smoke.sh       (after ./Allwmake)
#
# 1. `liggghts -h` lists fix couple/coarse;
# 2. an unknown keyword of fix couple/coarse is rejected with a LIGGGHTS error;
# 3. liggghts_smoke/driver.cpp, compiled here with mpicxx against platforms/liggghts, runs the
#    coupling cycle (pull, push, run) serially and with 2 MPI ranks and checks the physics
#    (see driver.cpp).
# Exit status 0 only if everything passed; the last line is "N passed, N failed".
set -uo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
project="$(cd "$here/../.." && pwd)"
# shellcheck source=../../etc/bashrc
. "$project/etc/bashrc"

lig="$COARSEDEM_LIGGGHTS_DIR"
. "$here/result.sh"

if [ ! -x "$lig/bin/liggghts" ] || [ ! -f "$lig/lib/libliggghts.so" ]; then
    result fail "no LIGGGHTS build in $lig: run ./Allwmake first"
    finish
fi

work="$project/platforms/tests/liggghts_smoke"
rm -rf "$work"
mkdir -p "$work"
cp "$here/liggghts_smoke/in.smoke" "$work/"
cd "$work" || exit 1

# mpirun refuses root unless told; the tests run as root on the build machines
mpirun_np2=(mpirun --allow-run-as-root --oversubscribe -np 2)

# ---- 1. the style is compiled in
help="$(liggghts -log none -h 2>&1 || true)"
if grep -q 'couple/coarse' <<< "$help"; then
    result ok "liggghts -h lists fix couple/coarse"
else
    result fail "liggghts -h does not list fix couple/coarse"
fi

# ---- 2. unknown keyword rejected
sed 's|^fix *cpl all couple/coarse.*|fix cpl all couple/coarse no_such_keyword 1|' in.smoke > in.badkeyword
if liggghts -log none -in in.badkeyword > out.badkeyword 2>&1; then
    result fail "fix couple/coarse accepted an unknown keyword (see $work/out.badkeyword)"
elif grep -q "unknown keyword 'no_such_keyword'" out.badkeyword; then
    result ok "fix couple/coarse rejects an unknown keyword with a LIGGGHTS error"
else
    result fail "unknown keyword: no 'unknown keyword' message (see $work/out.badkeyword)"
fi

# ---- 3. in-process driver
if mpicxx -std=c++11 -O1 -Wall -DOMPI_SKIP_MPICXX -DMPICH_SKIP_MPICXX \
       -I"$lig/include/liggghts" "$here/liggghts_smoke/driver.cpp" \
       -L"$lig/lib" -lliggghts -Wl,-rpath,"$lig/lib" -o driver > out.compile 2>&1; then
    result ok "driver compiled and linked with mpicxx against $lig"
else
    cat out.compile
    result fail "driver did not compile (see $work/out.compile)"
    finish
fi

run_driver() { # label command...
    local label="$1"; shift
    "$@" ./driver in.smoke > "out.$label" 2>&1
    local rc=$?
    grep -E '^(PASS|FAIL):' "out.$label" | sed "s/^/  [$label] /"
    if [ "$rc" -eq 0 ] && grep -q ' 0 failed' "out.$label"; then
        result ok "driver $label"
    else
        tail -n 20 "out.$label"
        result fail "driver $label (exit $rc, see $work/out.$label)"
    fi
}
run_driver serial
run_driver np2 "${mpirun_np2[@]}"

finish
