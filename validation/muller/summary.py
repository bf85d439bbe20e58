#!/usr/bin/python3
"""Error against run time for the Mueller-bed runs of every model.

    summary.py [-instrument depthBinned|midThickness] <out dir> <run dir> [<run dir> ...]

For each run (tutorials/fluidizedBedMuller/runs/<model>_dx<..>_U<..>_<mode>): the RMS errors from
results/comparison/errors.csv (compare.py), the wall time (per start of the solver, from its log or
wall_seconds.txt, summed over restarts) and the coupling share of it from the solver's stage timers
(every stage but DEM, fluid and the output-only fields, over all stages; each start's last line,
summed; runs before the stages were renamed have other names, the same rule holds). Copies each run's
profile CSVs and comparison plots to <out>/<run>_<commit>/ (runs of one model at different commits
side by side) and writes <out>/error_vs_runtime.{csv,md,png}; the PNG labels each model's last run
on the command line (give the runs oldest first) and shows its earlier runs as grey circles.
A run given as one of <out>'s own folders (<out>/<run>_<commit>, made by an earlier summary, whose
run directory and logs may be gone) keeps its row of <out>/error_vs_runtime.csv.

The instrument of the headline columns and figures (RMS and maximum error, batch SEM, symmetrised
and noise-removed RMS): `depthBinned` (default; the gas fraction and particle v_z averaged over the
bed's depth, particles counted in the cell of their centre, independent of the method under test,
as the MR data were measured: validation/muller/README.md) or `midThickness` (the method's own alpha
and v_z on the mid-thickness line: the runs made before the depth-averaged profiles existed). The
other instrument's RMS stays in further columns.
<out>/profiles_all_models.png: for every MR data file at an inlet velocity of the runs (the data
directory next to this script), each case's last run (model, dx/d, U and mode) against the data.
<out>/profiles_all_heights.png: each case's last run at every sampled height (15 ... 35 mm), gas
fraction and particle v_z of the headline instrument, with the MR data where they exist.
"""
import collections, csv, glob, os, re, shutil, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare import read_profile

DATA_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")

# an instrument: the errors.csv quantities of the gas fraction and the particle v_z, the profile
# file stems of the MR data's quantities (voidfraction, vz), and its words in tables and figures
Instrument = collections.namedtuple("Instrument", "void_error vz_error stems words")
INSTRUMENTS = {
    "depthBinned": Instrument("void_fraction_depth_binned", "vz_particle_depth_binned_m_per_s",
                              {"voidfraction": "voidfractiondepthbinned", "vz": "vzdepthbinned"},
                              "depth-averaged, binned"),
    "midThickness": Instrument("void_fraction", "vz_particle_m_per_s",
                               {"voidfraction": "voidfraction", "vz": "vz"}, "mid-thickness"),
}
# per headline instrument: (the headline's, the other's) for the error columns
ERROR_INSTRUMENTS = {k: (INSTRUMENTS[k], INSTRUMENTS["midThickness" if k == "depthBinned" else "depthBinned"])
                     for k in INSTRUMENTS}
HEIGHTS_MM = ("15", "16.4", "20", "25", "31.2", "35")


def inlet_of(name):
    """The inlet velocity (m/s, as written) in a run's name (..._U0.9_...), or None."""
    m = re.search(r"_U([0-9.]+)_", name)
    return m.group(1) if m else None


def draw_profile(ax, path, label, **style):
    """A run's time-averaged profile (x in mm) with +-2 batch SEM as a band where the SEMs exist;
    False when the file is missing or empty."""
    if not os.path.exists(path):
        return False
    _, sx, sy, se = read_profile(path)
    if not sx:
        return False
    xs = [x * 1e3 for x in sx]
    line, = ax.plot(xs, sy, "-", label=label, **style)
    if all(e == e for e in se):
        ax.fill_between(xs, [y - 2 * e for y, e in zip(sy, se)], [y + 2 * e for y, e in zip(sy, se)],
                        color=line.get_color(), alpha=0.12, lw=0)
    return True


def plot_profiles(out, rows, plt, instrument, data_dir=DATA_DIR):
    """One panel per MR data file at an inlet velocity of the runs: each case's last run (a case:
    model, dx/d, U and mode, the run directory's name) against the data, its profile as copied to
    <out>, +-2 batch SEM as a band. Returns the number of panels."""
    latest = {r["name"]: r for r in rows}
    def inlet(name):
        u = inlet_of(name)
        return float(u) if u else None
    files = []
    for path in sorted(glob.glob(os.path.join(data_dir, "mueller_U*_*_z*mm_MR.csv"))):
        m = re.match(r"mueller_U([0-9.]+)_(\w+?)_z([0-9.]+)mm_MR\.csv", os.path.basename(path))
        if m and any(inlet(n) == float(m.group(1)) for n in latest):
            files.append((path, float(m.group(1)), m.group(2), m.group(3)))
    if not files:
        return 0
    fig, axes = plt.subplots(1, len(files), figsize=(5.5 * len(files), 4.2), squeeze=False)
    for ax, (path, U, q, h) in zip(axes[0], files):
        for name, r in latest.items():
            if inlet(name) != U:
                continue
            label = name.replace(f"_U{inlet_of(name)}", "")
            draw_profile(ax, os.path.join(out, r["run"], f"profile_{INSTRUMENTS[instrument].stems[q]}_z{h}mm.csv"),
                         f"{label} ({r['commit']})")
        _, dx, dy, _ = read_profile(path)
        ax.plot([x * 1e3 for x in dx], dy, "ko", ms=4, label="Müller et al. (MR)")
        ax.set_xlabel("distance from the left wall (mm)")
        ax.set_ylabel({"voidfraction": "time-averaged gas fraction",
                       "vz": "time-averaged particle v_z (m/s)"}.get(q, q))
        ax.set_title(f"U = {U:g} m/s, z = {h} mm")
        ax.legend(fontsize=7)
    fig.suptitle(f"Mueller bed: each case's last run against the MR data ({INSTRUMENTS[instrument].words}; bands: +-2 batch SEM)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "profiles_all_models.png"), dpi=110)
    plt.close(fig)
    return len(files)


def case_labels(names):
    """{run directory name: legend label}: the model and the parts of the name (mesh, inlet, mode,
    background) that differ between the cases drawn, e.g. "diffusion medium" and "diffusion full"."""
    parts = {n: n.split("_") for n in names}
    common = set.intersection(*(set(p[1:]) for p in parts.values())) if parts else set()
    return {n: " ".join([p[0]] + [x for x in p[1:] if x not in common]) for n, p in parts.items()}


def plot_all_heights(out, rows, plt, instrument, data_dir=DATA_DIR):
    """Two rows (gas fraction, particle v_z) by six heights: each case's last run, its profile with
    +-2 batch SEM, and the MR data where they exist at the runs' inlet velocity."""
    latest = {r["name"]: r for r in rows}
    labels = case_labels(latest)
    fig, axes = plt.subplots(2, len(HEIGHTS_MM), figsize=(3.2 * len(HEIGHTS_MM), 6.5), sharey="row")
    for i, q in enumerate(("voidfraction", "vz")):
        for ax, h in zip(axes[i], HEIGHTS_MM):
            inlets = set()
            for name, r in latest.items():
                sim = os.path.join(out, r["run"], f"profile_{INSTRUMENTS[instrument].stems[q]}_z{h}mm.csv")
                if draw_profile(ax, sim, labels[name], lw=1):
                    inlets.add(inlet_of(name))
            for U in sorted(u for u in inlets if u):
                data = os.path.join(data_dir, f"mueller_U{U}_{q}_z{h}mm_MR.csv")
                if os.path.exists(data):
                    _, dx, dy, _ = read_profile(data)
                    ax.plot([x * 1e3 for x in dx], dy, "ko", ms=3, label=f"MR, U = {U} m/s")
            ax.set_title(f"z = {h} mm", fontsize=9)
            ax.set_xlabel("x (mm)", fontsize=8)
        axes[i][0].set_ylabel("gas fraction" if q == "voidfraction" else "particle v_z (m/s)")
    axes[0][0].legend(fontsize=6)
    fig.suptitle(f"Mueller bed, every sampled height ({INSTRUMENTS[instrument].words}; bands: +-2 batch SEM)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "profiles_all_heights.png"), dpi=100)
    plt.close(fig)


def log_segments(log):
    """Per start of the solver (a log continued after a restart holds several, each beginning with
    OpenFOAM's "Create time"): its last stage-timer line (the timers count from each start) and its
    wall seconds. The wall clock is read at every step: coarseDemFoam's "Progress: t = T s ...,
    wall W s", DPMFoam's "Time = T" then "ClockTime = W". A start that was stopped and continued
    from its last write is counted up to the time the continuation started from: the stretch after
    it was computed again (and is counted there). Its stage timers were last printed at that write,
    so they cover the same stretch.

    Pauses: a long run stopped by SIGSTOP (the machine needed for something else) shows as one step
    whose wall time is PAUSE_FACTOR times the segment's median step or more. The excess over the
    median is the pause: taken off the segment's clock (seg["paused"], seg["pauses"]), and the
    stage-timer intervals holding one are left out of the stage shares (seg["stages"] is then the
    sum of the clean intervals), since the stage that was running when the run was stopped would
    otherwise carry the whole pause."""
    segs, t, nprocs = [], None, 1
    for line in open(log, errors="replace"):
        m = re.match(r"nProcs\s*:\s*(\d+)", line)   # in OpenFOAM's banner, before "Create time"
        if m:
            nprocs = int(m.group(1))
        elif line.startswith("Create time"):
            segs.append({"stage_lines": [], "walls": [], "nprocs": nprocs})
            t, nprocs = None, 1
        elif not segs:
            continue
        elif line.startswith("Stage timers"):
            segs[-1]["stage_lines"].append((t, {m.group(1): float(m.group(2)) for m in re.finditer(r"(\w+) ([0-9.eE+-]+) \(", line)}))
        elif line.startswith("Time = "):
            t = float(line.split()[2])
        else:
            m = re.match(r"Progress: t = ([0-9.eE+-]+) s .* wall ([0-9.eE+-]+) s", line)
            if m:
                segs[-1]["walls"].append((float(m.group(1)), float(m.group(2)), "progress"))
                continue
            m = re.search(r"ClockTime = ([0-9.eE+-]+)", line)
            if m:
                segs[-1]["walls"].append((t if t is not None else float("inf"), float(m.group(1)), "clock"))
    # each segment counts up to the earliest time any later segment started from (a start that
    # failed before its first step has no wall entries and cuts nothing)
    restart = float("inf")
    for seg in reversed(segs):
        walls = seg["walls"] if restart == float("inf") else [w for w in seg["walls"] if w[0] < restart]
        seg["clock"] = max((w[1] for w in walls), default=0.0)
        seg["pauses"] = find_pauses(walls)
        seg["paused"] = sum(p for _, p in seg["pauses"])
        lines = [l for l in seg["stage_lines"] if l[0] is None or l[0] <= restart]
        seg["stages"] = clean_stages(lines, [t for t, _ in seg["pauses"]])
        if seg["walls"]:
            restart = min(restart, seg["walls"][0][0])
    return segs

PAUSE_FACTOR = 100   # a step this many times the typical step: the run was stopped, not slow


def find_pauses(walls):
    """(time, seconds) of each pause among a segment's wall samples (time, wall, kind). Steps of one
    kind only: coarseDemFoam's "Progress" walls (its closing ClockTime counts from an earlier
    start, and its last "step" would hold the start-up), else DPMFoam's ClockTime (whole seconds:
    the typical step is the median, or where most steps round to 0 s the mean of the steps
    without their largest tenth, which would hold the pauses)."""
    kind = "progress" if any(w[2] == "progress" for w in walls) else "clock"
    ws = [w for w in walls if w[2] == kind]
    steps = sorted(b[1] - a[1] for a, b in zip(ws, ws[1:]))
    if not steps:
        return []
    kept = steps[:max(1, len(steps) - len(steps) // 10)]
    typical = steps[len(steps) // 2] or sum(kept) / len(kept)
    return [(b[0], b[1] - a[1] - typical) for a, b in zip(ws, ws[1:])
            if typical > 0 and b[1] - a[1] >= PAUSE_FACTOR * typical]


def clean_stages(lines, pause_times):
    """Stage seconds of a segment: its last stage-timer line, or without pauses, the sum of the
    increments between consecutive lines (from zero at the start) whose interval holds no pause."""
    if not lines:
        return None
    if not pause_times:
        return lines[-1][1]
    total, prev_t, prev = {}, float("-inf"), {}
    for t, cum in lines:
        if not any(prev_t < p <= t for p in pause_times):
            for k, v in cum.items():
                total[k] = total.get(k, 0.0) + v - prev.get(k, 0.0)
        prev_t, prev = t, cum
    return total

# the solver's stage timers that are not the coupling's (src/openfoam/coupling/stageTimers.H)
NOT_COUPLING = ("DEM", "fluid", "fields")

def stage_times(segs):
    """Stage seconds summed over the segments (None without any stage-timer line)."""
    total = {}
    for seg in segs:
        for k, v in (seg["stages"] or {}).items():
            total[k] = total.get(k, 0.0) + v
    return total or None

def run_wall(run):
    """(wall seconds, core seconds, sorted MPI rank counts, log segments, pauses) of a run directory.
    The solver log has every start, also one cut by a kill, each with its ranks (OpenFOAM's nProcs),
    its pauses taken off and the stretch computed again after a restart counted once
    (log_segments); wall_seconds.txt (one line per (re)start that returned, "<wall seconds>
    [<MPI ranks>]") only where there is no log."""
    logs = [p for p in (os.path.join(run, "log.coarseDemFoam"), os.path.join(run, "log.DPMFoam")) if os.path.exists(p)]
    segs = log_segments(logs[0]) if logs else []
    if segs:
        wall = sum(seg["clock"] - seg["paused"] for seg in segs)
        core = sum((seg["clock"] - seg["paused"]) * seg["nprocs"] for seg in segs)
        return wall, core, sorted(set(seg["nprocs"] for seg in segs)), segs, [p for seg in segs for p in seg["pauses"]]
    wpath = os.path.join(run, "wall_seconds.txt")
    starts = [l.split() for l in open(wpath) if l.strip()] if os.path.exists(wpath) else []
    wall = sum(float(t[0]) for t in starts)
    core = sum(float(t[0]) * (int(t[1]) if len(t) > 1 else 1) for t in starts)
    return wall, core, sorted(set(int(t[1]) if len(t) > 1 else 1 for t in starts)) or [1], segs, []

# error_vs_runtime.csv's columns after "instrument", in order, and the row keys they hold
CSV_ERRORS = ("void_rms", "void_max", "void_sem", "void_sym", "void_clean",
              "vz_rms", "vz_max", "vz_sem", "vz_sym", "vz_clean", "void_other", "vz_other")


def error_fields(path, head, other):
    """A run's errors from its errors.csv (compare.py) as the row keys of CSV_ERRORS: the headline
    instrument's RMS, max, SEM, symmetrised and noise-removed RMS of the gas fraction at 16.4 mm and
    the particle v_z at 15 mm, and the other instrument's RMS (nan where missing; older files lack
    the symmetrised and noise-removed RMS)."""
    errs = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            errs[(r["quantity"], r["z_mm"])] = tuple(float(r.get(k) or "nan") for k in (
                "rms_error", "max_error", "mean_batch_sem", "rms_error_symmetrised", "rms_error_noise_removed"))
    nan5 = (float("nan"),) * 5
    void, vz = errs.get((head.void_error, "16.4"), nan5), errs.get((head.vz_error, "15"), nan5)
    fields = dict(zip(CSV_ERRORS[:5], void), **dict(zip(CSV_ERRORS[5:10], vz)))
    fields["void_other"] = errs.get((other.void_error, "16.4"), nan5)[0]
    fields["vz_other"] = errs.get((other.vz_error, "15"), nan5)[0]
    return fields


def kept_rows(out, instrument):
    """The rows of <out>/error_vs_runtime.csv written with this instrument, by run folder name (with
    the fields a row made from a run directory has), so that a run summarised before can be given
    as its folder in <out> once its run directory is gone."""
    path = os.path.join(out, "error_vs_runtime.csv")
    if not os.path.exists(path):
        return {}
    rows = {}
    with open(path) as f:
        for r in csv.reader(f):
            if r[0] == "run" or len(r) != 10 + len(CSV_ERRORS) or r[9] != instrument:
                continue
            row = dict(run=r[0], name=re.sub(r"_[^_]+$", "", r[0]), model=r[1], commit=r[2], ranks=r[3],
                       wall=float(r[4]), core=float(r[5]), coupling_share=float(r[6]),
                       fluid_share=float(r[7]), dem_share=float(r[8]))
            errors = os.path.join(out, r[0], "errors.csv")
            row.update(error_fields(errors, *ERROR_INSTRUMENTS[instrument]) if os.path.exists(errors)
                       else {k: float(v) for k, v in zip(CSV_ERRORS, r[10:])})
            info = os.path.join(out, r[0], "profiles_info.txt")
            row["window"] = open(info).readline().split(";")[0].strip() if os.path.exists(info) else ""
            rows[r[0]] = row
    return rows


def main():
    args = sys.argv[1:]
    instrument = "depthBinned"
    if "-instrument" in args:   # anywhere on the line
        i = args.index("-instrument")
        if i + 1 >= len(args) or args[i + 1] not in INSTRUMENTS:
            sys.exit(f"summary.py: -instrument takes one of {', '.join(INSTRUMENTS)}")
        instrument, args = args[i + 1], args[:i] + args[i + 2:]
    if len(args) < 2:
        sys.exit(__doc__)
    out, runs = args[0], args[1:]
    head, other = ERROR_INSTRUMENTS[instrument]
    os.makedirs(out, exist_ok=True)
    kept = kept_rows(out, instrument)
    rows = []
    for run in runs:
        name = os.path.basename(os.path.normpath(run))
        if name in kept and os.path.samefile(os.path.dirname(os.path.abspath(os.path.normpath(run))), out):
            # one of <out>'s own folders: a run summarised before, whose run directory (its logs) may
            # be gone; its row as the last summary wrote it
            rows.append(kept[name])
            continue
        path = os.path.join(run, "results", "comparison", "errors.csv")
        if not os.path.exists(path):
            print(f"summary.py: {name}: no comparison yet, skipped")
            continue
        errs = error_fields(path, head, other)
        wall, core, rank_set, segs, pauses = run_wall(run)
        if pauses:
            print(f"summary.py: {name}: {len(pauses)} pause(s) of the run taken off its wall time "
                  f"(" + ", ".join(f"{p:.0f} s at t = {t:g} s" for t, p in pauses) + ") and left out of its stage shares")
        ranks = "/".join(str(r) for r in rank_set)
        cpath = os.path.join(run, "commit.txt")
        commit = " ".join(sorted(set(l.strip() for l in open(cpath) if l.strip()))) if os.path.exists(cpath) else "unknown"
        st = stage_times(segs) or {}
        total = sum(st.values()) or float("nan")
        coupling = sum(v for k, v in st.items() if k not in NOT_COUPLING)
        info = open(os.path.join(run, "results", "profiles_info.txt")).readline().split(";")[0].strip()
        label = f"{name}_{commit.replace(' ', '+')}"
        if errs["void_rms"] != errs["void_rms"] or errs["vz_rms"] != errs["vz_rms"]:
            print(f"summary.py: {name}: no {instrument} errors in {path}: n/a in the headline columns"
                  + (" (try -instrument midThickness)" if instrument == "depthBinned" else ""))
        rows.append(dict(run=label, name=name, model=name.split("_")[0], wall=wall, core=core, ranks=ranks, commit=commit, coupling_share=coupling / total,
                         fluid_share=st.get("fluid", 0) / total, dem_share=st.get("DEM", 0) / total, window=info, **errs))
        dest = os.path.join(out, label)
        os.makedirs(dest, exist_ok=True)
        for f in glob.glob(os.path.join(run, "results", "*.csv")) + glob.glob(os.path.join(run, "results", "*.txt")):
            shutil.copy(f, dest)
        for f in glob.glob(os.path.join(run, "results", "comparison", "*")):
            shutil.copy(f, dest)
    with open(os.path.join(out, "error_vs_runtime.csv"), "w") as f:
        # headline columns: the chosen instrument (column "instrument"); *_other_rms: the other one
        f.write("run,model,commit,ranks,wall_time_s,core_seconds,coupling_share,fluid_share,dem_share,instrument,"
                "voidfraction_z16.4_rms,voidfraction_z16.4_max,voidfraction_z16.4_mean_sem,voidfraction_z16.4_rms_symmetrised,voidfraction_z16.4_rms_noise_removed,"
                "vz_z15_rms_m_per_s,vz_z15_max_m_per_s,vz_z15_mean_sem,vz_z15_rms_symmetrised,vz_z15_rms_noise_removed,"
                "voidfraction_z16.4_other_rms,vz_z15_other_rms_m_per_s\n")
        for r in rows:
            f.write(f"{r['run']},{r['model']},{r['commit']},{r['ranks']},{r['wall']:.0f},{r['core']:.0f},{r['coupling_share']:.3f},{r['fluid_share']:.3f},{r['dem_share']:.3f},{instrument},"
                    + ",".join(f"{r[k]:.4f}" for k in CSV_ERRORS) + "\n")
    with open(os.path.join(out, "error_vs_runtime.md"), "w") as f:
        f.write(f"| run | commit | ranks | wall time (s) | core-seconds | coupling share | gas fraction, z = 16.4 mm, {head.words}: RMS / max | "
                f"particle v_z, z = 15 mm, {head.words}: RMS / max (m/s) | gas fraction RMS, {other.words} | particle v_z RMS, {other.words} (m/s) |\n"
                "|---|---|---|---|---|---|---|---|---|---|\n")
        def cell(rms, mx, sem, sym, clean):
            if rms != rms:
                return "n/a"
            more = "" if sym != sym else f"; sym. {sym:.3f}; noise removed {clean:.3f}"
            return f"{rms:.3f} / {mx:.3f} (SEM {sem:.3f}{more})"
        def bare(x):
            return "n/a" if x != x else f"{x:.3f}"
        for r in rows:
            share = "n/a" if r['coupling_share'] != r['coupling_share'] else f"{100*r['coupling_share']:.1f} %"
            f.write(f"| {r['run']} | {r['commit']} | {r['ranks']} | {r['wall']:.0f} | {r['core']:.0f} | {share} | "
                    f"{cell(r['void_rms'], r['void_max'], r['void_sem'], r['void_sym'], r['void_clean'])} | "
                    f"{cell(r['vz_rms'], r['vz_max'], r['vz_sem'], r['vz_sym'], r['vz_clean'])} | "
                    f"{bare(r['void_other'])} | {bare(r['vz_other'])} |\n")
        f.write("\nRMS / max: over the MR data points; SEM: the mean batch-means standard error of the simulated "
                "profile; sym.: RMS of the profile averaged with its mirror image about the mid-width; noise "
                "removed: sqrt(RMS^2 - mean SEM^2) (compare.py). Wall time and core-seconds: every start summed, "
                "the pauses found taken off (a stopped run: summary.py names them); on a shared machine not "
                "cost figures (see the README).\n")
        windows = list(dict.fromkeys(r["window"] for r in rows))   # runs of different modes differ
        if len(windows) == 1:
            f.write(f"\nAveraging window: {windows[0]}\n")
        elif windows:
            f.write("\nAveraging windows:\n" + "".join(f"- {r['run']}: {r['window']}\n" for r in rows))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        # rows: gas fraction at 16.4 mm, particle v_z at 15 mm; columns: wall time, coupling share.
        # One labelled point per model (its last run on the command line), earlier runs in grey.
        latest = {r["model"]: r for r in rows}
        fig, ax = plt.subplots(2, 2, figsize=(10, 8))
        for i, (key, sem, label) in enumerate((("void_rms", "void_sem", "gas fraction RMS error, z = 16.4 mm"),
                                               ("vz_rms", "vz_sem", "particle v_z RMS error, z = 15 mm (m/s)"))):
            label += f"\n({head.words})"
            for r in rows:
                current = latest[r["model"]] is r
                for j, x in enumerate((r["core"], 100 * r["coupling_share"])):
                    if x != x:
                        continue   # no stage timers (the DPMFoam baseline): no coupling share
                    if current:
                        ax[i][j].errorbar(x, r[key], yerr=r[sem], fmt="o", capsize=3, label=f"{r['model']} ({r['commit']})")
                        ax[i][j].annotate(r["model"], (x, r[key]), textcoords="offset points", xytext=(4, 4))
                    else:
                        ax[i][j].plot(x, r[key], "o", mfc="none", color="0.6", ms=5)
            ax[i][0].set_ylabel(label)
            ax[i][1].set_ylabel(label)
            ax[i][0].set_xlabel("run time (core-seconds: wall x MPI ranks)")
            ax[i][1].set_xlabel("coupling share of the wall time (%)")
            for a in ax[i]:
                a.axhline(0.05, color="grey", lw=0.8, ls="--")
        ax[0][0].legend(fontsize=8, loc="upper right")
        fig.suptitle("Mueller bed: error against run time (error bars: mean batch SEM of the simulation;\n"
                     "each model's last run as given to summary.py; grey circles: its earlier runs, see the table)")
        fig.tight_layout()
        fig.savefig(os.path.join(out, "error_vs_runtime.png"), dpi=110)
        plt.close(fig)
        try:
            plot_profiles(out, rows, plt, instrument)
            plot_all_heights(out, rows, plt, instrument)
        except (OSError, ValueError, IndexError) as e:   # the table above is written: say what failed
            print(f"summary.py: profile figures not made: {e}")
    except ImportError:
        print("summary.py: matplotlib missing, no PNG")
    for r in rows:
        print(f"{r['run']}: wall {r['wall']:.0f} s x {r['ranks']} ranks, coupling {100*r['coupling_share']:.1f} %, void RMS {r['void_rms']:.4f}, vz RMS {r['vz_rms']:.4f}")

if __name__ == "__main__":
    main()
