# result.sh -- the PASS/FAIL bookkeeping of the integration scripts (sourced):
#   result ok|fail "message"    prints "PASS: message" or "FAIL: message" and counts it
#   results_from                reads a checker's "PASS: ..."/"FAIL: ..." lines on stdin and counts each
#                               as result does (other lines echoed, indented); nread = how many
#   finish                      prints "N passed, N failed" and exits (non-zero on any failure)
npass=0
nfail=0
result() {
    if [ "$1" = ok ]; then npass=$((npass + 1)); echo "PASS: $2"; else nfail=$((nfail + 1)); echo "FAIL: $2"; fi
}
results_from() {
    local line
    nread=0
    while IFS= read -r line; do
        case "$line" in
            PASS:*) result ok "${line#PASS: }"; nread=$((nread + 1)) ;;
            FAIL:*) result fail "${line#FAIL: }"; nread=$((nread + 1)) ;;
            *) echo "    $line" ;;
        esac
    done
}
finish() {
    echo "$npass passed, $nfail failed"
    [ "$nfail" -eq 0 ]
    exit $?
}
