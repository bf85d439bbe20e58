"""Compare the Mueller demo's profiles across diffusion tolerances (bench/diffusion_tolerance.sh).

    diffusion_tolerance.py WORK RESULTS REF T2 T3 ...

For each tolerance T, quantity (depth-averaged binned gas fraction and v_z) and MR height: the RMS over
the profile's points of profile_T - profile_REF, beside the RMS spread of the reference profile about
its mean (the size of the profile itself). From each run's log, the alphaP stage timer (spreading,
smoothing and limiter) and its share of the timed stages.
"""
import csv
import math
import os
import re
import sys

HEIGHTS = ["15", "16.4", "20", "25", "31.2", "35"]
QUANTITIES = ["voidfractiondepthbinned", "vzdepthbinned"]


def run_dir(work, tol):
    return os.path.join(work, tol, "tutorials", "fluidizedBedMuller", "runs", "diffusion_dx1_U0.9_demo")


def profile(work, tol, quantity, z):
    path = os.path.join(run_dir(work, tol), "results", "profile_%s_z%smm.csv" % (quantity, z))
    with open(path) as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    return [float(r[1]) for r in rows[1:]]


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values))


def alpha_p_timer(work, tol):
    """(seconds, share %) of the alphaP stage from the last 'Stage timers' line of the solver log."""
    line = None
    with open(os.path.join(run_dir(work, tol), "log.coarseDemFoam")) as f:
        for text in f:
            if text.startswith("Stage timers"):
                line = text
    m = re.search(r"alphaP ([0-9.eE+-]+) \(([0-9.]+)%\)", line or "")
    if not m:
        sys.exit("diffusion_tolerance.py: no alphaP stage timer in the log of tolerance %s" % tol)
    return float(m.group(1)), float(m.group(2))


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    work, results, ref, others = argv[0], argv[1], argv[2], argv[3:]
    with open(os.path.join(results, "diffusion_tolerance.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["tolerance", "reference", "quantity", "z_mm", "rms_difference", "rms_spread_of_reference"])
        for q in QUANTITIES:
            for z in HEIGHTS:
                a = profile(work, ref, q, z)
                mean = sum(a) / len(a)
                spread = rms([x - mean for x in a])
                for t in others:
                    b = profile(work, t, q, z)
                    w.writerow([t, ref, q, z, "%.4g" % rms([x - y for x, y in zip(b, a)]), "%.4g" % spread])
    with open(os.path.join(results, "diffusion_tolerance_timers.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["tolerance", "alphaP_s", "alphaP_share_pct"])
        for t in [ref] + others:
            s, share = alpha_p_timer(work, t)
            w.writerow([t, "%.2f" % s, "%.1f" % share])


if __name__ == "__main__":
    main(sys.argv[1:])
