"""Compare the Mueller demo's profiles across the tolerances of one setting (bench/tolerance_study.sh).

    tolerance_study.py WORK RUN STAGE OUT REF T2 T3 ...

WORK/<tol>/tutorials/fluidizedBedMuller/runs/RUN is the demo run of each tolerance. For each tolerance
T, quantity (depth-averaged binned gas fraction and v_z) and MR height: the RMS over the profile's
points of profile_T - profile_REF, beside the RMS spread of the reference profile about its mean (the
size of the profile itself): OUT.csv. From each run's log, the solver's STAGE timer and its share of
the timed stages, the time loop's wall seconds, the fluid's largest Courant number (over the run, and
its mean over the steps) and the number of CFD steps above 1 (the first step, the hand-over from the shipped state, left out),
the pressure's mean linear-solver iterations per solve and the mean of the steps' local continuity
error (the log's "sum local", the step's |ddt(alpha) + div(alpha phi)| dt averaged over the cells):
OUT_timers.csv.
"""
import csv
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "etc", "python"))
from muller_compare import read_profile  # noqa: E402  (the reader of profiles.py's CSV files)
from muller_plots import HEIGHTS_MM as HEIGHTS  # noqa: E402  (the six MR heights)
QUANTITIES = ["voidfractiondepthbinned", "vzdepthbinned"]


def run_dir(work, run, tol):
    return os.path.join(work, tol, "tutorials", "fluidizedBedMuller", "runs", run)


def profile(path, quantity, z):
    """The time-averaged values of one profile of a run."""
    return read_profile(os.path.join(path, "results", "profile_%s_z%smm.csv" % (quantity, z)))[2]


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values))


def stage_timer(path, stage):
    """(seconds, share %) of the stage from the last 'Stage timers' line of the solver log."""
    line = None
    with open(os.path.join(path, "log.coarseDemFoam")) as f:
        for text in f:
            if text.startswith("Stage timers"):
                line = text
    m = re.search(r"\b%s ([0-9.eE+-]+) \(([0-9.]+)%%\)" % re.escape(stage), line or "")
    if not m:
        sys.exit("tolerance_study.py: no %s stage timer in %s/log.coarseDemFoam" % (stage, path))
    return float(m.group(1)), float(m.group(2))


def loop_and_courant(path):
    """(time loop wall s, largest Courant number, its mean over the steps, CFD steps above 1, CFD steps)
    from the solver log: the
    last Progress line and the per-step 'Courant Number mean: M max: X' lines, the first step left out
    (the hand-over from the shipped state, whose fluid was solved with the tutorial's step)."""
    wall, courant = None, []
    with open(os.path.join(path, "log.coarseDemFoam")) as f:
        for text in f:
            m = re.match(r"Progress: .* wall ([0-9.eE+-]+) s", text)
            if m:
                wall = float(m.group(1))
            m = re.match(r"Courant Number mean: \S+ max: ([0-9.eE+-]+)", text)
            if m:
                courant.append(float(m.group(1)))
    if wall is None or len(courant) < 2:
        sys.exit("tolerance_study.py: no Progress or Courant Number lines in %s/log.coarseDemFoam" % path)
    steps = courant[1:]
    return wall, max(steps), sum(steps) / len(steps), sum(1 for c in steps if c > 1), len(steps)


def pressure_work(path):
    """(mean iterations of the pressure solves, mean of the steps' local continuity error) from the
    solver log's 'Solving for p' and 'fluid-phase continuity errors : sum local = E' lines."""
    iterations, errors = [], []
    with open(os.path.join(path, "log.coarseDemFoam")) as f:
        for text in f:
            m = re.search(r"Solving for p, .*No Iterations (\d+)", text)
            if m:
                iterations.append(int(m.group(1)))
            m = re.match(r"fluid-phase continuity errors : sum local = ([0-9.eE+-]+)", text)
            if m:
                errors.append(float(m.group(1)))
    if not iterations or not errors:
        sys.exit("tolerance_study.py: no pressure solves or continuity errors in %s/log.coarseDemFoam" % path)
    return sum(iterations) / len(iterations), sum(errors) / len(errors)


def main(argv):
    if len(argv) < 6:
        sys.exit(__doc__)
    work, run, stage, out, ref, others = argv[0], argv[1], argv[2], argv[3], argv[4], argv[5:]
    with open(out + ".csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["tolerance", "reference", "quantity", "z_mm", "rms_difference", "rms_spread_of_reference"])
        for q in QUANTITIES:
            for z in HEIGHTS:
                a = profile(run_dir(work, run, ref), q, z)
                mean = sum(a) / len(a)
                spread = rms([x - mean for x in a])
                for t in others:
                    b = profile(run_dir(work, run, t), q, z)
                    w.writerow([t, ref, q, z, "%.4g" % rms([x - y for x, y in zip(b, a)]), "%.4g" % spread])
    with open(out + "_timers.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["tolerance", stage + "_s", stage + "_share_pct", "loop_wall_s", "courant_max",
                    "courant_max_step_mean", "cfd_steps_above_1", "cfd_steps", "p_iterations_mean",
                    "continuity_local_mean"])
        for t in [ref] + others:
            s, share = stage_timer(run_dir(work, run, t), stage)
            wall, co, co_mean, above, steps = loop_and_courant(run_dir(work, run, t))
            p_iterations, continuity = pressure_work(run_dir(work, run, t))
            w.writerow([t, "%.2f" % s, "%.1f" % share, "%.2f" % wall, "%.3g" % co, "%.3g" % co_mean, above, steps,
                        "%.2f" % p_iterations, "%.3g" % continuity])


if __name__ == "__main__":
    main(sys.argv[1:])
