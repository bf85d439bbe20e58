# result.sh -- the PASS/FAIL bookkeeping of the integration scripts (sourced):
#   result ok|fail "message"    prints "PASS: message" or "FAIL: message" and counts it
#   results_from [-prefix P] [-quiet] [-known GLOB]...
#                               reads a checker's "PASS: ..."/"FAIL: ..." lines on stdin and counts each
#                               as result does, P before its text (other lines echoed, indented, unless
#                               -quiet); a FAIL line matching a GLOB is a known defect of an open issue:
#                               printed as "KNOWN (issue 41, not counted): ...", not counted; nread = how
#                               many were counted
#   finish                      prints "N passed, N failed" and exits (non-zero on any failure)
npass=0
nfail=0
result() {
    if [ "$1" = ok ]; then npass=$((npass + 1)); echo "PASS: $2"; else nfail=$((nfail + 1)); echo "FAIL: $2"; fi
}
results_from() {
    local line prefix= quiet=0 known=() k
    while [ $# -gt 0 ]; do
        case "$1" in
            -prefix) prefix="$2"; shift 2 ;;
            -quiet) quiet=1; shift ;;
            -known) known+=("$2"); shift 2 ;;
            *) echo "results_from: unknown option '$1'" >&2; return 2 ;;
        esac
    done
    nread=0
    while IFS= read -r line; do
        if [[ "$line" == FAIL:* ]]; then
            for k in "${known[@]}"; do
                # shellcheck disable=SC2053  # k is a glob
                [[ "$line" == $k ]] && { echo "KNOWN (issue 41, not counted): ${line#FAIL: }"; continue 2; }
            done
        fi
        case "$line" in
            PASS:*) result ok "$prefix${line#PASS: }"; nread=$((nread + 1)) ;;
            FAIL:*) result fail "$prefix${line#FAIL: }"; nread=$((nread + 1)) ;;
            *) [ "$quiet" -eq 1 ] || echo "    $line" ;;
        esac
    done
}
finish() {
    echo "$npass passed, $nfail failed"
    [ "$nfail" -eq 0 ]
    exit $?
}
