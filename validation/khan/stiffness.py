#!/usr/bin/python3
"""stiffness.py -- does a softer contact stiffness change the binary bed? One run against a stiffer one.

    stiffness.py OUT SOFT_RUN STIFF_RUN

The runs (directories with results/ from postprocess.py, as for compare.py) must be of one method,
background setting, velocity and mode, and differ in Young's modulus only (refused otherwise,
naming what differs). Issue 19 asks for the short mode's softened contacts to be checked once
against a stiffer run: the validation runs use E = 1e5 Pa, the short mode's own is 1e6 Pa.

For each quantity the two time means are compared with their batch-means errors combined
(sqrt(sem_soft^2 + sem_stiff^2)). A quantity AGREES when the difference is within two combined
errors or within the tolerance below, else it DIFFERS:
  - each species' plateau alpha_p: 0.01 (a third of issue 19's 0.03 target against Richardson-Zaki);
  - each species' mean height: 0.5 mm (half a cell);
  - the frictional pressure drop: 1 % of the bed's buoyant weight (a third of the 3 % target);
  - the mixing region's width: 1 mm (one bin of the profiles it is measured on).
The largest contact overlap (% of the smaller diameter) is listed, not judged: it is what stiffer
contacts change by design.

OUT gets stiffness.md (the table and the verdict); the same lines are printed, the last one
"stiffness.py: ... N of M quantities agree".
"""
import importlib.util, math, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
# compare.py's read_run: one reader of a run's results for both scripts (loaded by path: another
# "compare" module, validation/muller's, may already be imported where this one is)
_spec = importlib.util.spec_from_file_location("khan_compare_for_stiffness", os.path.join(HERE, "compare.py"))
compare = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(compare)

TOLERANCE = {"plateau": 0.01, "height": 0.5, "dp": 0.01, "mixing": 1.0}
SAME_CASE = ("method", "background", "U", "mode")


def refuse_unless_comparable(soft, stiff):
    """SystemExit naming what differs beyond Young's modulus, or the modulus itself when equal."""
    a, b = soft["bed"], stiff["bed"]
    differ = ["%s (%s against %s)" % (k, a[k], b[k]) for k in SAME_CASE
              if (float(a[k]) != float(b[k]) if k == "U" else a[k] != b[k])]
    if differ:
        raise SystemExit("stiffness.py: %s and %s differ in more than the contact stiffness: %s"
                         % (soft["name"], stiff["name"], ", ".join(differ)))
    if not float(a["young_pa"]) < float(b["young_pa"]):
        raise SystemExit("stiffness.py: %s (E = %g Pa) is not softer than %s (E = %g Pa); give the softer run first"
                         % (soft["name"], float(a["young_pa"]), stiff["name"], float(b["young_pa"])))


def judged(what, unit, soft, soft_sem, stiff, stiff_sem, tol):
    """One compared quantity: (row for the table, agrees)."""
    diff = soft - stiff
    sem = math.hypot(soft_sem, stiff_sem)
    agrees = abs(diff) <= max(2 * sem, tol)
    in_sem = "%.1f" % (abs(diff) / sem) if sem > 0 else "-"
    u = " " + unit if unit else ""
    return ("| %s | %.4g ± %.2g | %.4g ± %.2g | %+.3g%s | %s | %.3g%s | %s |"
            % (what, soft, soft_sem, stiff, stiff_sem, diff, u, in_sem, tol, u,
               "agrees" if agrees else "DIFFERS"), agrees)


def compare_runs(soft, stiff):
    """The table's rows and verdicts, one per judged quantity."""
    rows = []
    for sp in ("big", "small"):
        a, b = soft["layers"][sp], stiff["layers"][sp]
        rows.append(judged("%s plateau alpha_p" % sp, "", float(a["alpha_p_plateau"]), float(a["alpha_p_sem"]),
                           float(b["alpha_p_plateau"]), float(b["alpha_p_sem"]), TOLERANCE["plateau"]))
        rows.append(judged("%s mean height" % sp, "mm", float(a["mean_height_mm"]), float(a["mean_height_sem_mm"]),
                           float(b["mean_height_mm"]), float(b["mean_height_sem_mm"]), TOLERANCE["height"]))
    a, b = soft["bed"], stiff["bed"]
    rows.append(judged("frictional pressure drop", "Pa", float(a["dp_pa"]), float(a["dp_sem_pa"]),
                       float(b["dp_pa"]), float(b["dp_sem_pa"]), TOLERANCE["dp"] * float(a["dp_weight_pa"])))
    rows.append(judged("mixing region", "mm", float(a["mixing_width_mm"]), float(a["mixing_width_sem_mm"]),
                       float(b["mixing_width_mm"]), float(b["mixing_width_sem_mm"]), TOLERANCE["mixing"]))
    return rows


def main(argv):
    if len(argv) != 3:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    out = argv[0]
    soft, stiff = compare.read_run(argv[1]), compare.read_run(argv[2])
    refuse_unless_comparable(soft, stiff)
    rows = compare_runs(soft, stiff)
    n_agree = sum(ok for _, ok in rows)
    a, b = soft["bed"], stiff["bed"]
    lines = ["%s (E = %g Pa) against %s (E = %g Pa): %s, %s m/s, %s mode; windows %s and %s s."
             % (soft["name"], float(a["young_pa"]), stiff["name"], float(b["young_pa"]), soft["method"],
                a["U"], a["mode"], a["window_s"], b["window_s"]),
             "",
             "| quantity | E = %g Pa | E = %g Pa | soft - stiff | in combined sem | tolerance | verdict |"
             % (float(a["young_pa"]), float(b["young_pa"])),
             "|---|---|---|---|---|---|---|"]
    lines += [r for r, _ in rows]
    lines += ["",
              "Largest contact overlap: %s %% of d (E = %g Pa), %s %% of d (E = %g Pa)."
              % (a["max_overlap_pct_d"], float(a["young_pa"]), b["max_overlap_pct_d"], float(b["young_pa"])),
              "A quantity agrees when the difference is within two combined batch-means errors or within "
              "its tolerance (stiffness.py's docstring says why each).",
              "",
              "stiffness.py: E = %g Pa against E = %g Pa: %d of %d quantities agree%s"
              % (float(a["young_pa"]), float(b["young_pa"]), n_agree, len(rows),
                 "" if n_agree == len(rows) else " (the softer contacts change the bed)")]
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "stiffness.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
