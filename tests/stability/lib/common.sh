# common.sh -- helpers of the stability suite's solver-level scenes (sourced by tests/stability/run).
#   make_case <template> <case dir> KEY=value ...     mkcase.py
#   run_case <case dir> [np]                          blockMesh, 0/, (decomposePar), coarseDemFoam;
#                                                     writes <case>/log.coarseDemFoam and <case>/wall_time;
#                                                     returns the solver's exit status
#   emit "<PASS|FAIL line>"                           print and count one result line

STAB_LIB="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
PY=/usr/bin/python3

make_case() {
    local tmpl="$1" case="$2"; shift 2
    $PY "$STAB_LIB/mkcase.py" "$STAB_DIR/cases/$tmpl" "$case" "$@"
}

run_case() {
    local case="$1" np="${2:-1}" start rc
    (
        cd "$case" || exit 1
        blockMesh > log.blockMesh 2>&1 || { echo "blockMesh failed" > log.coarseDemFoam; exit 90; }
        rm -rf 0 && cp -r 0.orig 0
        start=$(date +%s.%N)
        if [ "$np" -gt 1 ]; then
            decomposePar -force > log.decomposePar 2>&1 || { echo "decomposePar failed" > log.coarseDemFoam; exit 91; }
            timeout "${STAB_TIMEOUT:-600}" mpirun --allow-run-as-root --oversubscribe -np "$np" \
                coarseDemFoam -parallel > log.coarseDemFoam 2>&1
        else
            timeout "${STAB_TIMEOUT:-600}" coarseDemFoam > log.coarseDemFoam 2>&1
        fi
        rc=$?
        echo "$(date +%s.%N) - $start" | bc > wall_time
        echo "$rc" > exit_status
        exit $rc
    )
}

# Count PASS/FAIL lines as they are printed (the runner's totals).
emit() {
    local line
    while IFS= read -r line; do
        echo "$line"
        case "$line" in
            PASS*) STAB_PASS=$((STAB_PASS + 1)) ;;
            FAIL*) STAB_FAIL=$((STAB_FAIL + 1)) ;;
        esac
    done <<< "$1"
}
