#!/bin/bash
# The Mueller bed in its demo mode (README command 1): runs end to end (settled bed, coupled run,
# profiles, comparison with the MR data) and writes both profiles at every height, finite, with
# the solid volume conserved and the inflow equal to the superficial velocity of the experiment;
# the binned particle fields hold every particle's volume and the same momentum as the kernel fields.
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
    for q in ("voidfraction", "vz", "vzbinned"):
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
# binned particle fields: every particle's volume in the cell of its centre (no loss), and the
# binned and the kernel-spread momentum density hold the same total sum V_p v_p
V = 0.010 * 0.044 * 0.120 / (8 * 36 * 100)
vp = 9240 * math.pi / 6 * 1.2e-3 ** 3
ab = rd(os.path.join(run, last, "alphaPBinned"))
ub, uk = rd(os.path.join(run, last, "alphaPUsBinned")), rd(os.path.join(run, last, "alphaPUs"))
err_v = abs(sum(ab) * V - vp) / vp
mom_b = [sum(ub[3 * i + d] for i in range(len(ab))) * V for d in range(3)]
mom_k = [sum(uk[3 * i + d] for i in range(len(ab))) * V for d in range(3)]
scale = max(sum(abs(ub[3 * i + d]) for i in range(len(ab))) * V for d in range(3))
err_m = max(abs(b - k) for b, k in zip(mom_b, mom_k)) / scale
ok = err_v <= 1e-12 and err_m <= 1e-12
print(("PASS" if ok else "FAIL") + f": Muller demo: binned particle fields hold the particle volume (rel. err {err_v:.2e}) "
      f"and the kernel fields' momentum (rel. diff {err_m:.2e})")
status |= not ok
sys.exit(status)
PYEOF
