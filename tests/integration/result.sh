# result.sh -- the PASS/FAIL bookkeeping of the integration scripts (sourced):
#   result ok|fail "message"    prints "PASS: message" or "FAIL: message" and counts it
#   finish                      prints "N passed, N failed" and exits (non-zero on any failure)
npass=0
nfail=0
result() {
    if [ "$1" = ok ]; then npass=$((npass + 1)); echo "PASS: $2"; else nfail=$((nfail + 1)); echo "FAIL: $2"; fi
}
finish() {
    echo "$npass passed, $nfail failed"
    [ "$nfail" -eq 0 ]
    exit $?
}
