#!/usr/bin/python3
"""scene_refinement.py -- CFD-step refinement of the fluidized column: the rise of the bed's mean
height at the end time for each case (coarsest CFD step first), the difference to the next coarser
step, and one result line:

    scene_refinement.py <label> <case> <case> <case> [...] [--max-last 0.01]

PASS if the run converges: the difference between the two finest steps is below --max-last times the
rise and smaller than the difference between the two coarsest. The DEM step is the same in every case;
the cases differ only in couplingInterval.
"""
import argparse

import stablib


def rises(case):
    """{DEM step: rise of the mean particle height (m) since the first dump}"""
    d = stablib.dumps(case)
    if not d:
        return {}
    zmean = lambda rows: sum(r[2] for r in rows.values()) / len(rows)
    z0 = zmean(d[min(d)])
    return {s: zmean(rows) - z0 for s, rows in d.items()}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("label")
    ap.add_argument("cases", nargs="+")
    ap.add_argument("--max-last", type=float, default=0.01)
    a = ap.parse_args()
    rows = []
    for c in a.cases:
        p = stablib.params(c)
        r = rises(c)
        if not r:
            print("FAIL: %s: no particle dumps in %s (run failed?)" % (a.label, c))
            return
        dt = float(p["COUPLING_INTERVAL"]) * float(p["DEM_TIMESTEP"])
        rows.append((dt, r[max(r)], r))
    print("  %-10s %-11s %-11s %s" % ("CFD step", "rise (mm)", "difference", "rise at 0.012 / 0.024 / 0.036 s (mm)"))
    for k, (dt, rise, r) in enumerate(rows):
        diff = "" if k == 0 else "%+.4f" % (1e3 * (rise - rows[k - 1][1]))
        mid = " / ".join("%.4f" % (1e3 * r[s]) for s in (2400, 4800, 7200) if s in r)
        print("  %-10g %-11.4f %-11s %s" % (dt, 1e3 * rise, diff, mid))
    if len(rows) < 3:
        print("FAIL: %s: needs at least three steps" % a.label)
        return
    first = abs(rows[1][1] - rows[0][1])
    last = abs(rows[-1][1] - rows[-2][1])
    rel = last / max(abs(rows[-1][1]), 1e-12)
    ok = rel <= a.max_last and last < first
    print("%s: %s: bed rise %.4f mm at the finest step %g s; finest difference %.4f mm (%.2f %% of the rise, "
          "bound %.1f %%), coarsest %.4f mm" %
          ("PASS" if ok else "FAIL", a.label, 1e3 * rows[-1][1], rows[-1][0], 1e3 * last, 100 * rel,
           100 * a.max_last, 1e3 * first))


if __name__ == "__main__":
    main()
