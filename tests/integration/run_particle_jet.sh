#!/bin/bash
# The particle-laden jet (tutorials/particleJet) in its demo: coarse-grained parcels (factor 3,
# Model B, Gidaspow drag with the primary diameter, RANS k-epsilon) fed into a pipe by LIGGGHTS
# (fix insert/stream), through the free jet, deleted at 19.5 D; stopped at 0.02 s and continued to
# 0.045 s. Checks: the coupling's particle inventory against LIGGGHTS' own counts at the end; nothing
# lost; the mass balance and the solid volume to round-off; the solid mass flow through the planes
# the demo fills (-5 D, 0.1 D) within 3 % of the feed's 0.634 g/s; the factor named in the log.
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$top/etc/bashrc" || exit 1
. "$here/result.sh"
work=/tmp/coarsedem-particleJet
exec 9> "$work.lock"
flock 9
rm -rf "$work"; mkdir -p "$work"
(cd "$top/tutorials/particleJet" && cp -r 0.orig DEM constant system Allrun Allclean inletProfile.py postprocess.py "$work/")
run="$work/runs/demo"
if "$work/Allrun" -run demo -endTime 0.02 > "$work/run1.log" 2>&1 &&
   "$work/Allrun" -run demo -continue > "$work/run2.log" 2>&1; then
    result ok "particleJet demo: ran to 0.02 s, stopped, continued to 0.045 s"
else
    result fail "particleJet demo: Allrun failed (see $work/run1.log, run2.log)"
    finish
fi
log="$run/log.coarseDemFoam"
grep -q "coarse-grained: each grain 3 real diameters, the drag of 27 real particles" "$log" &&
    result ok "particleJet demo: the log names the coarse-graining factor 3 (the drag of 27 real particles per grain)" ||
    result fail "particleJet demo: no coarse-graining line with factor 3 in $log"

# the last inventory against the DEM's counts at the same time (post/counts.txt, every coupling)
results_from < <(/usr/bin/python3 - "$run" <<'PY'
import re, sys
run = sys.argv[1]
t, inv = None, None
for line in open(run + "/log.coarseDemFoam", errors="replace"):
    if line.startswith("Time = "):
        t = float(line.split()[2])
    elif line.startswith("Particle inventory:"):
        inv = (t, line.strip())
t, line = inv
n = int(re.search(r"inventory: (\d+) particles", line).group(1))
fed = int(re.search(r"entered feed (\d+)", line).group(1))
out = int(re.search(r"left exit (\d+)", line).group(1))
lost = int(re.search(r"lost (\d+)", line).group(1))
err = float(re.search(r"rel\. err ([-+.eE0-9]+)", line).group(1))
offset = 0.0
rows = [list(map(float, l.split())) for l in open(run + "/post/counts.txt") if l.strip() and not l.startswith("#")]
row = min(rows, key=lambda r: abs(r[0] + offset - t))
ok = n == int(row[1]) and out == int(row[2])
print("%s: particleJet demo: inventory at t = %g s: %d grains, %d fed, %d left through the exit; the DEM at t = %g s: %d grains, %d deleted at the exit"
      % ("PASS" if ok else "FAIL", t, n, fed, out, row[0], row[1], row[2]))
ok = lost == 0 and fed == n + out
print("%s: particleJet demo: none lost (%d), fed = held + left (%d = %d + %d)" % ("PASS" if ok else "FAIL", lost, fed, n, out))
print("%s: particleJet demo: the inventory's mass balance to round-off (rel. err %g)" % ("PASS" if abs(err) < 1e-10 else "FAIL", err))
cpl = [l for l in open(run + "/log.coarseDemFoam", errors="replace") if l.startswith("Coupling:")][-1]
m = re.search(r"solid volume particles ([-+.eE0-9]+) cells ([-+.eE0-9]+) \(rel\. err ([-+.eE0-9]+)\)", cpl)
print("%s: particleJet demo: the grains' solid volume in the cells to round-off (%s m3, rel. err %s)"
      % ("PASS" if float(m.group(3)) < 1e-12 else "FAIL", m.group(1), m.group(3)))
PY
)
/usr/bin/python3 "$work/postprocess.py" -o "$work/results" -window 0.02 0.045 "$run" > "$work/post.log" 2>&1 ||
    result fail "particleJet demo: postprocess.py failed (see $work/post.log)"
results_from < <(/usr/bin/python3 - "$work/results/summary.csv" <<'PY'
import csv, sys
row = next(csv.DictReader(open(sys.argv[1])))
feed = float(row["mdot_feed_gps"])
fed = float(row["mdot_in_gps"])
print("%s: particleJet demo: the feed's rate in 0.02-0.045 s from the inventory %.4f g/s vs fix insert/stream's massrate %.4f g/s (%+.2f %%, tolerance 1 %%)"
      % ("PASS" if abs(fed / feed - 1) <= 0.01 else "FAIL", fed, feed, 100 * (fed / feed - 1)))
for tag in ("m5D", "0.1D"):
    m = float(row["mdot_%s_gps" % tag])
    print("%s: particleJet demo: solid mass flow through the plane %s in 0.02-0.045 s %.4f g/s vs the feed %.4f g/s (%+.2f %%, tolerance 3 %%; %s grains)"
          % ("PASS" if abs(m / feed - 1) <= 0.03 else "FAIL", tag, m, feed, 100 * (m / feed - 1), row["grains_" + tag]))
PY
)
finish
