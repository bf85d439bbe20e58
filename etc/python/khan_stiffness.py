"""khan_stiffness.py (run as validation/khan/stiffness.py) -- does a softer contact stiffness, or a longer DEM step, change the binary bed? One run
against another that differs in that setting only.

    stiffness.py OUT SOFT_RUN STIFF_RUN       Young's modulus: the softer run first (OUT/stiffness.md)
    stiffness.py OUT COARSE_RUN FINE_RUN      the DEM step (same E): the longer step first (OUT/demStep.md)

The runs (directories with results/ from postprocess.py, as for compare.py) must be of one method,
background setting, velocity and mode, and differ in Young's modulus or in the DEM step (bed.csv's
dem_dt_s), not both (refused otherwise, naming what differs). Issue 19 asks for the short mode's
softened contacts to be checked once against a stiffer run: the validation runs use E = 1e5 Pa, the
short mode's own is 1e6 Pa. Issue 44 doubled the DEM step (17.5 % of the Rayleigh time instead of
8.75 %): the same check, with the step.

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
import math, os, sys

from dem_series import dem_script_step
from khan_runs import read_run  # one reader of a run's results for compare.py and this

TOLERANCE = {"plateau": 0.01, "height": 0.5, "dp": 0.01, "mixing": 1.0}
SAME_CASE = ("method", "background", "U", "mode")


def dem_dt(run):
    """The run's DEM step (s): bed.csv's dem_dt_s, or for a run post-processed before that column the
    timestep line of its DEM script; None when neither is there (a kept copy of results/ alone)."""
    v = run["bed"].get("dem_dt_s")
    if v:
        return float(v)
    return dem_script_step(run.get("dir", ""), "in.liggghts")


def compared_setting(soft, stiff):
    """'young' or 'step': the one setting the runs differ in (SystemExit naming what else differs, or
    that the first run is not the softer / longer-stepped one)."""
    a, b = soft["bed"], stiff["bed"]
    differ = ["%s (%s against %s)" % (k, a[k], b[k]) for k in SAME_CASE
              if (float(a[k]) != float(b[k]) if k == "U" else a[k] != b[k])]
    young = float(a["young_pa"]) != float(b["young_pa"])
    ds, dt = dem_dt(soft), dem_dt(stiff)
    if not young and (ds is None or dt is None):
        raise SystemExit("stiffness.py: %s and %s have the same Young's modulus and the DEM step of %s is not known "
                         "(bed.csv without dem_dt_s and no DEM/in.liggghts): post-process it again"
                         % (soft["name"], stiff["name"], soft["name"] if ds is None else stiff["name"]))
    step = ds is not None and dt is not None and abs(ds - dt) > 1e-9 * dt
    if young and step:
        differ.append("both Young's modulus and the DEM step")
    if differ:
        raise SystemExit("stiffness.py: %s and %s differ in more than one setting: %s"
                         % (soft["name"], stiff["name"], ", ".join(differ)))
    if young:
        if not float(a["young_pa"]) < float(b["young_pa"]):
            raise SystemExit("stiffness.py: %s (E = %g Pa) is not softer than %s (E = %g Pa); give the softer run first"
                             % (soft["name"], float(a["young_pa"]), stiff["name"], float(b["young_pa"])))
        return "young"
    if step:
        if not ds > dt:
            raise SystemExit("stiffness.py: %s (DEM step %g s) has not the longer step of the two (%s: %g s); give it first"
                             % (soft["name"], ds, stiff["name"], dt))
        return "step"
    raise SystemExit("stiffness.py: %s and %s have the same Young's modulus and DEM step: nothing to compare"
                     % (soft["name"], stiff["name"]))


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
    soft, stiff = read_run(argv[1]), read_run(argv[2])
    soft["dir"], stiff["dir"] = argv[1], argv[2]
    setting = compared_setting(soft, stiff)
    rows = compare_runs(soft, stiff)
    n_agree = sum(ok for _, ok in rows)
    a, b = soft["bed"], stiff["bed"]
    if setting == "young":
        label = lambda r: "E = %g Pa" % float(r["bed"]["young_pa"])
        diff_name, out_file, change = "soft - stiff", "stiffness.md", "the softer contacts change the bed"
    else:
        label = lambda r: "DEM step %g s" % dem_dt(r)
        diff_name, out_file, change = "long - short", "demStep.md", "the longer DEM step changes the bed"
    lines = ["%s (%s) against %s (%s): %s, %s m/s, %s mode; windows %s and %s s."
             % (soft["name"], label(soft), stiff["name"], label(stiff), soft["method"],
                a["U"], a["mode"], a["window_s"], b["window_s"]),
             "",
             "| quantity | %s | %s | %s | in combined sem | tolerance | verdict |" % (label(soft), label(stiff), diff_name),
             "|---|---|---|---|---|---|---|"]
    lines += [r for r, _ in rows]
    lines += ["",
              "Largest contact overlap: %s %% of d (%s), %s %% of d (%s)."
              % (a["max_overlap_pct_d"], label(soft), b["max_overlap_pct_d"], label(stiff)),
              "A quantity agrees when the difference is within two combined batch-means errors or within "
              "its tolerance (stiffness.py's docstring says why each).",
              "",
              "stiffness.py: %s against %s: %d of %d quantities agree%s"
              % (label(soft), label(stiff), n_agree, len(rows),
                 "" if n_agree == len(rows) else " (%s)" % change)]
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, out_file), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0

