#!/usr/bin/python3
"""How the error against the MR data changes with the length of the averaging window.

    window.py <run dir> [<run dir> ...] -tstart T [-step 0.5] [-U 0.9] [-o out dir] [-data dir] [-add]

Whether a run's statistics have converged: for each run the profiles are averaged over the
windows (T, T + step], (T, T + 2 step], ... up to the run's last sample, and each is compared with
the MR data. Per window, the averages are made by profiles.py's own functions (read_series with
drop_superseded for restarted runs, depth_average, write_profiles: the same whole batches, the
same means, the same 6-digit profile files, written to a temporary directory) and compared by
compare.py's compare (the simulation interpolated to the data's x; RMS and maximum error): the
numbers of a window are those that `profiles.py <run> T T+k*step` followed by compare.py would
give. Every variant the run samples is compared (mid-thickness voidfraction, vz, vzbinned; depth-
averaged voidfractiondepthbinned, vzdepthbinned, voidfractiondepth), at every height that has an
MR data file for U (data directory: default data/ next to this script).

Writes <out>/window.csv (run,window_s,quantity,z_mm,rms,max,n_samples; quantity as in compare.py's
errors.csv, n_samples the samples the mean is over: profiles.py's whole batches, so a window of n
samples may use fewer, e.g. 20 of 21) and <out>/window.png: the RMS error against the window
length for the headline quantities (depth-averaged, particles binned by their centre's cell), one
panel for the gas fraction and one for the particle v_z, one line per run (its label is the run
directory's name) with the RMS averaged over the heights that have data, and a thin line per height
where there are several. Default out dir: ./window. -add: keep the rows of <out>/window.csv of the
runs not given (runs measured before, whose run directories may be gone) and draw them too.

Assumptions: samples in <run>/postProcessing/depthProfiles/<time>/ (and profiles/<time>/), or
compacted (compactSamples.py), as profiles.py reads them. A window is taken while its end is at
most half a sample spacing after the last sample (sample times are shifted by up to a CFD step). A
run still being written: a last sample directory with fewer files than the one before it is being
written and is left out. The
batch-means SEMs and their corrections (compare.py's symmetrised and noise-removed RMS) are not
in this table: compare.py on a chosen window gives them.
Errors (exit status 2, one line): a run without samples, a tstart at or beyond a run's last sample
or with no whole window after it, an inlet velocity without MR data.
"""
import contextlib, csv, glob, io, math, os, re, sys, tempfile

# the project's Python library, etc/python (COARSEDEM_DIR: this file may run from a copy of its folder)
sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."), "etc", "python"))
import muller_compare as compare  # noqa: E402
import muller_profiles as profiles  # noqa: E402

DATA_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")
BATCHES, MIN_BATCH = 10, 5          # profiles.py's defaults
HEADLINE = [(compare.QUANTITY["voidfractiondepthbinned"], "gas fraction, depth-averaged, binned"),
            (compare.QUANTITY["vzdepthbinned"], "particle v_z, depth-averaged, binned (m/s)")]


def fail(msg):
    print(f"window.py: {msg}", file=sys.stderr)
    sys.exit(2)


def mr_heights(data_dir, U):
    """The heights (as written in the file names) of the MR data files at inlet velocity U, and the
    inlet velocities that have data."""
    heights, speeds = set(), set()
    for path in glob.glob(os.path.join(data_dir, "mueller_U*_*_z*mm_MR.csv")):
        m = re.match(r"mueller_U([0-9.]+)_\w+?_z([0-9.]+)mm_MR\.csv$", os.path.basename(path))
        if m:
            speeds.add(float(m.group(1)))
            if abs(float(m.group(1)) - U) <= 1e-9:
                heights.add(m.group(2))
    return heights, sorted(speeds)


def sample_times(base, store):
    """The sample times under a function object's directory (its folders and its compacted
    samples, store: profiles.read_store of it), without a last folder still being written (fewer
    files than the one before it)."""
    counts = {}
    for t, d in profiles.sample_dirs(base).items():
        n = len(glob.glob(os.path.join(d, "z*.csv")))
        if n:
            counts[t] = n
    ts = sorted(counts)
    if len(ts) > 1 and counts[ts[-1]] < counts[ts[-2]]:
        print(f"window.py: {base}: the sample at {ts[-1]:g} s is still being written, left out")
        ts.pop()
    return sorted(set(ts).union(t for byt in store.values() for t in byt))


def windows(name, times, tstart, step):
    """The window ends tstart + k step, k = 1, 2, ..., while the end is at most half a sample
    spacing after the last sample."""
    last = times[-1]
    if tstart >= last:
        fail(f"{name}: -tstart {tstart:g} is at or beyond the last sample ({last:g} s)")
    gaps = sorted(b - a for a, b in zip(times, times[1:]))
    half = 0.5 * gaps[len(gaps) // 2] if gaps else 0.0
    k = int(math.floor((last + half - tstart) / step + 1e-9))
    if k < 1:
        fail(f"{name}: no whole window of -step {step:g} s after -tstart {tstart:g} (last sample {last:g} s)")
    return [round(j * step, 12) for j in range(1, k + 1)]


def in_window(series, t0, t1):
    """The part of a series {set: {time: record}} with t0 < t <= t1, as profiles.read_series selects."""
    out = {}
    for name, byt in series.items():
        sub = {t: rec for t, rec in byt.items() if t0 < t <= t1 + 1e-9}
        if sub:
            out[name] = sub
    return out


def used_samples(path):
    """The number of samples a profile file's mean is over, from write_profiles' first line."""
    with open(path) as f:
        m = re.search(r"(\d+) of \d+ samples", f.readline())
    return int(m.group(1)) if m else -1


def window_errors(mid, depth, t0, t1, data_dir, U):
    """The rows of compare.compare for the profiles averaged over (t0, t1], each with the number
    of samples of its mean. The per-profile PNGs of compare_one are not drawn (it draws only when
    matplotlib imports, and a None in sys.modules makes that import fail) and its messages are
    returned apart."""
    with tempfile.TemporaryDirectory() as tmp:
        os.makedirs(os.path.join(tmp, "results"))
        info, lag1 = [], []
        if mid:
            profiles.write_profiles(tmp, mid, t0, t1, BATCHES, MIN_BATCH, profiles.MID_THICKNESS, info, lag1)
        if depth:
            profiles.write_profiles(tmp, depth, t0, t1, BATCHES, MIN_BATCH, profiles.DEPTH, info, lag1)
        saved = sys.modules.get("matplotlib")
        sys.modules["matplotlib"] = None
        said = io.StringIO()
        try:
            with contextlib.redirect_stdout(said):
                rows = compare.compare(os.path.join(tmp, "results"), data_dir, U, os.path.join(tmp, "cmp"))
        finally:
            if saved is None:
                del sys.modules["matplotlib"]
            else:
                sys.modules["matplotlib"] = saved
        name_of = {v: k for k, v in compare.QUANTITY.items()}
        for r in rows:
            q = name_of.get(r["quantity"], r["quantity"])
            r["n_samples"] = used_samples(os.path.join(tmp, "results", f"profile_{q}_z{r['z_mm']}mm.csv"))
    return rows, said.getvalue().splitlines()


def plot(out, table, tstart):
    """RMS error against the window length, a panel per headline quantity, a line per run."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("window.py: matplotlib missing, no PNG")
        return False
    fig, axes = plt.subplots(1, len(HEADLINE), figsize=(5.5 * len(HEADLINE), 4.2), squeeze=False)
    runs = list(dict.fromkeys(r["run"] for r in table))
    for ax, (quantity, label) in zip(axes[0], HEADLINE):
        for i, run in enumerate(runs):
            rows = [r for r in table if r["run"] == run and r["quantity"] == quantity]
            if not rows:
                continue
            colour = f"C{i % 10}"
            heights = sorted(set(r["z_mm"] for r in rows), key=float)
            ws = sorted(set(r["window_s"] for r in rows))
            mean = [sum(r["rms"] for r in rows if r["window_s"] == w) /
                    sum(1 for r in rows if r["window_s"] == w) for w in ws]
            ax.plot(ws, mean, "o-", color=colour, ms=3,
                    label=run + (f" (mean of z = {', '.join(heights)} mm)" if len(heights) > 1 else f" (z = {heights[0]} mm)"))
            if len(heights) > 1:
                for h in heights:
                    hr = sorted((r["window_s"], r["rms"]) for r in rows if r["z_mm"] == h)
                    ax.plot([w for w, _ in hr], [e for _, e in hr], "-", color=colour, lw=0.7, alpha=0.5)
        ax.set_title(label, fontsize=10)
        ax.set_xlabel(f"averaging window after t = {tstart:g} s (s)")
        ax.set_ylabel("RMS error against the MR data")
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("Mueller bed: the error against the averaging window (one line per run; where several heights "
                 "have data: their mean, thin lines the single heights)", fontsize=9)
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    fig.savefig(os.path.join(out, "window.png"), dpi=110)
    plt.close(fig)
    return True


def kept_rows(path, given):
    """The rows of an earlier window.csv of the runs not in `given` (-add), as the table's dicts."""
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [{"run": r["run"], "window_s": float(r["window_s"]), "quantity": r["quantity"], "z_mm": r["z_mm"],
                 "rms": float(r["rms"]), "max": float(r["max"]), "n_samples": int(r["n_samples"])}
                for r in csv.DictReader(f) if r["run"] not in given]


def main():
    args = sys.argv[1:]
    add = "-add" in args
    args = [a for a in args if a != "-add"]
    opts = {"-tstart": None, "-step": "0.5", "-U": "0.9", "-o": "window", "-data": DATA_DIR}
    for key in opts:
        if key in args:
            i = args.index(key)
            if i + 1 >= len(args):
                fail(f"{key} needs a value")
            opts[key] = args[i + 1]
            del args[i:i + 2]
    if not args or opts["-tstart"] is None:
        print(__doc__, file=sys.stderr)
        fail("give at least one run directory and -tstart")
    bad = [a for a in args if a.startswith("-")]
    if bad:
        fail(f"unknown option {bad[0]}")
    nums = {}
    for key in ("-tstart", "-step", "-U"):
        try:
            nums[key] = float(opts[key])
        except ValueError:
            fail(f"{key} {opts[key]}: not a number")
    tstart, step, U, out, data_dir = nums["-tstart"], nums["-step"], nums["-U"], opts["-o"], opts["-data"]
    if not step > 0:
        fail(f"-step {opts['-step']}: must be positive")
    heights, speeds = mr_heights(data_dir, U)
    if not heights:
        fail(f"-U {opts['-U']}: no MR data at that inlet velocity in {data_dir} "
             f"(data for U = {', '.join('%g' % s for s in speeds) or 'none'})")

    # every run checked before any is averaged
    plan = []
    for run in args:
        name = os.path.basename(os.path.normpath(run))
        bases = {k: os.path.join(run, "postProcessing", k) for k in ("profiles", "depthProfiles")}
        stores = {k: profiles.read_store(b) for k, b in bases.items()}   # read once, used twice
        times = {k: sample_times(b, stores[k]) for k, b in bases.items()}
        present = [ts for ts in times.values() if ts]
        if not present:
            fail(f"{name}: no samples in {bases['profiles']} or {bases['depthProfiles']}")
        if not times["depthProfiles"]:
            print(f"window.py: {name}: no depth-averaged samples (postProcessing/depthProfiles): "
                  "mid-thickness quantities in window.csv only, not in the figure")
        m = re.search(r"_U([0-9.]+)_", name)
        if m and abs(float(m.group(1)) - U) > 1e-9:
            print(f"window.py: warning: {name} looks like a run at U = {m.group(1)}, compared with the data for {U:g}")
        # the windows of the series that ends first, so every window is whole for both
        ends = windows(name, min(present, key=lambda ts: ts[-1]), tstart, step)
        plan.append((run, name, bases, stores, times, ends))

    table = []
    for run, name, bases, stores, times, ends in plan:
        t_read = tstart + ends[-1]
        def keep(series):   # the heights with data ("z16.4" for the file's "z16.4mm")
            return {s: byt for s, byt in series.items() if s[1:] in heights}
        mid = keep(profiles.read_series(bases["profiles"], tstart, t_read, stores["profiles"])[0]) if times["profiles"] else {}
        depth = {}
        if times["depthProfiles"]:
            depth = keep(profiles.depth_average(profiles.read_series(bases["depthProfiles"], tstart, t_read,
                                                                     stores["depthProfiles"])[0]))
        stores.clear()   # this run's samples are in mid and depth now
        messages = []
        for w in ends:
            t1 = tstart + w
            rows, said = window_errors(in_window(mid, tstart, t1), in_window(depth, tstart, t1), tstart, t1, data_dir, U)
            messages += [m for m in said if m not in messages]
            for r in rows:
                table.append({"run": name, "window_s": w, "quantity": r["quantity"], "z_mm": r["z_mm"],
                              "rms": r["rms_error"], "max": r["max_error"], "n_samples": r["n_samples"]})
            head = [f"{q} RMS {r['rms_error']:.4f} (z = {r['z_mm']} mm)"
                    for q, _ in HEADLINE for r in rows if r["quantity"] == q]
            print(f"{name}: window ({tstart:g}, {t1:g}] s: " + ("; ".join(head) or "no headline quantity"))
        for m in messages:
            print(f"window.py: {name}: {m}")

    os.makedirs(out, exist_ok=True)
    if add:
        table = kept_rows(os.path.join(out, "window.csv"), set(r[1] for r in plan)) + table
    with open(os.path.join(out, "window.csv"), "w") as f:
        f.write("run,window_s,quantity,z_mm,rms,max,n_samples\n")
        for r in table:
            f.write(f"{r['run']},{r['window_s']:g},{r['quantity']},{r['z_mm']},{r['rms']:.10g},{r['max']:.10g},{r['n_samples']}\n")
    made = plot(out, table, tstart)
    print(f"window.py: wrote {os.path.join(out, 'window.csv')}" + (f" and {os.path.join(out, 'window.png')}" if made else ""))


if __name__ == "__main__":
    main()
