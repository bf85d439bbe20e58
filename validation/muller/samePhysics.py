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

    samePhysics.py [-o OUT.md] -windows REF_W1 REF_W2 ... -- OTHER_W1 OTHER_W2 ...

Each argument is one window of a run (profiles.py and pressureDrop.py over it: equal, non-overlapping
windows after the start-up). Why: the batch errors of one 5 s window understate how far this bed's time
averages move from one window to the next (the tutorial's own halves "differ" by the rule above,
validation/muller/results/medium/README.md), so this form takes the spread from the windows themselves.
The rule (written before the runs it judges, issue 44): the 14 quantities above, each window one sample;
for each, D = the RMS over its points of the difference of the two settings' window means, divided by
the RMS over its points of the standard deviation of all windows about their grand mean (a scale that
does not depend on which window belongs to which setting); the statistic T is the sum of the 14. Under
"the same physics" the windows are exchangeable, so T is compared with its value for every division of
the windows into two groups of the same sizes (a permutation test): p = the share of divisions with a
T as large as the observed one. CHANGED when p <= 0.05, else NO CHANGE DETECTED (with p and the
differences beside the windows' spread, so that the size of what could hide in the noise is seen).
Needs 4 and 4 windows at least (then p <= 0.05 only for the most extreme of the 35 divisions: a weak
test; 5 and 5 are better). Consecutive windows of one run are not quite independent (the circulation
changes over seconds), which makes p smaller than it should be: a CHANGED near 0.05 is weaker than
it reads, and NO CHANGE DETECTED says only that no change larger than the windows' spread was seen.
Each quantity's own p is listed, not judged; so are the windows' v_z peaks at 15 mm.
"""
import itertools
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


def same_points(xa, xb):
    """two profiles sampled at the same points"""
    return len(xa) == len(xb) and all(abs(a - b) <= 1e-9 for a, b in zip(xa, xb))


def compare(ref, other):
    """[(label, ref value, other value, difference, allowed, agrees)] and the v_z peaks at 15 mm"""
    rows, peaks = [], None
    for q, label in QUANTITIES:
        for z in HEIGHTS:
            xa, ya, ea = profile(ref, q, z)
            xb, yb, eb = profile(other, q, z)
            if (q, z) == ("vzdepthbinned", "15"):
                peaks = [max(ya), max(yb)]
            if not same_points(xa, xb):
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


def window_samples(window):
    """{label: list of values} of one window: the 12 profiles (over their points), the pressure drop
    (of the weight) and the expansion (one value each); and the v_z peak at 15 mm"""
    out, xs_of = {}, {}
    for q, label in QUANTITIES:
        for z in HEIGHTS:
            xs, ys, _ = profile(window, q, z)
            out["%s at %s mm" % (label, z)] = list(ys)
            xs_of["%s at %s mm" % (label, z)] = list(xs)
    pr = pressure(window)
    out["pressure drop - weight (of the weight)"] = [float(pr["dp_rel_err"])]
    out["expansion"] = [float(pr["expansion_2zbar_over_settled"])]
    return out, xs_of, max(out["v_z (m/s) at 15 mm"])


def permutation_test(ref_windows, other_windows):
    """rows (label, ref mean, other mean, D, spread, own p) and the overall p of the rule above"""
    samples = [window_samples(w) for w in ref_windows + other_windows]
    labels = list(samples[0][0])
    for w, (s, xs, _) in zip(ref_windows + other_windows, samples):
        if not all(same_points(xs[k], samples[0][1][k]) for k in xs):
            sys.exit("samePhysics.py: %s samples other points than %s" % (w, ref_windows[0]))
    n, ka = len(samples), len(ref_windows)
    rms = lambda v: math.sqrt(sum(x * x for x in v) / len(v))
    scale = {}
    for k in labels:
        cols = list(zip(*[s[0][k] for s in samples]))   # per point, the n windows' values
        sd = [math.sqrt(sum((v - sum(c) / n) ** 2 for v in c) / (n - 1)) for c in cols]
        scale[k] = rms(sd) or 1.0

    def stats(group):
        other = [i for i in range(n) if i not in group]
        out = {}
        for k in labels:
            ma = [sum(samples[i][0][k][j] for i in group) / len(group) for j in range(len(samples[0][0][k]))]
            mb = [sum(samples[i][0][k][j] for i in other) / len(other) for j in range(len(ma))]
            out[k] = (rms([b - a for a, b in zip(ma, mb)]) / scale[k], sum(ma) / len(ma), sum(mb) / len(mb))
        return out

    splits = list(itertools.combinations(range(n), ka))
    perms = [stats(g) for g in splits]
    observed = perms[0]   # the first division is the observed one: the reference windows first
    t_obs = sum(v[0] for v in observed.values())
    p_all = sum(sum(v[0] for v in s.values()) >= t_obs - 1e-12 for s in perms) / len(splits)
    rows = []
    for k in labels:
        d, a, b = observed[k]
        own_p = sum(s[k][0] >= d - 1e-12 for s in perms) / len(splits)
        rows.append((k, a, b, d * scale[k], scale[k], own_p))
    return rows, p_all, t_obs, len(splits), [s[2] for s in samples]


def main_windows(argv):
    if "--" not in argv:
        sys.exit("usage: samePhysics.py [-o OUT.md] -windows REF_W1 REF_W2 ... -- OTHER_W1 OTHER_W2 ...")
    cut = argv.index("--")
    ref_w, other_w = argv[:cut], argv[cut + 1:]
    n_splits = math.comb(len(ref_w) + len(other_w), len(ref_w)) if ref_w and other_w else 0
    smallest_p = (2 if len(ref_w) == len(other_w) else 1) / n_splits if n_splits else 1
    if len(ref_w) < 4 or len(other_w) < 4:
        sys.exit("samePhysics.py -windows: %d and %d windows: 4 and 4 windows at least (fewer leave a "
                 "smallest p of %.3g or a spread from too few windows)" % (len(ref_w), len(other_w), smallest_p))
    rows, p_all, t_obs, n_splits, peaks = permutation_test(ref_w, other_w)
    verdict = "CHANGED" if p_all <= 0.05 else "NO CHANGE DETECTED"
    lines = ["Reference windows: %s" % ", ".join(os.path.normpath(w) for w in ref_w),
             "Other windows: %s" % ", ".join(os.path.normpath(w) for w in other_w), "",
             "| quantity | reference (mean of windows) | other | RMS difference of the means | windows' spread (RMS sd) | own p |",
             "|---|---|---|---|---|---|"]
    for label, a, b, d, spread, own_p in rows:
        lines.append("| %s | %.4g | %.4g | %.3g | %.3g | %.2f |" % (label, a, b, d, spread, own_p))
    lines += ["", "v_z peak at 15 mm per window (not judged): reference %s; other %s m/s" % (
        ", ".join("%.3f" % v for v in peaks[:len(ref_w)]), ", ".join("%.3f" % v for v in peaks[len(ref_w):])),
        "", "samePhysics.py: T = %.3g, p = %.3f over %d divisions of the windows: %s" % (t_obs, p_all, n_splits, verdict)]
    return "\n".join(lines)


def main(argv):
    out = None
    if len(argv) >= 2 and argv[0] == "-o":
        out, argv = argv[1], argv[2:]
    if argv and argv[0] == "-windows":
        text = main_windows(argv[1:])
    else:
        if len(argv) != 2:
            sys.exit("usage: samePhysics.py [-o OUT.md] REFERENCE_RUN OTHER_RUN\n"
                     "       samePhysics.py [-o OUT.md] -windows REF_W1 REF_W2 ... -- OTHER_W1 OTHER_W2 ...")
        text = main_pair(*argv)
    print(text)
    if out:
        with open(out, "w") as f:
            f.write(text + "\n")
    return 0


def main_pair(ref, other):
    rows, peaks = compare(ref, other)
    n = sum(r[5] for r in rows)
    verdict = "UNCHANGED" if n == len(rows) else "CHANGED"
    lines = ["Reference: %s" % os.path.normpath(ref), "Other: %s" % os.path.normpath(other), "",
             "| quantity | reference | other | difference | allowed | |", "|---|---|---|---|---|---|"]
    for label, a, b, d, allowed, ok in rows:
        lines.append("| %s | %.4g | %.4g | %+.3g | %.3g | %s |" % (label, a, b, d, allowed, "agrees" if ok else "**differs**"))
    lines += ["", "v_z peak at 15 mm (not judged): %.3f and %.3f m/s" % tuple(peaks), "",
              "samePhysics.py: %d of %d agree: %s" % (n, len(rows), verdict)]
    return "\n".join(lines)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
