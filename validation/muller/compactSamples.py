#!/usr/bin/python3
"""Fold a Mueller-bed run's profile samples into one small file per function object.

    compactSamples.py <run dir> -until T [-from T0]

A run's `profiles` and `depthProfiles` function objects write a folder of CSV files every 0.01 s:
about 40 MB per simulated second, nine tenths of it the eight cell columns across the depth. A run
too long for one session (the full mode: 30 s) cannot then be carried to another machine by
etc/runArchive. This folds the samples with T0 < t <= T into <function dir>/compacted.csv.gz and
removes their folders: only the columns profiles.py reads (those of its MID_THICKNESS and DEPTH
lists that the samples have, and y), the depthProfiles ones averaged over the depth as profiles.py
averages them, written with 10 significant digits (the samples have 8). profiles.py and window.py
read the store as the folders it replaces: their profiles and errors are those of the folders (to
the 10th digit of the depth averages). About 1/40 of the size (the medium run of
the recommended set-up: 301 MB of samples into 7.2 MB).

T must be at most the run's last complete write time (the time a continued run starts from:
etc/lastCompleteWrite): a continued run samples the times after it again, and those must stay
folders for profiles.py to tell the continued run's samples from the stopped one's. The samples of
a stopped segment superseded by a continued run (profiles.drop_superseded) in (T0, T] are not
stored; their folders are moved into <function dir>/superseded/. Folding again later adds to the
store. Default T0: the first sample.

Carrying a full-mode run stopped at its write time W:
    compactSamples.py RUN -until W -from 10
    etc/runArchive pack -samplesFrom 10 RUN archive.tar.xz     (the start-up's folders left out)
Errors (exit status 2, one line naming the file or entry): no samples, T after the last complete
write time, a sample without a column the store holds, an unreadable store.
"""
import gzip, os, shutil, subprocess, sys

# the project's Python library, etc/python (COARSEDEM_DIR: this file may run from a copy of its folder)
sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."), "etc", "python"))
import muller_profiles as profiles  # noqa: E402

# the columns stored per function: those profiles.py's variants read, and the position
COLUMNS = {
    "profiles": ["y"] + sorted({c for v in profiles.MID_THICKNESS for c in v[3]}),
    "depthProfiles": ["y"] + sorted({c for v in profiles.DEPTH for c in v[3]}),
}


def fail(msg):
    print(f"compactSamples.py: {msg}", file=sys.stderr)
    sys.exit(2)


def last_complete_write(run):
    """The last write time after 0 complete on every rank (etc/lastCompleteWrite), or None."""
    tool = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "etc", "lastCompleteWrite")
    r = subprocess.run([tool, run], capture_output=True, text=True)
    return float(r.stdout) if r.returncode == 0 and r.stdout.strip() else None


def fold(base, fn, t0, t1):
    """Fold the samples of function fn in (t0, t1] into base/compacted.csv.gz; returns (samples
    folded, superseded folders moved aside, store bytes)."""
    store = os.path.join(base, profiles.STORE)
    try:
        kept = profiles.read_store(base)
    except (OSError, ValueError, EOFError) as e:
        fail(f"{store}: cannot be read ({e})")
    dirs = profiles.sample_dirs(base)
    series, times, superseded = profiles.read_series(base, t0, t1, kept)
    new = sorted(t for t in times if t in dirs)
    if not new and not superseded:
        return 0, 0, os.path.getsize(store) if os.path.exists(store) else 0
    if fn == "depthProfiles":
        series = profiles.depth_average(series)
    # the columns of the store: those it holds already, else those of COLUMNS the samples have (a run
    # without binnedParticleFields samples no binned ones)
    first = next((rec for byt in kept.values() for rec in byt.values()), None) or \
        next((byt[t] for byt in series.values() for t in new if t in byt), {})
    cols = [c for c in COLUMNS[fn] if c in first]
    if "y" not in cols:
        fail(f"{base}: samples without a y column (sets along y expected)")
    for name, byt in series.items():
        for t in new:
            if t not in byt:
                continue
            missing = [c for c in cols if c not in byt[t]]
            if missing:
                fail(f"{dirs[t]}: set {name} has no column {', '.join(missing)} (the store holds {', '.join(cols)})")
            kept.setdefault(name, {})[t] = byt[t]
    tmp = store + ".tmp"
    with gzip.open(tmp, "wt") as f:
        f.write(f"# samples of the function object {fn} folded by compactSamples.py"
                + (", averaged over the depth" if fn == "depthProfiles" else "") + "\n")
        f.write("time,set," + ",".join(cols) + "\n")
        for t in sorted(set(t for byt in kept.values() for t in byt)):
            for name in sorted(kept):
                rec = kept[name].get(t)
                if rec is None:
                    continue
                for k in range(len(rec["y"])):
                    f.write(f"{t:.10g},{name}," + ",".join(f"{rec[c][k]:.10g}" for c in cols) + "\n")
    os.replace(tmp, store)
    # the folders only once the store holding them is in place; the superseded ones (chosen by their
    # file times) are kept aside, out of the samples, not deleted
    for t in new:
        shutil.rmtree(dirs[t])
    for t in superseded:
        aside = os.path.join(base, "superseded")
        os.makedirs(aside, exist_ok=True)
        shutil.move(dirs[t], os.path.join(aside, os.path.basename(dirs[t])))
    return len(new), len(superseded), os.path.getsize(store)


def main():
    args = sys.argv[1:]
    opts = {}
    for key in ("-until", "-from"):
        if key in args:
            i = args.index(key)
            if i + 1 >= len(args):
                fail(f"{key} needs a time")
            try:
                opts[key] = float(args[i + 1])
            except ValueError:
                fail(f"{key} {args[i + 1]}: not a time")
            del args[i:i + 2]
    if len(args) != 1 or "-until" not in opts:
        sys.exit(__doc__)
    run = args[0]
    t1, t0 = opts["-until"], opts.get("-from", float("-inf"))
    last = last_complete_write(run) if os.path.isdir(run) else None
    if last is None:
        fail(f"{run}: no complete write time after 0 (not a run, or not written yet)")
    if t1 > last + 1e-9:
        fail(f"-until {t1:g}: after the run's last complete write time {last:g} s, from which a continued "
             "run samples again")
    done = 0
    for fn in COLUMNS:
        base = os.path.join(run, "postProcessing", fn)
        if not os.path.isdir(base):
            continue
        n, s, size = fold(base, fn, t0, t1)
        done += n
        print(f"compactSamples.py: {fn}: {n} samples in ({t0:g}, {t1:g}] s folded into {base}/{profiles.STORE} "
              f"({size / 1e6:.2f} MB)" + (f"; {s} superseded sample(s) moved to {base}/superseded" if s else ""))
    if not done:
        fail(f"{run}: no sample folders in ({t0:g}, {t1:g}] s under postProcessing/profiles or depthProfiles")


if __name__ == "__main__":
    main()
