#!/usr/bin/python3
"""scene_column.py -- PASS/FAIL line of a solver-level column scene.

    scene_column.py <case> <scene name> [--alpha-min 0.3] [--vmax 1.0] [--co-range lo hi]

Common checks (stablib.check_run): solver exit 0, particle count constant and as created, solid volume
rel. err <= 1e-12, momentum imbalance <= 1e-10 x force scale, no NaN, alpha_f within [alphaMin, 1] at
the last write. Also reports the particles' motion from the LIGGGHTS dumps (bed mean height change,
max speed; the speed must stay below --vmax m/s: a DEM or coupling blow-up shows there first) and the
Courant number range (--co-range: the run must reach a max Co in [lo, hi]).
"""
import argparse, math, os, re, sys

import stablib


def courant(case):
    co = []
    with open(os.path.join(case, "log.coarseDemFoam"), errors="replace") as f:
        for line in f:
            m = re.match(r"Courant Number mean: (\S+) max: (\S+)", line)
            if m:
                co.append(float(m.group(2)))
    return co


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case")
    ap.add_argument("scene")
    ap.add_argument("--alpha-min", type=float, default=0.3)
    ap.add_argument("--vmax", type=float, default=1.0)
    ap.add_argument("--speed-not-asserted", metavar="REASON",
                    help="report the largest particle speed without asserting --vmax (and say why)")
    ap.add_argument("--co-range", type=float, nargs=2)
    ap.add_argument("--skip-co", type=int, default=0, help="ignore the first N Courant numbers (adjustTimeStep)")
    ap.add_argument("--reference", help="a case of the same scene with other settings: bed mean z compared")
    ap.add_argument("--max-diff", type=float, help="with --reference: the bed rises must agree to this fraction")
    a = ap.parse_args()
    p = stablib.params(a.case)
    n0 = int(p["N_PARTICLES"]) if "N_PARTICLES" in p else None
    ok, summary, m = stablib.check_run(a.case, a.alpha_min, n0)
    extra = []
    d = stablib.dumps(a.case)
    if len(d) >= 2:
        steps = list(d)
        first, last = d[steps[0]], d[steps[-1]]
        zmean = lambda rows: sum(r[2] for r in rows.values()) / max(1, len(rows))
        vmax = max(math.sqrt(r[3] ** 2 + r[4] ** 2 + r[5] ** 2) for s in steps for r in d[s].values())
        extra.append("bed mean z %.2f -> %.2f mm, max particle speed %.3f m/s" %
                     (1e3 * zmean(first), 1e3 * zmean(last), vmax))
        if a.speed_not_asserted:
            extra.append("speed not asserted: " + a.speed_not_asserted)
        elif not vmax <= a.vmax:
            ok = False
            extra.append("particle speed above %g m/s" % a.vmax)
        if a.reference:
            dr = stablib.dumps(a.reference)
            pr = stablib.params(a.reference)
            t_end = steps[-1] * float(p["DEM_TIMESTEP"])
            # the reference dump at the same time
            match = [s for s in dr if abs(s * float(pr["DEM_TIMESTEP"]) - t_end) < 1e-9]
            if match:
                zr0, zr1 = zmean(dr[min(dr)]), zmean(dr[match[0]])
                rise, rise_r = zmean(last) - zmean(first), zr1 - zr0
                diff = abs(rise - rise_r) / max(abs(rise_r), 1e-12)
                extra.append("bed rise %.4f mm vs %.4f mm with couplingInterval %s x DEM step %s s (difference %.1f %%)" %
                             (1e3 * rise, 1e3 * rise_r, pr["COUPLING_INTERVAL"], pr["DEM_TIMESTEP"], 100 * diff))
                if a.max_diff is not None and diff > a.max_diff:
                    ok = False
                    extra.append("differs by more than %.0f %%" % (100 * a.max_diff))
            else:
                extra.append("no reference dump at t = %g s" % t_end)
                if a.max_diff is not None:
                    ok = False
    co = courant(a.case)[a.skip_co:]
    if co:
        extra.append("Co max %.3f" % max(co))
        if a.co_range and not (a.co_range[0] <= max(co) <= a.co_range[1]):
            ok = False
            extra.append("max Co outside [%g, %g]" % tuple(a.co_range))
    if m["rc"] != 0:
        # how far it got: the last time step reached
        last = None
        with open(os.path.join(a.case, "log.coarseDemFoam"), errors="replace") as f:
            for line in f:
                if line.startswith("Time = "):
                    last = line.split()[2]
        extra.append("stopped at t = %s s of %s s" % (last, p.get("END_TIME", "?")))
    print("%s: %s: %s%s" % ("PASS" if ok else "FAIL", a.scene, summary, ("; " + ", ".join(extra)) if extra else ""))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
