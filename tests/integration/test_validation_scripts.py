#!/usr/bin/python3
"""Unit checks of the Mueller validation scripts' bookkeeping of stopped and continued runs:
profiles.drop_superseded (samples of a stopped segment re-sampled by its continuation) and
summary.log_segments (wall seconds per start, cut where the continuation started, MPI ranks), and
summary.plot_profiles (cases at two inlet velocities, missing profiles, missing SEMs).
Prints PASS/FAIL per check and "N passed, N failed"."""
import importlib.util, os, sys, tempfile, time

top = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
def load(name):
    spec = importlib.util.spec_from_file_location(name, os.path.join(top, "validation", "muller", name + ".py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod
profiles, summary = load("profiles"), load("summary")
npass = nfail = 0
def check(ok, what):
    global npass, nfail
    print(("PASS" if ok else "FAIL") + ": validation scripts: " + what)
    npass += ok
    nfail += not ok

with tempfile.TemporaryDirectory() as tmp:
    # samples every 0.01 s; a first segment stopped after 0.05 wrote 0.06008 and 0.07008, a second
    # one (continued from 0.05) 0.0599 and 0.0699, a third (again from 0.05) 0.05995 and 0.06995
    def sample(t, age):
        d = os.path.join(tmp, "%g" % t)
        os.makedirs(d)
        os.utime(d, (time.time() - age, time.time() - age))
        return d
    dirs = {}
    for k in range(1, 6):
        dirs[k / 100] = sample(k / 100, 300)
    for t, age in ((0.06008, 300), (0.07008, 300), (0.0599, 200), (0.0699, 200), (0.05995, 100), (0.06995, 100),
                   (0.08, 100), (0.09, 100)):
        dirs[t] = sample(t, age)
    kept, dropped = profiles.drop_superseded(dirs)
    check(sorted(kept) == [0.01, 0.02, 0.03, 0.04, 0.05, 0.05995, 0.06995, 0.08, 0.09] and
          dropped == [0.0599, 0.06008, 0.0699, 0.07008],
          "re-sampled instants of two stops: the newest of each group kept (kept %s)" % sorted(kept))

    # a coarseDemFoam log: a start stopped at t = 0.3 (last write 0.2), a start that failed before its
    # first step, and a start continued from 0.2 on 2 ranks that ran to the end
    log = os.path.join(tmp, "log")
    with open(log, "w") as f:
        f.write("nProcs : 1\nCreate time\n")
        for i in range(1, 31):
            f.write("Progress: t = %g s of 0.4 s, %d steps, wall %g s, estimated left 1 s\n" % (i / 100, i, 10.0 * i))
        f.write("nProcs : 1\nCreate time\n--> FOAM FATAL IO ERROR\n")
        f.write("nProcs : 2\nCreate time\n")
        for i in range(21, 41):
            f.write("Progress: t = %g s of 0.4 s, %d steps, wall %g s, estimated left 1 s\n" % (i / 100, i, 5.0 * (i - 20)))
        f.write("ExecutionTime = 90 s  ClockTime = 101 s\n")
    segs = summary.log_segments(log)
    clocks = [s["clock"] for s in segs]
    check(clocks == [200.0, 0.0, 101.0] and [s["nprocs"] for s in segs] == [1, 1, 2],
          "wall seconds per start %s (expected 200 = up to t = 0.2 where the run continued, 0, 101), "
          "ranks %s" % (clocks, [s["nprocs"] for s in segs]))

    # the profiles figure: two cases at 0.9 m/s (one without the 15 mm profile, one without SEMs),
    # one at 0.6 m/s; the data of both speeds: 3 + 2 panels, each case where it has a profile
    data = os.path.join(tmp, "data")
    os.makedirs(data)
    for U, q, h in ((0.9, "voidfraction", "16.4"), (0.9, "vz", "15"), (0.6, "voidfraction", "16.4"),
                    (0.6, "voidfraction", "31.2"), (0.9, "voidfraction", "31.2")):
        with open(os.path.join(data, "mueller_U%g_%s_z%smm_MR.csv" % (U, q, h)), "w") as f:
            f.write("# test\nx_m,%s\n0.01,0.5\n0.03,0.6\n" % q)
    out = os.path.join(tmp, "out")
    rows = []
    for name, commit, profs, sem in (("a_dx1_U0.9_short", "c1", ("voidfraction_z16.4mm",), "0.01"),
                                     ("b_dx1_U0.9_short", "c2", ("voidfraction_z16.4mm", "vz_z15mm"), ""),
                                     ("a_dx0.67_U0.6_short", "c3", ("voidfraction_z16.4mm",), "0.02")):
        run = name + "_" + commit
        os.makedirs(os.path.join(out, run))
        for pr in profs:
            with open(os.path.join(out, run, "profile_%s.csv" % pr), "w") as f:
                f.write("# test\nx_m,q,sem\n0.005,0.5,%s\n0.039,0.55,%s\n" % (sem, sem))
        rows.append({"run": run, "name": name, "commit": commit})
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    try:
        n = summary.plot_profiles(out, rows, plt, data)
        made = os.path.exists(os.path.join(out, "profiles_all_models.png"))
        err = ""
    except Exception as e:   # any failure of the figure is this check's failure
        n, made, err = 0, False, repr(e)
    check(n == 5 and made, "profiles figure: %d panels for two inlet velocities (expected 5), PNG %s%s"
          % (n, "written" if made else "missing", (": " + err) if err else ""))

print("%d passed, %d failed" % (npass, nfail))
sys.exit(1 if nfail else 0)
