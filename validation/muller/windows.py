#!/usr/bin/python3
"""windows.py -- a Mueller run's averaging window cut into N equal windows, each averaged alone.

    windows.py RUN T_START T_END N OUT_DIR

Writes OUT_DIR/<run name>_w<i>_<a>-<b>s/ for i = 1..N, the window (a, b] of length (T_END - T_START)/N:
the profiles of profiles.py and pressure.csv of pressureDrop.py over that window alone, as a run's
results/ holds them over its whole window. Prints the folders, in time order.

Why: the time averages of this bubbling bed move from one window to the next by more than the batch
errors of one window say (a circulation that changes its pattern over seconds: the medium pair of
issue 44, validation/muller/results/medium/README.md). Several windows of each run give that spread;
samePhysics.py -windows judges two settings against it.
"""
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(HERE, "..", ".."), "etc", "python"))
import muller_profiles  # noqa: E402  (the sample times of a run)


def main(argv):
    if len(argv) != 5:
        sys.exit(__doc__)
    run, out = argv[0], argv[4]
    try:
        t0, t1, n = float(argv[1]), float(argv[2]), int(argv[3])
    except ValueError:
        sys.exit("windows.py: T_START and T_END are times in s, N a whole number: %s" % " ".join(argv[1:4]))
    if not (t1 > t0 and n >= 1):
        sys.exit("windows.py: needs T_END > T_START and N >= 1, got %g %g %d" % (t0, t1, n))
    if not os.path.isdir(os.path.join(run, "postProcessing")):
        sys.exit("windows.py: %s has no postProcessing/ (not a run of tutorials/fluidizedBedMuller)" % run)
    # the last window must lie within the samples (profiles.py averages whatever falls in a window)
    base = os.path.join(run, "postProcessing", "profiles")
    times = list(muller_profiles.sample_dirs(base)) + [t for byt in muller_profiles.read_store(base).values() for t in byt]
    if not times or max(times) < t1 - 0.006:
        sys.exit("windows.py: %s's samples end at %s s, before T_END %g s" % (run, "%g" % max(times) if times else "none", t1))
    name = os.path.basename(os.path.normpath(run))
    run = os.path.abspath(run)
    os.makedirs(out, exist_ok=True)
    for i in range(n):
        a, b = t0 + i * (t1 - t0) / n, t0 + (i + 1) * (t1 - t0) / n
        dest = os.path.join(out, "%s_w%d_%g-%gs" % (name, i + 1, a, b))
        # the run seen through links, with a results/ of its own: the scripts write only there
        with tempfile.TemporaryDirectory() as view:
            for entry in os.listdir(run):
                if entry != "results":
                    os.symlink(os.path.join(run, entry), os.path.join(view, entry))
            for script in ("profiles.py", "pressureDrop.py"):
                r = subprocess.run([sys.executable, os.path.join(HERE, script), view, repr(a), repr(b)],
                                   capture_output=True, text=True)
                if r.returncode != 0:
                    sys.exit("windows.py: %s over (%g, %g] failed:\n%s" % (script, a, b, r.stdout + r.stderr))
                for line in r.stdout.splitlines():   # profiles.py's warnings (correlated batches...)
                    if "warning" in line:
                        print("windows.py: (%g, %g] s: %s" % (a, b, line), file=sys.stderr)
            shutil.rmtree(dest, ignore_errors=True)
            shutil.copytree(os.path.join(view, "results"), dest)
        print(dest)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
