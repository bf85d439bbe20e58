#!/bin/bash
# The Mueller bed in its demo mode (README command 1): runs end to end (settled bed, coupled run,
# profiles, comparison with the MR data) and writes both profiles at every height, finite, with
# the solid volume conserved and the inflow equal to the superficial velocity of the experiment.
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$top/etc/bashrc" || exit 1
case_dir="$top/tutorials/fluidizedBedMuller"
"$case_dir/Allrun" -mode demo > /tmp/coarsedem-muller-demo.log 2>&1 ||
    { echo "FAIL: Muller demo run (see /tmp/coarsedem-muller-demo.log)"; tail -5 /tmp/coarsedem-muller-demo.log; exit 1; }
run="$case_dir/runs/bigParticle_dx1_U0.9_demo"
/usr/bin/python3 - "$run" <<'PYEOF'
import math, os, re, struct, sys
run = sys.argv[1]
status = 0
for h in ("15", "16.4", "20", "25", "31.2", "35"):
    for q in ("voidfraction", "vz"):
        p = os.path.join(run, "results", f"profile_{q}_z{h}mm.csv")
        ok = os.path.exists(p)
        vals = []
        if ok:
            vals = [float(l.split(",")[1]) for l in open(p) if l[0].isdigit()]
            ok = len(vals) == 44 and all(math.isfinite(v) for v in vals)
        print(("PASS" if ok else "FAIL") + f": Muller demo profile {q} z = {h} mm ({len(vals)} finite points)")
        status |= not ok
log = open(os.path.join(run, "log.coarseDemFoam")).read()
m = re.findall(r"^End: Coupling: particles (\d+), .*?rel\. err ([0-9.eE+-]+)\)", log, re.M)
ok = bool(m) and int(m[-1][0]) == 9240 and float(m[-1][1]) <= 1e-12
print(("PASS" if ok else "FAIL") + f": Muller demo: 9240 particles kept, solid volume rel. err {m[-1][1] if m else '?'}")
status |= not ok
# superficial inflow above the bed (top layer of cells): alpha * Uz = 0.9 m/s
last = sorted((d for d in os.listdir(run) if re.fullmatch(r"[0-9.e-]+", d) and float(d) > 0), key=float)[-1]
def rd(path):
    b = open(path, "rb").read()
    mm = re.search(rb"internalField\s+nonuniform\s+List<(scalar|vector)>\s*(\d+)\s*\(", b)
    n = int(mm.group(2)); k = 3 if mm.group(1) == b"vector" else 1
    return struct.unpack("<%dd" % (n * k), b[mm.end():mm.end() + 8 * n * k])
U, a = rd(os.path.join(run, last, "U")), rd(os.path.join(run, last, "alpha"))
top = range(99 * 8 * 36, 100 * 8 * 36)
us = sum(U[3 * i + 2] * a[i] for i in top) / len(top)
ok = abs(us - 0.9) <= 0.01
print(("PASS" if ok else "FAIL") + f": Muller demo: superficial gas velocity at the top {us:.4f} m/s (inlet 0.9)")
status |= not ok
sys.exit(status)
PYEOF
