#!/usr/bin/python3
"""Unit checks of the Mueller validation scripts' bookkeeping of stopped and continued runs:
profiles.drop_superseded (samples of a stopped segment re-sampled by its continuation) and
solver_log.log_segments (wall seconds per start, cut where the continuation started, MPI ranks; a
run's pauses taken off its wall time and its stage shares), muller_plots.plot_profiles (cases at two inlet velocities, missing profiles, missing SEMs), and
window.py on a synthetic run (errors per averaging window against ones computed here, its refusals;
the same run with its samples folded by compactSamples.py),
etc/runArchive (a stopped run packed and unpacked to continue elsewhere), and the binary bed's
scripts (pressure samples of every start, runs of one case, the wall-corrected reference), and
gasBypass.py (dense cells without a particle centre, fast cells) on four hand-made cells, and the
Mueller physics checks (net solid flux, minimum fluidization, bubble chords, pressure drop).
Prints PASS/FAIL per check and "N passed, N failed"."""
import csv, math, os, random, re, shutil, struct, subprocess, sys, tempfile, time

top = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
# the functions under test live in the project's Python library, etc/python
sys.path.insert(0, os.path.join(top, "etc", "python"))
import muller_profiles as profiles  # noqa: E402
import muller_plots  # noqa: E402
import solver_log  # noqa: E402
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
    segs = solver_log.log_segments(log)
    clocks = [s["clock"] for s in segs]
    check(clocks == [200.0, 0.0, 101.0] and [s["nprocs"] for s in segs] == [1, 1, 2],
          "wall seconds per start %s (expected 200 = up to t = 0.2 where the run continued, 0, 101), "
          "ranks %s" % (clocks, [s["nprocs"] for s in segs]))

    # a run stopped (SIGSTOP) for 500 s during its kernel stage at t = 0.15: steps of 1 s, stage
    # timers printed at 0.1, 0.2, 0.3 (kernel 10 s per 0.1 s, DEM 90 s; 500 s more in 0.1-0.2)
    log = os.path.join(tmp, "logpause")
    with open(log, "w") as f:
        f.write("nProcs : 2\nCreate time\n")
        wall = 0.0
        for i in range(1, 31):
            wall += 501.0 if i == 15 else 1.0
            f.write("Time = %g\n\nProgress: t = %g s of 0.3 s, %d steps, wall %g s, estimated left 1 s\n" % (i / 100, i / 100, i, wall))
            if i % 10 == 0:
                k = 10.0 * i / 10 + (500.0 if i >= 20 else 0.0)
                f.write("Stage timers (s, share): kernel %g (1%%) DEM %g (1%%) fluid 0 (0%%)\n" % (k, 9.0 * i))
        f.write("ExecutionTime = 540 s  ClockTime = 545 s\n")   # counts the 15 s of start-up too
    seg = solver_log.log_segments(log)[0]
    share = seg["stages"]["kernel"] / (seg["stages"]["kernel"] + seg["stages"]["DEM"])
    check(abs(seg["clock"] - seg["paused"] - 45.0) < 1e-9 and len(seg["pauses"]) == 1 and abs(share - 0.1) < 1e-12,
          "a paused run: wall %g s less %g s paused (expected 30 s of steps + 15 s of start-up: the closing "
          "ClockTime is no pause), kernel share %.4f without the paused interval (expected 0.1; with it 0.63)"
          % (seg["clock"], seg["paused"], share))

    # the same run continued from its write at 0.1 s: the first start's stage lines after 0.1 s
    # (holding the pause) are the continuation's stretch, not the first start's
    with open(log, "a") as f:
        f.write("nProcs : 2\nCreate time\n")
        for i in range(11, 31):
            f.write("Time = %g\n\nProgress: t = %g s of 0.3 s, %d steps, wall %g s, estimated left 1 s\n" % (i / 100, i / 100, i, i - 10.0))
            if i % 10 == 0:
                f.write("Stage timers (s, share): kernel %g (1%%) DEM %g (1%%) fluid 0 (0%%)\n" % (i - 10.0, 9.0 * (i - 10)))
    segs = solver_log.log_segments(log)
    st = solver_log.stage_times(segs)
    check(segs[0]["paused"] == 0 and abs(segs[0]["clock"] - 10.0) < 1e-9 and abs(st["kernel"] - 30.0) < 1e-9,
          "a continued run: the first start counted to 0.1 s (wall %g s, expected 10; paused %g s, expected 0), "
          "kernel %g s over both starts (expected 10 + 20)" % (segs[0]["clock"], segs[0]["paused"], st["kernel"]))

    # DPMFoam: ClockTime in whole seconds, most steps 0 s; one 1000 s pause
    log = os.path.join(tmp, "logdpm")
    with open(log, "w") as f:
        f.write("nProcs : 1\nCreate time\n")
        for i in range(1, 101):
            f.write("Time = %g\n\nExecutionTime = 1 s  ClockTime = %d s\n" % (i / 100, i // 4 + (1000 if i > 50 else 0)))
    seg = solver_log.log_segments(log)[0]
    check(len(seg["pauses"]) == 1 and abs(seg["clock"] - seg["paused"] - 25) < 1,
          "DPMFoam, whole-second clock: %d pause(s) (expected 1 at t = 0.51), wall less pauses %g s (expected 25 +- 1)"
          % (len(seg["pauses"]), seg["clock"] - seg["paused"]))

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
        n = muller_plots.plot_profiles(out, rows, plt, "midThickness", data)
        made = os.path.exists(os.path.join(out, "profiles_all_models.png"))
        err = ""
    except Exception as e:   # any failure of the figure is this check's failure
        n, made, err = 0, False, repr(e)
    check(n == 5 and made, "profiles figure: %d panels for two inlet velocities (expected 5), PNG %s%s"
          % (n, "written" if made else "missing", (": " + err) if err else ""))

with tempfile.TemporaryDirectory() as tmp:
    # window.py on a synthetic run: samples every 0.01 s (i = 1..50 complete, a 51st being written:
    # one file of its directory), a constant profile plus noise, two columns across the thickness
    # (depthProfiles) and the mid-thickness alpha (profiles, complete up to i = 51)
    rng = random.Random(18)
    ys = [0.002 + 0.004 * j for j in range(11)]
    heights = ("15", "16.4")
    aP, aU, alpha = {}, {}, {}   # [(i, h, d)] / [(i, h)] -> values along y
    run = os.path.join(tmp, "synth_dx1_U0.9_test")
    def write(path, header, cols):
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(",".join(header) + "\n")
            for row in zip(ys, *cols):
                f.write(",".join(repr(v) for v in row) + "\n")
    for i in range(1, 52):
        t = "%g" % (i / 100)
        for h in heights:
            for d in (0, 1):
                aP[i, h, d] = [0.45 + 0.1 * y / 0.044 + rng.uniform(-0.08, 0.08) for y in ys]
                aU[i, h, d] = [a * (-0.1 + 0.2 * y / 0.044 + rng.uniform(-0.3, 0.3)) for a, y in zip(aP[i, h, d], ys)]
                base = os.path.join(run, "postProcessing", "depthProfiles", t, "z%sd%d" % (h, d))
                if i <= 50 or (h, d) == ("15", 0):
                    write(base + "_alpha_alphaPBinned.csv", ("y", "alpha", "alphaPBinned"), ([1 - a for a in aP[i, h, d]], aP[i, h, d]))
                if i <= 50:
                    write(base + "_alphaPUsBinned.csv", ("y", "alphaPUsBinned_0", "alphaPUsBinned_1", "alphaPUsBinned_2"),
                          ([0.0] * len(ys), [0.0] * len(ys), aU[i, h, d]))
            alpha[i, h] = [0.5 - 0.1 * y / 0.044 + rng.uniform(-0.1, 0.1) for y in ys]
            write(os.path.join(run, "postProcessing", "profiles", t, "z%s_alpha.csv" % h), ("y", "alpha"), (alpha[i, h],))
    data = os.path.join(tmp, "data")
    os.makedirs(data)
    mr = {}   # (data quantity, height) -> (x, value)
    for q, h in (("voidfraction", "15"), ("voidfraction", "16.4"), ("vz", "15")):
        xs = [0.0009, 0.0071, 0.0143, 0.0222, 0.0301, 0.0388, 0.0431]
        vals = [rng.uniform(0.4, 0.6) if q == "voidfraction" else rng.uniform(-0.2, 0.2) for _ in xs]
        mr[q, h] = (xs, vals)
        with open(os.path.join(data, "mueller_U0.9_%s_z%smm_MR.csv" % (q, h)), "w") as f:
            f.write("# synthetic\nx_m,%s\n" % q + "".join("%r,%r\n" % xv for xv in zip(xs, vals)))
    script = os.path.join(top, "validation", "muller", "window.py")
    def window(*args):
        return subprocess.run([sys.executable, script] + list(args), cwd=tmp, capture_output=True, text=True)
    out = os.path.join(tmp, "wout")
    r = window(run, "-tstart", "0.02", "-step", "0.07", "-U", "0.9", "-data", data, "-o", out)
    rows = list(csv.DictReader(open(os.path.join(out, "window.csv")))) if r.returncode == 0 else []
    check(r.returncode == 0 and os.path.exists(os.path.join(out, "window.png")) and rows and
          list(rows[0]) == ["run", "window_s", "quantity", "z_mm", "rms", "max", "n_samples"],
          "window.py on a synthetic run: exit %d, window.csv and window.png written%s"
          % (r.returncode, "" if r.returncode == 0 else ": " + r.stderr.strip()))

    # expected, computed here: window k holds the samples i = 3 .. 2 + 7k (0.02 < t <= 0.02 + 0.07k);
    # profiles.py averages the first B * (n // B) of its n samples, B = min(10, n // 5) (at least 1);
    # the profile files hold 6 significant digits; the simulation is interpolated linearly to the
    # data's x (held constant beyond its ends)
    def interp(x, xs, vs):
        if x <= xs[0]:
            return vs[0]
        for a, b, va, vb in zip(xs, xs[1:], vs, vs[1:]):
            if x <= b:
                return va + (x - a) / (b - a) * (vb - va)
        return vs[-1]
    six = lambda v: float("%.6g" % v)
    expected = {}
    for k in range(1, 7):
        n = 7 * k
        B = max(1, min(10, n // 5))
        used = list(range(3, 3 + B * (n // B)))
        for h in heights:
            depth_aP = [[(aP[i, h, 0][j] + aP[i, h, 1][j]) / 2 for j in range(len(ys))] for i in used]
            depth_aU = [[(aU[i, h, 0][j] + aU[i, h, 1][j]) / 2 for j in range(len(ys))] for i in used]
            prof = {"void_fraction_depth_binned": [1 - sum(a[j] for a in depth_aP) / len(used) for j in range(len(ys))],
                    "void_fraction_depth": [1 - sum(a[j] for a in depth_aP) / len(used) for j in range(len(ys))],
                    "void_fraction": [sum(alpha[i, h][j] for i in used) / len(used) for j in range(len(ys))],
                    "vz_particle_depth_binned_m_per_s": [sum(u[j] for u in depth_aU) / sum(a[j] for a in depth_aP)
                                                         for j in range(len(ys))]}
            for quantity, sim in prof.items():
                q = "vz" if quantity.startswith("vz") else "voidfraction"
                if (q, h) not in mr:
                    continue
                xs, vals = mr[q, h]
                err = [interp(x, ys, [six(v) for v in sim]) - v for x, v in zip(xs, vals)]
                expected[round(0.07 * k, 9), quantity, h] = (math.sqrt(sum(e * e for e in err) / len(err)),
                                                             max(abs(e) for e in err), len(used))
    got = {(round(float(r["window_s"]), 9), r["quantity"], r["z_mm"]): (float(r["rms"]), float(r["max"]), int(r["n_samples"]))
           for r in rows if r["run"] == "synth_dx1_U0.9_test"}
    windows = sorted(set(w for w, _, _ in got))
    check(windows == [round(0.07 * k, 9) for k in range(1, 7)] and len(rows) == len(got),
          "window.py: windows of 0.07 s after 0.02 up to the last whole sample, the one being written left out: %s" % windows)
    worst = max((abs(got[key][m] - expected[key][m]) for key in expected if key in got for m in (0, 1)), default=float("inf"))
    check(set(got) == set(expected) and worst < 1e-9 and all(got[key][2] == expected[key][2] for key in expected),
          "window.py: RMS and max error of every window, quantity and height as computed here (%d rows, worst "
          "difference %.2g, samples per window %s)" % (len(got), worst,
                                                         sorted(set((w, n) for (w, q, h), (_, _, n) in got.items()))))

    # refusals: exit status 2 and one line naming the run or the argument
    os.makedirs(os.path.join(tmp, "empty_run", "postProcessing"))
    for args, word, what in (((os.path.join(tmp, "empty_run"), "-tstart", "0"), "empty_run", "a run without samples"),
                             ((run, "-tstart", "0.6"), "-tstart 0.6", "a tstart beyond the last sample"),
                             ((run, "-tstart", "0.02", "-U", "0.7"), "-U 0.7", "an inlet velocity without data")):
        r = window(*(args + ("-data", data, "-o", out)))
        msg = r.stderr.strip()
        check(r.returncode == 2 and word in msg and "\n" not in msg,
              "window.py refuses %s: exit %d, %r" % (what, r.returncode, msg))

    # -add: the rows of a run measured before (its directory gone) kept beside the run given again
    before = open(os.path.join(out, "window.csv")).read().splitlines()
    gone = [l.replace("synth_dx1_U0.9_test", "gone_dx1_U0.9_test", 1) for l in before[1:]]
    open(os.path.join(out, "window.csv"), "w").write("\n".join(before[:1] + gone) + "\n")
    r = window(run, "-tstart", "0.02", "-step", "0.07", "-data", data, "-o", out, "-add")
    after = open(os.path.join(out, "window.csv")).read().splitlines()
    check(r.returncode == 0 and after == before[:1] + gone + before[1:],
          "window.py -add: the earlier rows of a run not given kept, the run given measured again (%d + %d rows)"
          % (len(gone), len(after) - 1 - len(gone)))

    # compactSamples.py: the same run, its samples up to its last complete write (0.3 s of 2 ranks;
    # 0.4 incomplete on one) folded in two steps into a store per function: window.py gives the rows
    # of the folders (to 1e-9), only the folders after 0.3 are left, and a time after 0.3 is refused
    comp = os.path.join(tmp, "compacted", os.path.basename(run))
    shutil.copytree(run, comp)
    os.makedirs(os.path.join(comp, "system"))
    # a stopped segment's sample at 0.15 re-sampled by its continuation at 0.15005 (same values): the
    # older folder is superseded, moved aside by the fold, not stored
    for fn in ("profiles", "depthProfiles"):
        src = os.path.join(comp, "postProcessing", fn, "0.15")
        shutil.copytree(src, src + "005")
        os.utime(src, (time.time() - 100, time.time() - 100))
    for rank, ts in (("processor0", ("0", "0.2", "0.3", "0.4")), ("processor1", ("0", "0.2", "0.3"))):
        for t in ts:
            os.makedirs(os.path.join(comp, rank, t, "uniform"))
    compact = os.path.join(top, "validation", "muller", "compactSamples.py")
    def compact_run(*args):
        return subprocess.run([sys.executable, compact, comp] + list(args), capture_output=True, text=True)
    r1, r2 = compact_run("-until", "0.2", "-from", "0.1"), compact_run("-until", "0.3")
    left = sorted(float(t) for t in os.listdir(os.path.join(comp, "postProcessing", "depthProfiles")) if t[0].isdigit())
    wout = os.path.join(tmp, "wout_compacted")
    r = window(comp, "-tstart", "0.02", "-step", "0.07", "-U", "0.9", "-data", data, "-o", wout)
    crows = list(csv.DictReader(open(os.path.join(wout, "window.csv")))) if r.returncode == 0 else []
    base_rows = [rw for rw in csv.DictReader(open(os.path.join(out, "window.csv"))) if rw["run"] == "synth_dx1_U0.9_test"]
    same = len(crows) == len(base_rows) > 0 and all(
        (a["window_s"], a["quantity"], a["z_mm"], a["n_samples"]) == (b["window_s"], b["quantity"], b["z_mm"], b["n_samples"])
        and abs(float(a["rms"]) - float(b["rms"])) < 1e-9 and abs(float(a["max"]) - float(b["max"])) < 1e-9
        for a, b in zip(crows, base_rows))
    aside = [sorted(os.listdir(os.path.join(comp, "postProcessing", fn, "superseded")))
             if os.path.isdir(os.path.join(comp, "postProcessing", fn, "superseded")) else []
             for fn in ("profiles", "depthProfiles")]
    check(r1.returncode == 0 and r2.returncode == 0 and r.returncode == 0 and same and
          left == [round(0.01 * i, 2) for i in range(31, 52)] and aside == [["0.15"], ["0.15"]] and
          "10 samples in (0.1, 0.2]" in r1.stdout and "1 superseded sample(s) moved" in r1.stdout and
          "20 samples in (-inf, 0.3]" in r2.stdout,
          "compactSamples.py folds the samples up to the last complete write (0.1-0.2, then the rest to 0.3; "
          "a superseded one moved aside) and window.py reads them as the folders: %d rows, the same: %s, %d folders left (%s)%s"
          % (len(crows), same, len(left), ", ".join("%g" % t for t in left[:1] + left[-1:]),
             "" if r.returncode == 0 and same else "; " + (r1.stdout + r2.stdout + r1.stderr + r2.stderr + r.stderr).strip()))
    r = compact_run("-until", "0.4")
    check(r.returncode == 2 and "-until 0.4" in r.stderr and "0.3" in r.stderr,
          "compactSamples.py refuses a time after the last complete write (0.4 written by one rank only): %r"
          % r.stderr.strip())

# summary.py: a run summarised before and given as its folder of the output directory (its run
# directory and logs gone, as on a fresh machine) keeps its row: the errors from the folder's
# errors.csv at full precision, wall time, ranks and shares from the table
with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "medium")
    label = "divided_dx1_U0.9_medium_background_abc1234"
    os.makedirs(os.path.join(out, label))
    with open(os.path.join(out, label, "errors.csv"), "w") as f:
        f.write("quantity,z_mm,rms_error,max_error,mean_batch_sem,rms_error_symmetrised,rms_error_noise_removed\n"
                "void_fraction_depth_binned,16.4,0.03594,0.06349,0.0092,0.0337,0.0346\n"
                "vz_particle_depth_binned_m_per_s,15,0.0506,0.1017,0.0105,0.0519,0.0495\n"
                "void_fraction,16.4,0.0411,0.07,0.01,0.04,0.04\nvz_particle_m_per_s,15,0.0514,0.09,0.01,0.05,0.05\n")
    open(os.path.join(out, label, "profiles_info.txt"), "w").write("window (2, 7] s; 499 samples\n")
    header = ("run,model,commit,ranks,wall_time_s,core_seconds,coupling_share,fluid_share,dem_share,instrument,"
              "voidfraction_z16.4_rms,voidfraction_z16.4_max,voidfraction_z16.4_mean_sem,voidfraction_z16.4_rms_symmetrised,"
              "voidfraction_z16.4_rms_noise_removed,vz_z15_rms_m_per_s,vz_z15_max_m_per_s,vz_z15_mean_sem,vz_z15_rms_symmetrised,"
              "vz_z15_rms_noise_removed,voidfraction_z16.4_other_rms,vz_z15_other_rms_m_per_s\n")
    row = label + ",divided,abc1234,2,6712,13425,0.196,0.446,0.358,depthBinned,0.0359,0.0635,0.0092,0.0337,0.0346,0.0506,0.1017,0.0105,0.0519,0.0495,0.0411,0.0514\n"
    open(os.path.join(out, "error_vs_runtime.csv"), "w").write(header + row)
    r = subprocess.run([sys.executable, os.path.join(top, "validation", "muller", "summary.py"), out, os.path.join(out, label)],
                       capture_output=True, text=True)
    table = open(os.path.join(out, "error_vs_runtime.md")).read() if r.returncode == 0 else ""
    check(r.returncode == 0 and open(os.path.join(out, "error_vs_runtime.csv")).read() == header + row and
          "| 6712 | 13425 | 19.6 % | 0.036 / 0.063 (SEM 0.009" in table and "(2, 7] s" in table,
          "summary.py keeps the row of a run given as its output folder, the max error from its errors.csv "
          "(0.063, not the table's rounded 0.0635): rc %d %s" % (r.returncode, r.stderr.strip()[-200:]))

# etc/runArchive: a stopped 2-rank run packed keeps the case, the samples and the last time complete
# (the fields of both ranks and the DEM restart coarseDemFoam writes for all ranks in <case>/<time>/),
# and unpacks into a run folder that Allrun -continue reads; it refuses to unpack over an existing run
with tempfile.TemporaryDirectory() as tmp:
    run = os.path.join(tmp, "runs", "m_dx1_U0.9_medium")
    def touch(rel, text=""):
        f = os.path.join(run, rel)
        os.makedirs(os.path.dirname(f), exist_ok=True)
        open(f, "w").write(text)
    for rel in ("system/controlDict", "constant/couplingProperties", "DEM/in.liggghts", "log.coarseDemFoam",
                "wall_seconds.txt", "commit.txt", "postProcessing/profiles/0.01/z15_alpha.csv",
                "0/U", "processor0/constant/polyMesh/points", "processor1/constant/polyMesh/points"):
        touch(rel, rel)
    for t in ("2.25", "2.5", "3"):
        touch("%s/dem.restart" % t, t)
        for rank in (0, 1):
            touch("processor%d/0/U" % rank)
            touch("processor%d/%s/U" % (rank, t), t)
            touch("processor%d/%s/uniform/time" % (rank, t))
    touch("processor0/2.75/uniform/time")   # being written: the fields of one rank only
    touch("2.75/dem.restart")
    touch("processor0/3/uniform/time")      # 3 was written completely, but before the DEM restart (no file yet):
    os.remove(os.path.join(run, "3", "dem.restart"))   # not complete either
    touch("incomplete/processor0/3.25/U")   # a write cut short, set aside by -continue: not packed
    archive = os.path.join(tmp, "m.tar.xz")
    tool = os.path.join(top, "etc", "runArchive")
    r = subprocess.run([tool, "pack", run, archive], capture_output=True, text=True)
    names = subprocess.run(["tar", "tJf", archive], capture_output=True, text=True).stdout.split() if r.returncode == 0 else []
    times = sorted(set(n.split("/")[2] for n in names if n.split("/")[1].startswith("processor") and len(n.split("/")) > 3
                       and n.split("/")[2][0].isdigit()))
    check(r.returncode == 0 and "t = 2.5 (2 ranks)" in r.stdout and times == ["0", "2.5"] and
          all("m_dx1_U0.9_medium/" + rel in names for rel in ("system/controlDict", "DEM/in.liggghts",
              "postProcessing/profiles/0.01/z15_alpha.csv", "wall_seconds.txt", "commit.txt", "2.5/dem.restart",
              "processor1/2.5/U", "processor0/constant/polyMesh/points")) and
          not any(n.startswith("m_dx1_U0.9_medium/" + t + "/") for n in names for t in ("2.25", "2.75", "3", "incomplete")),
          "runArchive pack: case, samples and the last time complete (2.5: not 3 without its DEM restart, "
          "2.75 on one rank only, nor the older 2.25, nor the writes set aside in incomplete/): %r, times %s" % (r.stdout.strip() or r.stderr.strip(), times))
    # -samplesFrom: the samples before the averaging window left out, the rest as before
    touch("postProcessing/profiles/2.01/z15_alpha.csv", "2.01")
    touch("postProcessing/profiles/2/z15_alpha.csv", "2")
    touch("postProcessing/profiles/1.99/z15_alpha.csv", "1.99")
    touch("postProcessing/readme.txt")
    touch("postProcessing/profiles/compacted.csv.gz")   # samples folded by compactSamples.py: kept
    # series (surfaceFieldValue): a folder per start, its samples running on past T
    touch("postProcessing/pInlet/0/surfaceFieldValue.dat")        # superseded by the start at 1.5
    touch("postProcessing/pInlet/1.5/surfaceFieldValue.dat")      # runs on past 2: kept
    touch("postProcessing/pOutlet/0/surfaceFieldValue.dat")       # one start only: kept
    # the DEM's particle dumps (the binary bed's post/dump<step>.liggghts), timed by the input's DEM step
    touch("DEM/in.liggghts", "units si\ntimestep        1e-5\n")
    for step in ("0000000000", "0000199999", "0000200000", "0000210000"):
        touch("post/dump%s.liggghts" % step)
    touch("post/notes.txt")
    windowed = os.path.join(tmp, "m_from2.tar.xz")
    r2 = subprocess.run([tool, "pack", "-samplesFrom", "2", run, windowed], capture_output=True, text=True)
    names2 = subprocess.run(["tar", "tJf", windowed], capture_output=True, text=True).stdout.split() if r2.returncode == 0 else []
    samples = sorted(n.split("/")[3] for n in names2 if n.startswith("m_dx1_U0.9_medium/postProcessing/profiles/")
                     and len(n.split("/")) > 4 and n.split("/")[4])
    dumps = sorted(n.split("/")[2] for n in names2 if n.startswith("m_dx1_U0.9_medium/post/") and n.split("/")[2])
    series = sorted(set("/".join(n.split("/")[2:4]) for n in names2 if re.match(r"m_dx1_U0.9_medium/postProcessing/p(In|Out)let/[^/]+/", n)))
    check(r2.returncode == 0 and samples == ["2", "2.01"] and "m_dx1_U0.9_medium/postProcessing/readme.txt" in names2 and
          "m_dx1_U0.9_medium/postProcessing/profiles/compacted.csv.gz" in names2 and
          "m_dx1_U0.9_medium/2.5/dem.restart" in names2 and series == ["pInlet/1.5", "pOutlet/0"] and
          dumps == ["dump0000200000.liggghts", "dump0000210000.liggghts", "notes.txt"],
          "runArchive pack -samplesFrom 2: the samples and DEM dumps at 2 s and later only, a series from its "
          "last start at or before 2 s, the folded samples' store, the rest as without it: samples %s, series %s, dumps %s %s"
          % (samples, series, dumps, r2.stderr.strip()[-200:]))
    # dumps whose times cannot be known (no timestep line in the DEM input) stop the packing, named
    touch("DEM/in.liggghts", "units si\n")
    r3 = subprocess.run([tool, "pack", "-samplesFrom", "2", run, os.path.join(tmp, "bad.tar.xz")], capture_output=True, text=True)
    check(r3.returncode != 0 and "in.liggghts has no timestep line" in r3.stderr and not os.path.exists(os.path.join(tmp, "bad.tar.xz")),
          "runArchive pack -samplesFrom refuses dumps of unknown times: %r" % r3.stderr.strip())
    dest = os.path.join(tmp, "elsewhere")
    r = subprocess.run([tool, "unpack", archive, dest], capture_output=True, text=True)
    restored = os.path.join(dest, "m_dx1_U0.9_medium")
    check(r.returncode == 0 and open(os.path.join(restored, "processor1", "2.5", "U")).read() == "2.5" and
          open(os.path.join(restored, "wall_seconds.txt")).read() == "wall_seconds.txt",
          "runArchive unpack: the run folder as packed (%r)" % (r.stdout.strip() or r.stderr.strip()))
    r = subprocess.run([tool, "unpack", archive, dest], capture_output=True, text=True)
    check(r.returncode != 0 and "exists" in r.stderr and restored in r.stderr,
          "runArchive refuses to unpack over an existing run: %r" % r.stderr.strip())

# etc/lastCompleteWrite on a 2-rank run that writes dem.restart.step last: 1 and 2 complete, 3 stopped
# after the fields of both ranks and its dem.restart but before dem.restart.step (complete by the
# older rule, not this one), 4 on one rank only; -setAside moves 3 and 4 of the case and of each rank
# into incomplete/ and leaves 2 as the latest time; a run stopped before its first complete write
# has none (exit 1) and -setAside takes it back to 0
with tempfile.TemporaryDirectory() as tmp:
    run = os.path.join(tmp, "r")
    def touch(rel):
        os.makedirs(os.path.dirname(os.path.join(run, rel)), exist_ok=True)
        open(os.path.join(run, rel), "w").close()
    touch("system/controlDict")
    for t in ("0", "1", "2", "3"):
        for rank in (0, 1):
            touch("processor%d/%s/U" % (rank, t))
            if t != "0":
                touch("processor%d/%s/uniform/time" % (rank, t))
        if t != "0":
            touch("%s/dem.restart" % t)
            if t != "3":
                touch("%s/dem.restart.step" % t)
    touch("processor0/4/uniform/time")
    tool = os.path.join(top, "etc", "lastCompleteWrite")
    r = subprocess.run([tool, run], capture_output=True, text=True)
    r2 = subprocess.run([tool, "-setAside", run], capture_output=True, text=True)
    moved = sorted(os.path.relpath(os.path.join(d, n), run) for d, ds, fs in os.walk(os.path.join(run, "incomplete"))
                   for n in ds if n[0].isdigit())
    left = sorted(n for n in os.listdir(os.path.join(run, "processor0")) if n[0].isdigit())
    check(r.returncode == 0 and r.stdout.strip() == "2" and r2.returncode == 0 and
          moved == ["incomplete/3", "incomplete/processor0/3", "incomplete/processor0/4", "incomplete/processor1/3"]
          and left == ["0", "1", "2"] and r2.stdout.count("cut short by a stop") == 4,
          "lastCompleteWrite: the last time with dem.restart.step (2, not 3 without it nor 4 on one rank), "
          "-setAside moves the later ones: %r, moved %s, processor0 keeps %s" % (r.stdout.strip(), moved, left))
    for t in ("1", "2"):
        os.remove(os.path.join(run, t, "dem.restart.step"))
    touch("9/dem.restart.step")   # a marker in a time the ranks do not have: the rule stays the marker's
    r = subprocess.run([tool, run], capture_output=True, text=True)
    r2 = subprocess.run([tool, "-setAside", run], capture_output=True, text=True)
    left = sorted(n for n in os.listdir(os.path.join(run, "processor1")) if n[0].isdigit())
    check(r.returncode == 1 and r.stdout == "" and r2.returncode == 0 and left == ["0"],
          "lastCompleteWrite: no complete write after 0 (exit %d, %r); -setAside leaves 0 only (%s)"
          % (r.returncode, r.stdout, left))
    # a 2-rank run started from a state and unpacked by runArchive (which keeps 0 and the last write:
    # the ranks have no 0) has its last complete write as its first time: that one, never 0
    run = os.path.join(tmp, "s")
    touch("system/controlDict")
    for rank in (0, 1):
        touch("processor%d/2.8/uniform/time" % rank)
    touch("2.8/dem.restart.step")
    r = subprocess.run([tool, run], capture_output=True, text=True)
    run = os.path.join(tmp, "z")
    touch("system/controlDict")
    touch("processor0/0/uniform/time")
    touch("0/dem.restart.step")
    r0 = subprocess.run([tool, run], capture_output=True, text=True)
    check(r.returncode == 0 and r.stdout.strip() == "2.8" and r0.returncode == 1,
          "lastCompleteWrite: a run whose first time is a complete write continues from it (%r); 0 is never "
          "a write (exit %d)" % (r.stdout.strip(), r0.returncode))

# profiles.drop_superseded after a fold: two folders left (0.3 of a stopped segment, 0.30005 of its
# continuation, written later) are told apart by the spacing of the store's times too
with tempfile.TemporaryDirectory() as tmp:
    dirs = {}
    for t, age in ((0.3, 200), (0.30005, 100)):
        d = os.path.join(tmp, "%g" % t)
        os.makedirs(d)
        os.utime(d, (time.time() - age, time.time() - age))
        dirs[t] = d
    kept, dropped = profiles.drop_superseded(dirs, [round(0.01 * k, 2) for k in range(1, 30)])
    alone, none = profiles.drop_superseded(dirs)
    check(sorted(kept) == [0.30005] and dropped == [0.3] and sorted(alone) == [0.3, 0.30005] and none == [],
          "drop_superseded: the folders' spacing taken with the store's times (kept %s, dropped %s; without "
          "them nothing is dropped: too few to know the spacing)" % (sorted(kept), dropped))

# the binary bed's scripts (tutorials/binaryBedKhan/postprocess.py, validation/khan/compare.py and
# references.py): pressure samples of every start, runs of one case only, the wall-corrected line
import dem_series  # noqa: E402
import khan_layers  # noqa: E402
import khan_pressure  # noqa: E402
import khan_references as khan_ref  # noqa: E402
import khan_runs  # noqa: E402
import numpy as np  # noqa: E402
with tempfile.TemporaryDirectory() as tmp:
    # a first start 0..0.5 s; a second from 0.5 killed at 0.7 s; a third again from 0.5 s, whose file
    # OpenFOAM names surfaceFieldValue_0.5.dat in the same folder, killed while writing its last line
    def series(folder, fname, times, value, cut=False):
        d = os.path.join(tmp, "postProcessing", "pInlet", folder)
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, fname), "w") as f:
            f.write("# Surface field value\n# Time areaAverage(p)\n")
            f.write("".join("%g\t%g\n" % (t, value) for t in times))
            if cut:
                f.write("1.01\t")
    steps = lambda a, b: [round(0.01 * k, 2) for k in range(int(round(a * 100)), int(round(b * 100)) + 1)]
    series("0", "surfaceFieldValue.dat", steps(0.01, 0.5), 1.0)
    series("0.5", "surfaceFieldValue.dat", steps(0.51, 0.7), 2.0)
    series("0.5", "surfaceFieldValue_0.5.dat", steps(0.51, 1.0), 3.0, cut=True)
    t, dp = khan_pressure.frictional_dp(tmp)
    p = (dp + khan_ref.RHO_F * khan_ref.G * khan_ref.HEIGHT) / khan_ref.RHO_F
    check(len(t) == 100 and abs(t[-1] - 1.0) < 1e-12 and (abs(p[t <= 0.5 + 1e-9] - 1.0) < 1e-9).all() and
          (abs(p[t > 0.5 + 1e-9] - 3.0) < 1e-9).all() and not khan_pressure.sample_gaps(t),
          "binary bed pressure: the last start's surfaceFieldValue_0.5.dat replaces the killed start's samples "
          "from 0.51 s, its cut last line left out (%d samples to %g s, values %s)" % (len(t), t[-1], sorted(set(p.round(6)))))
    gaps = khan_pressure.sample_gaps([0.1, 0.2, 0.3, 0.6, 0.7, 0.8])
    check(gaps == [(0.3, 0.6)], "binary bed pressure: a gap in the samples is found (%s)" % gaps)
    # a dense layer with a long dilute tail (sizeAwareDiffusion's big species at 0.015 m/s): its 5-95 %
    # interior ends in the tail, below half the plateau; the top lies where the dense part ends (the
    # walk from the interior's last cell extrapolated to -12.2 mm)
    zc = np.arange(120) * 1.0 + 0.5
    core = [0.497, 0.575, 0.629, 0.581, 0.600, 0.571, 0.572, 0.465, 0.340, 0.190, 0.110]
    tail = [0.092, 0.086, 0.084, 0.081, 0.079, 0.071, 0.064, 0.056, 0.046, 0.040, 0.035, 0.031, 0.028, 0.024, 0.019, 0.013]
    prof = np.array(core + tail + [0.0] * (120 - len(core) - len(tail)))
    lay = khan_layers.layer(zc, prof, [prof] * dem_series.NB)
    check(9.5 < lay["top"] < 10.5 and lay["bottom"] == 0.0,
          "binary bed layer of a dense core with a dilute tail: top %.2f mm (expected between 9.5 and 10.5, where "
          "the core falls below half the plateau %.3f), bottom %.2f mm (expected 0: the distributor)"
          % (lay["top"], 0.5 * lay["plateau"], lay["bottom"]))
    bad = os.path.join(tmp, "bad.dat")
    open(bad, "w").write("0.1 1\n0.2 x\n0.3 1\n")
    try:
        dem_series.read_fv(bad)
        raised = ""
    except ValueError as e:
        raised = str(e)
    check("bad.dat" in raised and "0.2 x" in raised, "a bad sample line before the last is an error naming the file: %r" % raised)

    # compare.py: the background label from bed.csv (not the name's last part), mixed cases refused
    def fake_run(name, mode, background, young, costs=True):
        d = os.path.join(tmp, "runs", name, "results")
        os.makedirs(d)
        cols = ",coupling_share,dem_per_fluid,coupling_per_fluid,commit" if costs else ""
        vals = ",0.035,20.2,0.77,b87f5cf" if costs else ""
        open(os.path.join(d, "bed.csv"), "w").write("method,U,mode,background,young_pa,ranks%s\nbigParticle,0.015,%s,%s,%s,2%s\n"
                                                    % (cols, mode, background, young, vals))
        open(os.path.join(d, "layers.csv"), "w").write("species\n")
        open(os.path.join(d, "profiles.csv"), "w").write("z_mm\n")
        return os.path.dirname(d)
    a = khan_runs.read_run(fake_run("bigParticle_U0.015_short_background_np2_E1e5", "short", "on", "100000"))
    b = khan_runs.read_run(fake_run("bigParticle_U0.015_short_np2", "short", "off", "1e+06"))
    check(a["method"] == "bigParticle+background" and b["method"] == "bigParticle",
          "binary bed compare.py: background fields labelled from bed.csv with _np2_E1e5 after it (%s, %s)" % (a["method"], b["method"]))
    try:
        khan_runs.one_case([a, b])
        refused = ""
    except SystemExit as e:
        refused = str(e)
    check("mix averaging windows or contact stiffnesses" in refused and "E = 100000 Pa" in refused and "E = 1e+06 Pa" in refused,
          "binary bed compare.py refuses runs of two contact stiffnesses, naming them: %r" % refused[:160])
    check(khan_runs.one_case([a]) == ("short", "100000"), "binary bed compare.py: one case passes")
    # the window decides, not the mode's name: a long run post-processed at 6 s compares with short runs
    def windowed(name, mode, tend):
        d = fake_run(name, mode, "off", "100000")
        bed = os.path.join(d, "results", "bed.csv")
        head, row = open(bed).read().splitlines()
        open(bed, "w").write(head + ",tstart,tend\n" + row + ",3,%s\n" % tend)
        return khan_runs.read_run(d)
    short6, long6, long13 = (windowed("divided_U0.015_short_E1e5", "short", 6), windowed("diffusion_U0.015_long_E1e5", "long", 6),
                             windowed("bigParticle_U0.015_long_E1e5", "long", 13))
    check(khan_runs.one_case([short6, long6]) == ("3..6", "100000"),
          "binary bed compare.py: a short run and a long run stopped at 6 s share the window 3..6 s")
    try:
        khan_runs.one_case([short6, long13])
        refused = ""
    except SystemExit as e:
        refused = str(e)
    check("window 3..6 s" in refused and "window 3..13 s" in refused,
          "binary bed compare.py refuses windows 3..6 and 3..13 s together, naming them: %r" % refused[:160])
    try:
        khan_runs.read_run(fake_run("centre_U0.015_short", "short", "off", "1e+06", costs=False))
        refused = ""
    except SystemExit as e:
        refused = str(e)
    check("bed.csv has no coupling_share" in refused and "-post again" in refused,
          "binary bed compare.py refuses a bed.csv without the stage costs, saying to post-process again: %r" % refused[-120:])

    # the fluid wall shear of postprocess.py (khan_pressure): uniform u_z = 0.02 m/s and alpha = 0.5 on the 10 x 10 x 120 block
    # give 4800 wall faces x rho nu sw u_z / (dx/2) dx^2; a written time outside the window is not read
    shear_run = os.path.join(tmp, "shear")
    for tdir, uz in (("5", 0.02), ("14", 1.0)):
        os.makedirs(os.path.join(shear_run, tdir))
        open(os.path.join(shear_run, tdir, "U"), "w").write(
            "FoamFile { version 2.0; format ascii; class volVectorField; object U; }\n"
            "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 %g);\n" % uz)
        open(os.path.join(shear_run, tdir, "alpha"), "w").write(
            "FoamFile { version 2.0; format ascii; class volScalarField; object alpha; }\n"
            "dimensions [0 0 0 0 0 0 0];\ninternalField uniform 0.5;\n")
    times = [(5.0, "5"), (14.0, "14")]
    ta, fa = khan_pressure.fluid_wall_shear(shear_run, times, 3, 13, True, (10, 10, 120), 1e-3)
    tb, fb = khan_pressure.fluid_wall_shear(shear_run, times, 3, 13, False, (10, 10, 120), 1e-3)
    expected = 4800 * khan_ref.RHO_F * khan_ref.NU * 0.02 / 0.5e-3 * 1e-6
    check(list(ta) == [5.0] and abs(fa[0] - 0.5 * expected) < 1e-12 * expected and abs(fb[0] - expected) < 1e-12 * expected,
          "binary bed khan_pressure: the fluid's wall shear of a uniform u_z over 4800 wall faces, alpha-weighted "
          "in Model A (%s at %s s; expected %.4g N and, Model B, %.4g N: %s)" % (list(fa), list(ta), 0.5 * expected,
                                                                             expected, list(fb)))

    # stiffness.py: a run against a stiffer one of the same case; copies of a kept run with edited values
    import khan_stiffness as khan_stiff
    kept = os.path.join(top, "validation/khan/results/runs/bigParticle_U0.015_short_np2_E1e5")

    read_rows = khan_runs.read_csv

    def write_rows(path, rows):
        with open(path, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]), lineterminator="\n")
            w.writeheader()
            w.writerows(rows)

    def edited_run(name, young, big_plateau_shift=0.0, dp_shift=0.0, method=None, dem_dt=None):
        d = os.path.join(tmp, "stiff", name)
        shutil.copytree(kept, d)
        bed = read_rows(os.path.join(d, "results", "bed.csv"))
        bed[0]["young_pa"] = young
        if dem_dt:
            bed[0]["dem_dt_s"] = dem_dt
        bed[0]["dp_pa"] = "%.6f" % (float(bed[0]["dp_pa"]) + dp_shift)
        if method:
            bed[0]["method"] = method
        write_rows(os.path.join(d, "results", "bed.csv"), bed)
        layers = read_rows(os.path.join(d, "results", "layers.csv"))
        for r in layers:
            if r["species"] == "big":
                r["alpha_p_plateau"] = "%.6f" % (float(r["alpha_p_plateau"]) + big_plateau_shift)
        write_rows(os.path.join(d, "results", "layers.csv"), layers)
        return khan_runs.read_run(d)
    soft = edited_run("soft", "100000")
    rows = khan_stiff.compare_runs(soft, edited_run("near", "1000000", big_plateau_shift=0.008, dp_shift=1.0))
    check(all(ok for _, ok in rows),
          "binary bed stiffness.py: plateau 0.008 and dp 1.0 Pa apart (within 0.01 and 1 % of the weight) agree")
    rows = khan_stiff.compare_runs(soft, edited_run("far", "1000000", big_plateau_shift=0.015, dp_shift=3.0))
    verdicts = dict((r.split("|")[1].strip(), ok) for r, ok in rows)
    check(not verdicts["big plateau alpha_p"] and not verdicts["frictional pressure drop"] and
          verdicts["small plateau alpha_p"] and verdicts["mixing region"],
          "binary bed stiffness.py: plateau 0.015 (5 sem) and dp 3.0 Pa (3.3 sem, 2.5 %% of the weight) apart "
          "differ, the unchanged quantities agree: %s" % verdicts)
    for args, want in (((soft, edited_run("other", "1000000", method="divided")), "method (bigParticle against divided)"),
                       ((edited_run("stiffer", "1000000"), soft), "is not softer than"),
                       ((edited_run("same", "100000", dem_dt="1e-05"), edited_run("same2", "100000", dem_dt="1e-05")),
                        "have the same Young's modulus and DEM step"),
                       ((soft, edited_run("nostep", "100000")), "DEM step of"),
                       ((edited_run("fine", "100000", dem_dt="1e-05"), edited_run("coarse", "100000", dem_dt="2e-05")),
                        "has not the longer step"),
                       ((edited_run("both", "100000", dem_dt="2e-05"), edited_run("both2", "1000000", dem_dt="1e-05")),
                        "both Young's modulus and the DEM step")):
        try:
            khan_stiff.compared_setting(*args)
            refused = ""
        except SystemExit as e:
            refused = str(e)
        check(want in refused, "binary bed stiffness.py refuses: %r" % refused[-110:])

    check(khan_stiff.compared_setting(edited_run("coarse2", "100000", dem_dt="2e-05"),
                                      edited_run("fine2", "100000", dem_dt="1e-05")) == "step",
          "binary bed stiffness.py compares two DEM steps of one Young's modulus (the longer first)")

    # references: Richardson-Zaki with the tube's wall correction of u_t, computed here independently
    u_t = khan_ref.terminal_velocity(1e-3)[0]
    re_t = u_t * 1e-3 / 1e-6
    n = (5.1 + 0.27 * re_t ** 0.9) / (1 + 0.1 * re_t ** 0.9)            # Garside & Al-Dibouni, solved for n
    want = 1 - (0.015 / (u_t * 10 ** -0.1)) ** (1 / n)
    got = khan_ref.alpha_richardson_zaki_wall(0.015, 1e-3)
    check(abs(got - want) < 1e-12 and got < khan_ref.alpha_richardson_zaki(0.015, 1e-3) and
          abs(khan_ref.alpha_richardson_zaki_wall(0.015, 1e-3, D=1e9) - khan_ref.alpha_richardson_zaki(0.015, 1e-3)) < 1e-9,
          "binary bed references: Richardson-Zaki with u_i = u_t 10^(-d/D), big at 0.015 m/s %.4f (here %.4f), "
          "the plain line for a wide tube" % (got, want))

    # the wall time of a run without a solver log: its wall_seconds.txt, ranks kept
    wrun = os.path.join(tmp, "nolog")
    os.makedirs(wrun)
    open(os.path.join(wrun, "wall_seconds.txt"), "w").write("100.5 2\n20 2\n")
    w = solver_log.run_wall(wrun)
    check(abs(w[0] - 120.5) < 1e-9 and abs(w[1] - 241) < 1e-9 and w[2] == [2],
          "solver_log.run_wall without a log: wall_seconds.txt summed (%g s, %g core-s, ranks %s)" % w[:3])

    # gasBypass.py on five cells: dense with a particle centre (two, one above Courant 1), dense
    # without (bare), dilute without, and dilute with one and fast; U written as a one-line list. A
    # binary field and a uniform one refused, naming the file
    brun = os.path.join(tmp, "bypass")
    os.makedirs(os.path.join(brun, "1"))
    def field(name, kind, values, one_line=False):
        sep = " " if one_line else "\n"
        open(os.path.join(brun, "1", name), "w").write(
            "FoamFile { class vol%sField; }\ninternalField nonuniform List<%s> %s%d%s(%s%s%s)\n;\n"
            "boundaryField { }\n" % (kind.capitalize(), kind, sep, len(values), sep, sep, sep.join(values), sep))
    field("Co", "scalar", ["0.5", "0.9", "0.1", "1.2", "0.85"])
    field("alpha", "scalar", ["0.45", "0.5", "0.9", "0.52", "0.8"])
    field("alphaPBinned", "scalar", ["0.5", "0", "0", "0.4", "0.1"])
    field("U", "vector", ["(0 0 1)", "(0.1 0 3)", "(0 0 0.5)", "(0 0 7)", "(0 0 9)"], one_line=True)
    tool = os.path.join(top, "validation", "muller", "gasBypass.py")
    r = subprocess.run([sys.executable, tool, brun, "1"], capture_output=True, text=True)
    out = r.stdout
    want = ["Courant number max 1.200", "dense cells (gas fraction < 0.6): 3, 1 without",
            "mean upward gas velocity 3.00 / 4.00 m/s, mean gas fraction 0.500 / 0.485",
            "gas fraction 0.50-0.55: 1 / 1 cells, upward gas velocity 3.00 / 7.00 m/s",
            "cells above Courant 1: 1, 1 dense, 0 without", "cells above Courant 0.8: 3, 2 dense, 1 without",
            "upward gas velocity 3.00-9.00 m/s"]
    check(r.returncode == 0 and all(w in out for w in want) and out.count("  gas fraction") == 1,
          "gasBypass.py: dense cells without a particle centre, their gas velocity and fraction (also at the same "
          "gas fraction), the fast cells: %s" % [w for w in want if w not in out])
    # the same Courant numbers written binary (writeFormat binary) read alike; a binary list cut
    # short, and a uniform gas fraction (which would leave the number of cells unknown), refused
    co = [0.5, 0.9, 0.1, 1.2, 0.85]
    def binary_co(values, count):
        return (b'FoamFile { format binary; arch "LSB;label=32;scalar=64"; class volScalarField; }\n'
                b"internalField nonuniform List<scalar> %d(" % count + struct.pack("<%dd" % len(values), *values)
                + b")\n;\nboundaryField { }\n")
    open(os.path.join(brun, "1", "Co"), "wb").write(binary_co(co, 5))
    r = subprocess.run([sys.executable, tool, brun, "1"], capture_output=True, text=True)
    check(r.returncode == 0 and r.stdout == out, "gasBypass.py reads a binary field as its ascii twin: %r" % r.stderr[-200:])
    refused = []
    for name, content, why in (("Co", binary_co(co[:4], 5), "Co: a binary list of 5 entries that does not end"),
                               ("alpha", b"FoamFile { }\ninternalField uniform 0.5;\n", "alpha: a uniform internalField")):
        keep = open(os.path.join(brun, "1", name), "rb").read()
        open(os.path.join(brun, "1", name), "wb").write(content)
        r = subprocess.run([sys.executable, tool, brun, "1"], capture_output=True, text=True)
        refused.append(r.returncode != 0 and why in r.stderr and "Traceback" not in r.stderr)
        open(os.path.join(brun, "1", name), "wb").write(keep)
    check(all(refused), "gasBypass.py refuses a binary list cut short and a uniform gas fraction, naming the file: %s"
          % refused)

# etc/python/foam_fields.py, the one reader of written fields and clouds: a vector field ascii,
# binary and gzipped (writeCompression) alike, a uniform one, zero-size lists, and the positions of
# a cloud ascii and binary; what does not fit refused naming the file
import foam_fields  # noqa: E402
with tempfile.TemporaryDirectory() as tmp:
    vec = [(0.1, -2.0, 3e-5), (4.0, 5.5, -6.25), (7.0, 8.0, 9.0)]
    head = b'FoamFile { version 2.0; format %s; arch "LSB;label=32;scalar=64"; class volVectorField; }\n'
    ascii_vec = head % b"ascii" + b"internalField nonuniform List<vector> 3\n(\n" + \
        b"\n".join(b"(%r %r %r)" % v for v in vec) + b"\n)\n;\nboundaryField { }\n"
    binary_vec = head % b"binary" + b"internalField nonuniform List<vector> 3(" + \
        struct.pack("<9d", *[c for v in vec for c in v]) + b")\n;\nboundaryField { }\n"
    import gzip
    for name, data in (("Ua", ascii_vec), ("Ub", binary_vec)):
        open(os.path.join(tmp, name), "wb").write(data)
    open(os.path.join(tmp, "Uz.gz"), "wb").write(gzip.compress(binary_vec))
    got = [foam_fields.read_internal_field(os.path.join(tmp, n)).tolist() for n in ("Ua", "Ub", "Uz")]
    check(all(g == [list(v) for v in vec] for g in got), "foam_fields: a vector field ascii, binary and gzipped: %s" % got[1])
    open(os.path.join(tmp, "Uu"), "wb").write(head % b"ascii" + b"internalField uniform (1 2 3);\n")
    open(os.path.join(tmp, "a0"), "wb").write(head % b"binary" + b"internalField nonuniform List<scalar> 0();\n")
    uni = foam_fields.read_internal_field(os.path.join(tmp, "Uu"), 2).tolist()
    check(uni == [[1, 2, 3], [1, 2, 3]] and foam_fields.read_internal_field(os.path.join(tmp, "a0")).shape == (0,),
          "foam_fields: a uniform vector field given the number of cells, an empty list: %s" % uni)
    pos = [(0.01, 0.02, 0.03), (-0.5, 0.25, 1.0)]
    phead = b'FoamFile { format %s; arch "LSB;label=32;scalar=64"; class Cloud<basicParticle>; object positions; }\n'
    open(os.path.join(tmp, "pa"), "wb").write(phead % b"ascii" + b"\n2\n(\n" +
                                              b"".join(b"(%r %r %r) %d\n" % (v + (k,)) for k, v in enumerate(pos)) + b")\n")
    open(os.path.join(tmp, "pb"), "wb").write(phead % b"binary" + b"\n2\n(" +
                                              b"".join(b"\n(" + struct.pack("<3di", *(v + (k,))) + b")" for k, v in enumerate(pos)) + b"\n)\n")
    got = [foam_fields.read_cloud_positions(os.path.join(tmp, n)).tolist() for n in ("pa", "pb")]
    check(all(g == [list(v) for v in pos] for g in got), "foam_fields: a cloud's positions ascii and binary: %s" % got)
    refused = []
    for name, call in (("Uu", lambda p: foam_fields.read_internal_field(p)),
                       ("pa", lambda p: foam_fields.read_internal_field(p)),
                       ("missing", lambda p: foam_fields.read_internal_field(p))):
        try:
            call(os.path.join(tmp, name))
            refused.append(False)
        except foam_fields.FieldFormatError as e:
            refused.append(str(e).startswith(os.path.join(tmp, name) + ":"))
    check(all(refused), "foam_fields refuses a uniform field without the number of cells, a file without "
          "internalField and a missing file, naming it: %s" % refused)
    # a decomposed run: two processors' parts (cells 1, 3 and 0, 2 of four), their cellProcAddressing
    # ascii and binary; a part without its field gives None, parts that miss a cell are refused
    lhead = b'FoamFile { version 2.0; format %s; arch "LSB;label=32;scalar=64"; class labelList; }\n'
    shead = b'FoamFile { version 2.0; format ascii; class volScalarField; }\n'
    for k, (cells, vals, fmt) in enumerate((([1, 3], [10.0, 30.0], b"ascii"), ([0, 2], [0.5, 20.0], b"binary"))):
        os.makedirs(os.path.join(tmp, "dec", "processor%d" % k, "constant", "polyMesh"))
        os.makedirs(os.path.join(tmp, "dec", "processor%d" % k, "1"))
        body = (b"2\n(\n%d\n%d\n)\n" % tuple(cells)) if fmt == b"ascii" else b"2(" + struct.pack("<2i", *cells) + b")\n"
        open(os.path.join(tmp, "dec", "processor%d" % k, "constant", "polyMesh", "cellProcAddressing"), "wb").write(
            lhead % fmt + b"// a comment\n" + body)
        open(os.path.join(tmp, "dec", "processor%d" % k, "1", "alpha"), "wb").write(
            shead + b"internalField nonuniform List<scalar> 2(%r %r);\n" % tuple(vals))
    whole = foam_fields.read_decomposed_field(os.path.join(tmp, "dec"), "1", "alpha", 4)
    none = foam_fields.read_decomposed_field(os.path.join(tmp, "dec"), "1", "U", 4)
    try:
        foam_fields.read_decomposed_field(os.path.join(tmp, "dec"), "1", "alpha", 5)
        short = ""
    except foam_fields.FieldFormatError as e:
        short = str(e)
    check(whole is not None and whole.tolist() == [0.5, 10.0, 20.0, 30.0] and none is None and "cover the 5 cells" in short,
          "foam_fields: a field of a decomposed run assembled by cellProcAddressing (ascii and binary): %s; a missing "
          "field gives None (%s); parts that do not cover the mesh are refused: %r" % (whole, none, short))

# the Mueller physics checks (issue 42): muller_flux.balance on profiles whose flux is known,
# muller_references' minimum fluidization (Di Felice's superficial law near Ergun, the printed slip
# form above it), muller_bubbles.chords, and muller_pressure on a hand-made run (pressure samples of
# two starts, wall forces and bed heights with DEM steps that do not start at 0)
import numpy as np  # noqa: E402
import muller_flux  # noqa: E402
import muller_references  # noqa: E402
import muller_bubbles  # noqa: E402
import muller_pressure  # noqa: E402
x = np.linspace(0, 0.044, 441)
v = 0.1 * np.cos(2 * np.pi * (x - 0.022) / 0.044)       # up in the middle, down at the sides, no net
b_even = muller_flux.balance(x, v, x, np.full_like(x, 0.5))
b_dense_up = muller_flux.balance(x, v, x, np.where(v > 0, 0.4, 0.7))   # more solid where it rises
check(abs(b_even[0]) < 1e-3 and b_dense_up[0] > 0.2 and abs(b_dense_up[3] * b_dense_up[1] + b_dense_up[2]) < 1e-12,
      "muller_flux: a half-up half-down profile balances at uniform gas fraction (%+.3f), more solid where "
      "it rises gives a net upward flux (%+.3f) and the balancing factor brings it to zero" % (b_even[0], b_dense_up[0]))
u_sup, u_slip, u_erg = (muller_references.umf_difelice(0.40), muller_references.umf_difelice(0.40, False),
                        muller_references.umf_ergun(0.40))
f_at = muller_references.difelice_force(0.40, u_sup)
w = 0.40 * (muller_references.RHO_P - muller_references.RHO_G) * muller_references.G * math.pi / 6 * muller_references.D ** 3
check(abs(f_at / w - 1) < 1e-9 and abs(u_sup / u_erg - 1) < 0.1 and u_slip > 1.2 * u_sup and 0.2 < muller_references.umf_wen_yu() < 0.5,
      "muller_references: U_mf of Di Felice at eps 0.40 carries the weight (%.3f m/s; Ergun %.3f, slip Re %.3f, Wen-Yu %.3f)"
      % (u_sup, u_erg, u_slip, muller_references.umf_wen_yu()))
ch = muller_bubbles.chords([0.9, 0.5, 0.9, 0.9, 0.5, 0.85, 0.85, 0.85], 1e-3, 0.8)
check(ch == [2e-3, 3e-3], "muller_bubbles.chords: runs of two cells or more above the threshold, one at the wall: %s" % ch)
with tempfile.TemporaryDirectory() as tmp:
    for start, t0 in (("5", 5.0), ("5.5", 5.5)):
        d = os.path.join(tmp, "postProcessing", "pInlet", start)
        os.makedirs(d)
        with open(os.path.join(d, "surfaceFieldValue.dat"), "w") as f:
            f.write("# Time areaAverage(p)\n")
            for k in range(1, 101):
                # kinematic p that gives the weight per area plus the gas column; the first start's
                # samples after 5.5 s are superseded by the second start's (10 % more)
                dp = muller_pressure.buoyant_weight() / muller_pressure.AREA * (1.1 if start == "5" and t0 + 0.01 * k > 5.5 else 1.0)
                f.write("%.4f %.8g\n" % (t0 + 0.01 * k, dp / muller_pressure.RHO_G + muller_pressure.G * muller_pressure.HEIGHT))
    os.makedirs(os.path.join(tmp, "6.0"))
    open(os.path.join(tmp, "6.0", "dem.restart.step"), "w").write("1000000\n")
    os.makedirs(os.path.join(tmp, "post"))
    os.makedirs(os.path.join(tmp, "DEM"))     # the run's DEM step, read from its script
    open(os.path.join(tmp, "DEM", "materials.liggghts"), "w").write("timestep        1e-5\n")
    with open(os.path.join(tmp, "post", "wallForce.txt"), "w") as f, open(os.path.join(tmp, "post", "bedHeight.txt"), "w") as g:
        for k in range(-200, 1):      # steps before the 6.0 s write, 500 of 1e-5 s apart: 5.0 ... 6.0 s
            step = 1000000 + 100 * k * 5
            f.write("%d %s\n" % (step, " ".join(["%.6g" % (0.01 * muller_pressure.buoyant_weight())] + ["0"] * 9)))
            g.write("%d 0.02\n" % step)
    row = muller_pressure.summary(tmp, 5.2, 6.0)
    check(abs(row["dp_rel_err"]) < 1e-6 and abs(row["wall_force_share"] - 0.01) < 1e-9 and row["samples"] == 80
          and abs(row["expansion_2zbar_over_settled"] - 4 / 3) < 1e-9,
          "muller_pressure: two starts' pressure samples (the later replacing the earlier), wall forces and bed "
          "heights timed from a write's DEM step: dp %+.2e, walls %.4f, %d samples, expansion %.4f"
          % (row["dp_rel_err"], row["wall_force_share"], row["samples"], row["expansion_2zbar_over_settled"]))

# samePhysics.py (a cost setting against the tutorial's): two windows of one run agree; a drag law
# whose Reynolds number differs (the ingredient dragSlipRe) does not. Committed runs of the study.
ing = os.path.join(top, "validation", "muller", "results", "ingredients")
def same_physics(a, b):
    r = subprocess.run([sys.executable, os.path.join(top, "validation", "muller", "samePhysics.py"),
                        os.path.join(ing, a), os.path.join(ing, b)], capture_output=True, text=True)
    return r.returncode, (r.stdout.strip().splitlines() or [""])[-1]
rc, last = same_physics("bigParticle_dx1_U0.9_study_baseline_185a0ba", "bigParticle_dx1_U0.9_study_baseline_window2_185a0ba")
check(rc == 0 and last.endswith("14 of 14 agree: UNCHANGED"), "samePhysics.py: two windows of one run: %r" % last)
rc, last = same_physics("bigParticle_dx1_U0.9_study_baseline_185a0ba", "bigParticle_dx1_U0.9_study_dragSlipRe_185a0ba")
check(rc == 0 and last.endswith("CHANGED") and "UNCHANGED" not in last and "13 of 14" in last,
      "samePhysics.py: Di Felice's Reynolds number from the interstitial slip changes the expansion: %r" % last)

# samePhysics.py -windows (the permutation test over windows): windows made from one committed window
# with offsets c (the profiles and the two scalars shifted by c times 5 % of their own mean). Settings
# whose windows have the same mean offset: no change detected (p = 1); a shift far beyond the
# windows' spread: CHANGED at the smallest p of 4 and 4 windows (2 of 70 divisions); 3 and 3: refused.
def offset_window(dst, c):
    base = os.path.join(ing, "bigParticle_dx1_U0.9_study_baseline_185a0ba")
    os.makedirs(dst)
    for name in os.listdir(base):
        src = os.path.join(base, name)
        if name.startswith("profile_") and name.endswith(".csv"):
            lines = open(src).read().splitlines()
            rows = [l.split(",") for l in lines[2:]]
            mean = sum(abs(float(r[1])) for r in rows) / len(rows)
            with open(os.path.join(dst, name), "w") as f:
                f.write("\n".join(lines[:2] + [",".join([r[0], repr(float(r[1]) + 0.05 * c * mean)] + r[2:])
                                                for r in rows]) + "\n")
        elif name == "pressure.csv":
            rows = list(csv.DictReader(open(src)))
            for r in rows:
                for k in ("dp_rel_err", "expansion_2zbar_over_settled"):
                    r[k] = repr(float(r[k]) * (1 + 0.05 * c))
            with open(os.path.join(dst, name), "w", newline="") as f:
                w = csv.DictWriter(f, fieldnames=list(rows[0]))
                w.writeheader()
                w.writerows(rows)
def same_physics_windows(tmp, ref_c, other_c):
    dirs = []
    for tag, cs in (("a", ref_c), ("b", other_c)):
        dirs.append([])
        for i, c in enumerate(cs):
            d = os.path.join(tmp, "%s%d_%g" % (tag, i, c))
            if not os.path.isdir(d):
                offset_window(d, c)
            dirs[-1].append(d)
    r = subprocess.run([sys.executable, os.path.join(top, "validation", "muller", "samePhysics.py"), "-windows"]
                       + dirs[0] + ["--"] + dirs[1], capture_output=True, text=True)
    return r.returncode, ((r.stdout + r.stderr).strip().splitlines() or [""])[-1]
with tempfile.TemporaryDirectory() as tmp:
    rc, last = same_physics_windows(tmp, [1, -1, 2, -2], [1.5, -1.5, 0.5, -0.5])
    check(rc == 0 and last.endswith("p = 1.000 over 70 divisions of the windows: NO CHANGE DETECTED"),
          "samePhysics.py -windows: windows of the same mean: %r" % last)
    rc, last = same_physics_windows(tmp, [1, -1, 2, -2], [21, 19, 22, 18])
    check(rc == 0 and "p = 0.029 over 70" in last and last.endswith(": CHANGED"),
          "samePhysics.py -windows: a shift ten times the windows' spread: %r" % last)
    rc, last = same_physics_windows(tmp, [1, -1, 2], [21, 19, 22])
    check(rc != 0 and "4 and 4 windows at least" in last, "samePhysics.py -windows: 3 and 3 refused: %r" % last)

# windows.py (a run's window cut in N): bad input stops with the reason, before anything is written
with tempfile.TemporaryDirectory() as tmp:
    win = os.path.join(top, "validation", "muller", "windows.py")
    for args, says in (([tmp, "2", "12", "5", os.path.join(tmp, "w")], "has no postProcessing"),
                       ([tmp, "12", "2", "5", os.path.join(tmp, "w")], "needs T_END > T_START"),
                       ([tmp, "2", "12", "five", os.path.join(tmp, "w")], "a whole number")):
        r = subprocess.run([sys.executable, win] + args, capture_output=True, text=True)
        check(r.returncode != 0 and says in r.stderr and not os.path.exists(os.path.join(tmp, "w")),
              "windows.py %s: %r" % (" ".join(args[1:4]), r.stderr.strip()))

print("%d passed, %d failed" % (npass, nfail))
sys.exit(1 if nfail else 0)
