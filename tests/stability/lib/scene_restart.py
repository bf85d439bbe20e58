#!/usr/bin/python3
"""scene_restart.py -- a run stopped at a write time and restarted continues as the uninterrupted run.

    scene_restart.py <uninterrupted case> <restarted case> <scene> [--tol 1e-9]

Both cases are the same fluidized column; the second ran to the middle write time, then again from it
(startFrom latestTime: the fluid fields and <time>/dem.restart). Compares at the last common DEM dump
the particle positions and velocities, and at the last write time the fields alpha, U and p:
the largest difference relative to the field's (or the particles' velocity) scale.
PASS: every difference <= tol (round-off: the DEM's sums of contact forces may run in another order
after a restart), and both runs pass the common checks.
"""
import argparse, os, sys

import stablib


def rel_diff(a, b):
    scale = max((abs(x) for x in a), default=0.0) or 1.0
    return max((abs(x - y) for x, y in zip(a, b)), default=0.0) / scale


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("whole")
    ap.add_argument("split")
    ap.add_argument("scene")
    ap.add_argument("--tol", type=float, default=1e-9)
    a = ap.parse_args()
    p = stablib.params(a.whole)
    ok, summary, _ = stablib.check_run(a.whole, float(p.get("ALPHA_MIN", 0.3)), int(p["N_PARTICLES"]))
    ok2, summary2, _ = stablib.check_run(a.split, float(p.get("ALPHA_MIN", 0.3)), int(p["N_PARTICLES"]))
    parts = []
    if not ok2:
        ok = False
        parts.append("restarted run: " + summary2)
    restarts = sum(1 for l in open(os.path.join(a.split, "log.coarseDemFoam"), errors="replace")
                   if l.startswith("DEM restart file: ") and "none" not in l)
    if restarts != 1:
        ok = False
        parts.append("the second run did not read a DEM restart file (%d)" % restarts)
    dw, ds = stablib.dumps(a.whole), stablib.dumps(a.split)
    common = sorted(set(dw) & set(ds))
    if not common:
        print("FAIL: %s: no common DEM dump" % a.scene)
        return 1
    step = common[-1]
    rw, rs = dw[step], ds[step]
    if set(rw) != set(rs):
        ok = False
        parts.append("particle ids differ at step %d" % step)
    ids = sorted(set(rw) & set(rs))
    dx = max(max(abs(rw[i][k] - rs[i][k]) for k in range(3)) for i in ids) / float(p["DIAMETER_M"])
    dv = rel_diff([rw[i][k] for i in ids for k in range(3, 6)], [rs[i][k] for i in ids for k in range(3, 6)])
    parts.append("DEM step %d: positions differ by %.2e d, velocities by %.2e of the largest" % (step, dx, dv))
    ok = ok and dx <= a.tol and dv <= a.tol
    tw = stablib.write_times(a.whole)[-1][1]
    for name, vec in (("alpha", False), ("U", True), ("p", False)):
        if vec:
            fw = [c for v in stablib.read_vector_field(a.whole, tw, name) for c in v]
            fs = [c for v in stablib.read_vector_field(a.split, tw, name) for c in v]
        else:
            fw = stablib.read_scalar_field(a.whole, tw, name)
            fs = stablib.read_scalar_field(a.split, tw, name)
        d = rel_diff(fw, fs) if len(fw) == len(fs) else float("inf")
        parts.append("%s at t = %s: %.2e" % (name, tw, d))
        ok = ok and d <= a.tol
    parts.append("tolerance %.0e; " % a.tol + summary)
    print("%s: %s: %s" % ("PASS" if ok else "FAIL", a.scene, "; ".join(parts)))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
