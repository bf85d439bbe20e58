"""khan_runs.py -- reading what tutorials/binaryBedKhan/postprocess.py left in a run's results/
(bed.csv, layers.csv, profiles.csv, axis_end.csv, messages.txt): for validation/khan/compare.py and
stiffness.py."""
import csv
import os

# the columns of bed.csv (postprocess.py) this script reads beyond the results
BED_CASE = ("background", "young_pa", "ranks", "coupling_share", "dem_per_fluid", "coupling_per_fluid", "commit")


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def read_run(run):
    res = os.path.join(run, "results")
    for f in ("bed.csv", "layers.csv", "profiles.csv"):
        if not os.path.isfile(os.path.join(res, f)):
            raise SystemExit("compare.py: %s has no results/%s (run postprocess.py first, or Allrun -post)" % (run, f))
    bed = read_csv(os.path.join(res, "bed.csv"))[0]
    missing = [k for k in BED_CASE if k not in bed]
    if missing:
        raise SystemExit("compare.py: %s/results/bed.csv has no %s: it was post-processed by an older postprocess.py; "
                         "run Allrun ... -post again" % (run, ", ".join(missing)))
    layers = {r["species"]: r for r in read_csv(os.path.join(res, "layers.csv"))}
    prof = read_csv(os.path.join(res, "profiles.csv"))
    axis = read_csv(os.path.join(res, "axis_end.csv")) if os.path.isfile(os.path.join(res, "axis_end.csv")) else []
    msgs = os.path.join(res, "messages.txt")
    warnings = [l.rstrip("\n") for l in open(msgs)] if os.path.isfile(msgs) else []
    name = os.path.basename(os.path.normpath(run))
    method = bed["method"] + ("+background" if bed["background"] == "on" else "")
    return dict(name=name, method=method, bed=bed, layers=layers, prof=prof, axis=axis, warnings=warnings,
                share=float(bed["coupling_share"]), dem_per_fluid=float(bed["dem_per_fluid"]),
                coupling_per_fluid=float(bed["coupling_per_fluid"]), case=(window(bed), "%g" % float(bed["young_pa"])))


def window(bed):
    """'T0..T1' of bed.csv's tstart and tend, or the mode's name for a bed.csv without them."""
    if "tstart" in bed and "tend" in bed:
        return "%g..%g" % (float(bed["tstart"]), float(bed["tend"]))
    return bed["mode"]


def one_case(runs):
    """The runs' (averaging window, Young's modulus), the same for all, or SystemExit naming the runs that
    differ. The window, not the mode's name: the short and long modes share the start state and the
    numerics, so a long run post-processed at 6 s (Allrun -endTime 6 -post) has the short mode's window
    and compares with short runs; the demo and full modes differ in their windows as in their beds."""
    cases = {}
    for r in runs:
        cases.setdefault(r["case"], []).append(r["name"])
    if len(cases) > 1:
        raise SystemExit("compare.py: the runs mix averaging windows or contact stiffnesses, whose beds differ; "
                         "compare one at a time:\n" + "\n".join("    window %s s, E = %s Pa: %s" % (w, e, ", ".join(n))
                                                                 for (w, e), n in sorted(cases.items())))
    return next(iter(cases))
