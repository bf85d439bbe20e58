#!/usr/bin/python3
"""samePhysics.py -- does a cost setting change the Mueller bed? One run against another that differs
in a numerical setting only (the CFD step, the PISO correctors, a tolerance), each with its own window.

    samePhysics.py [-o OUT.md] REFERENCE_RUN OTHER_RUN

A run is a directory with the profiles of profiles.py (profile_<quantity>_z<h>mm.csv, columns
x_m,<quantity>,sem) and pressure.csv of pressureDrop.py, directly or under results/.

The rule (written before the pair of issue 44 was run, and checked on two windows of one run first):
the bed is chaotic, so two runs that differ in a setting are two samples of the time averages, and
"unchanged" means "the same within the sampling noise of the two windows":
  - each of the 12 headline profiles (the depth-averaged particle-binned gas fraction and particle
    v_z, the MR instrument's reading, at the six MR heights) AGREES when the RMS over its points of
    the difference is at most twice the RMS of the combined batch-means errors sqrt(sem_a^2 + sem_b^2);
  - the frictional pressure drop AGREES when the two differ by at most 1 % of the weight (half the
    2 % of issue 42's target) or two combined errors;
  - the bed's expansion (2 z_mean over the settled height) AGREES within 2 % of its value.
The pair is UNCHANGED when every one of the 14 agrees. The v_z peak at 15 mm (the circulation issue
42 follows) is listed beside, not judged: one point of one profile.
Prints the table (and writes it to OUT.md), the last line "samePhysics.py: N of 14 agree: VERDICT".
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."), "etc", "python"))
from muller_compare import read_profile  # noqa: E402
from muller_plots import HEIGHTS_MM as HEIGHTS  # noqa: E402  (the six MR heights, one list)
QUANTITIES = [("voidfractiondepthbinned", "gas fraction"), ("vzdepthbinned", "v_z (m/s)")]
PROFILE_FACTOR = 2.0      # profile RMS difference against RMS combined error
DP_TOLERANCE = 0.01       # of the weight
EXPANSION_TOLERANCE = 0.02  # relative


def results_dir(run):
    sub = os.path.join(run, "results")
    return sub if os.path.isfile(os.path.join(sub, "pressure.csv")) else run


def profile(run, quantity, z):
    path = os.path.join(results_dir(run), "profile_%s_z%smm.csv" % (quantity, z))
    if not os.path.isfile(path):
        sys.exit("samePhysics.py: %s missing (profiles.py writes it)" % path)
    _, xs, ys, es = read_profile(path)
    return xs, ys, es


def pressure(run):
    path = os.path.join(results_dir(run), "pressure.csv")
    if not os.path.isfile(path):
        sys.exit("samePhysics.py: %s missing (pressureDrop.py writes it)" % path)
    rows = list(csv.DictReader(open(path)))
    if not rows:
        sys.exit("samePhysics.py: %s has no rows" % path)
    return rows[-1]


def compare(ref, other):
    """[(label, ref value, other value, difference, allowed, agrees)] and the v_z peaks at 15 mm"""
    rows, peaks = [], None
    for q, label in QUANTITIES:
        for z in HEIGHTS:
            xa, ya, ea = profile(ref, q, z)
            xb, yb, eb = profile(other, q, z)
            if (q, z) == ("vzdepthbinned", "15"):
                peaks = [max(ya), max(yb)]
            if len(xa) != len(xb) or any(abs(a - b) > 1e-9 for a, b in zip(xa, xb)):
                sys.exit("samePhysics.py: %s at %s mm: the two runs sample different points" % (q, z))
            d = math.sqrt(sum((a - b) ** 2 for a, b in zip(ya, yb)) / len(ya))
            s = math.sqrt(sum(a * a + b * b for a, b in zip(ea, eb)) / len(ea))
            mean = lambda v: sum(v) / len(v)
            rows.append(("%s at %s mm (mean; RMS difference)" % (label, z), mean(ya), mean(yb), d,
                         PROFILE_FACTOR * s, d <= PROFILE_FACTOR * s))
    pa, pb = pressure(ref), pressure(other)
    dpa, dpb = float(pa["dp_rel_err"]), float(pb["dp_rel_err"])
    w = float(pa["weight_per_area_pa"])
    sem = math.hypot(float(pa["dp_sem_pa"]), float(pb["dp_sem_pa"])) / w
    allowed = max(DP_TOLERANCE, 2 * sem)
    rows.append(("pressure drop - weight (of the weight)", dpa, dpb, dpb - dpa, allowed, abs(dpb - dpa) <= allowed))
    ea, eb = float(pa["expansion_2zbar_over_settled"]), float(pb["expansion_2zbar_over_settled"])
    rows.append(("expansion", ea, eb, eb - ea, EXPANSION_TOLERANCE * ea, abs(eb - ea) <= EXPANSION_TOLERANCE * ea))
    return rows, peaks


def main(argv):
    out = None
    if len(argv) >= 2 and argv[0] == "-o":
        out, argv = argv[1], argv[2:]
    if len(argv) != 2:
        sys.exit("usage: samePhysics.py [-o OUT.md] REFERENCE_RUN OTHER_RUN")
    ref, other = argv
    rows, peaks = compare(ref, other)
    n = sum(r[5] for r in rows)
    verdict = "UNCHANGED" if n == len(rows) else "CHANGED"
    lines = ["Reference: %s" % os.path.normpath(ref), "Other: %s" % os.path.normpath(other), "",
             "| quantity | reference | other | difference | allowed | |", "|---|---|---|---|---|---|"]
    for label, a, b, d, allowed, ok in rows:
        lines.append("| %s | %.4g | %.4g | %+.3g | %.3g | %s |" % (label, a, b, d, allowed, "agrees" if ok else "**differs**"))
    lines += ["", "v_z peak at 15 mm (not judged): %.3f and %.3f m/s" % tuple(peaks), "",
              "samePhysics.py: %d of %d agree: %s" % (n, len(rows), verdict)]
    text = "\n".join(lines)
    print(text)
    if out:
        with open(out, "w") as f:
            f.write(text + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
