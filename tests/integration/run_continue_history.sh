#!/bin/bash
# A continued run keeps the DEM script's fix print history (issue 45 item 4): tutorials/ErgunTest
# with a `fix print ... file post/history.txt` line, run to 0.001 s and continued to 0.002 s; the
# file must hold the steps of both starts. Then a continuation that is refused (a script that does
# not read the restart) must leave every line of it in place.
# Prints PASS/FAIL lines and "N passed, N failed".
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$here/result.sh"
. "$top/etc/bashrc" || exit 1
work=$(mktemp -d /tmp/coarsedem-history.XXXXXX)
trap 'rm -rf "$work"' EXIT
c="$work/case"
cp -r "$top/tutorials/ErgunTest" "$c"
(cd "$c" && ./Allclean > /dev/null && cp -r 0.orig 0 && sed -i 's/INLET_VELOCITY/0.1/' 0/U && mkdir -p post &&
 sed -i 's/^endTime .*/endTime 0.001;/; s/^writeInterval .*/writeInterval 0.001;/' system/controlDict &&
 printf 'variable hstep equal step\nfix hist all print 25 "${hstep}" file post/history.txt screen no title "# step"\n' >> DEM/in.liggghts &&
 blockMesh > log.blockMesh 2>&1 && coarseDemFoam > log.first 2>&1) || { result fail "first start of the history case ($c/log.first)"; finish; }
steps() { grep -v '^#' "$c/post/history.txt" | awk '{print $1}' | tr '\n' ' '; }
first=$(steps)
(cd "$c" && sed -i 's/^endTime .*/endTime 0.002;/; s/^startFrom .*/startFrom latestTime;/' system/controlDict &&
 coarseDemFoam > log.second 2>&1) || { result fail "continued start of the history case"; tail -5 "$c/log.second"; finish; }
both=$(steps)
n1=$(echo $first | wc -w); n2=$(echo $both | wc -w)
if [ "$n1" -ge 5 ] && [ "${both#"$first"}" != "$both" ] && [ "$n2" -ge $((2 * n1 - 1)) ] &&
   grep -q "fix print file(s) are appended to" "$c/log.second"; then
    result ok "a continued run appends to the DEM script's fix print file: $n1 lines after the first start, $n2 after the second (steps ${both:0:40}...)"
else
    result fail "the fix print history after a continued run: '$first' then '$both'"
fi
# a refused continuation (the script no longer reads the restart): the history stays
before=$(steps)
(cd "$c" && sed -i 's/^endTime .*/endTime 0.003;/' system/controlDict &&
 sed -i 's/^if "${restarting} == 1" then "read_restart ${restart}" &/if "0 == 1" then "read_restart ${restart}" \&/' DEM/in.liggghts &&
 coarseDemFoam > log.third 2>&1)
rc=$?
after=$(steps)
if [ $rc -ne 0 ] && [ "$after" = "$before" ]; then
    result ok "a refused continuation (exit $rc) leaves the history's $n2 lines as they were"
else
    result fail "refused continuation: exit $rc, history '$before' -> '$after'"
fi
finish
