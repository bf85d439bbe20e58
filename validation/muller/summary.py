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
import csv, glob, os, re, shutil, sys

# the project's Python library, etc/python (COARSEDEM_DIR: this file may run from a copy of its folder)
sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."), "etc", "python"))
from muller_plots import ERROR_INSTRUMENTS, INSTRUMENTS, plot_all_heights, plot_profiles  # noqa: E402
from solver_log import NOT_COUPLING, run_wall, stage_times  # noqa: E402

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
