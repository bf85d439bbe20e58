"""Time-averaged profiles of a Mueller-bed run, with their statistical uncertainty.

    profiles.py <case dir> <t_start> <t_end> [--batches 10]

Reads the instantaneous samples that the case's `profiles` function object writes every 0.01 s
(postProcessing/profiles/<time>/z<h>_*.csv: alpha, alphaP, alphaPUs along y at mid-thickness) and
averages those with t_start < t <= t_end:
  - gas volume fraction: the time mean of alpha;
  - vertical particle velocity: the solid-weighted mean mean(alphaP * Us_z) / mean(alphaP), the
    average velocity of the solid passing through the point. alphaPUs is spread with the run's own
    kernels (so a wide kernel smooths the profile); when the run also samples alphaPBinned and
    alphaPUsBinned (couplingProperties binnedParticleFields on: each particle counted in the cell of
    its centre, whatever the model), the same mean of those is written as profile_vzbinned, a
    model-independent velocity profile.
Uncertainty: batch means. The window is cut into B consecutive batches (default 10, each of at
least --min-batch 5 samples: consecutive samples 0.01 s apart are correlated for ~0.05 s); the
standard error of the mean is std(batch means) / sqrt(B) (for the velocity, the batch ratios).
Fewer than two such batches: no error bar (sem nan). Batches much longer than the bubble period
(~0.1-0.2 s here) make the batch means nearly independent; the lag-1 correlation of the batch
means (mean over the profile's points) is written to profiles_info.txt and a warning printed above
0.3 (a circulation slower than a batch: the SEM is then too small). Samples beyond B whole batches
are not used, and the info says how many.
Depth averages: when the case also has the `depthProfiles` function object (system/depthProfiles,
written by Allrun: one line of cell values per cell column across the 10 mm thickness at each
height), the profiles averaged over the depth are written too, as Mueller et al.'s MR profiles
average over the bed's depth: profile_voidfractiondepthbinned and profile_vzdepthbinned (from the
particles binned by the cell of their centre: the same instrument whatever the method under test;
the headline of the comparison) and profile_voidfractiondepth (the method's own alpha).
Compacted samples: the samples compactSamples.py folded into <function dir>/compacted.csv.gz (the
columns read here, depth-averaged for depthProfiles) are read as the sample folders they replace.
Writes <case>/results/profile_voidfraction_z<h>mm.csv and profile_vz_z<h>mm.csv (x_m = distance
from the left wall, value, sem), the depth-averaged ones, and results/profiles_info.txt. Samples from restarted runs (the
same time written twice, or the stretch between a stopped run's last write and its stop sampled
again by the continued run) are counted once (drop_superseded).
"""
import glob, gzip, math, os, re, sys

def drop_superseded(dirs, other_times=()):
    """A run stopped after its last write and continued from it samples that stretch of time again,
    at instants shifted by up to a CFD step (a function object counts its interval from the run's
    start). Both samples stay on disk; the stopped segment's are from an abandoned trajectory. Of two
    samples closer than half the usual spacing the one written later is kept. The usual spacing is
    the median gap of the folders' times and other_times (those of the compacted samples, which
    are not in question). Returns (the kept {time: dir}, the dropped times)."""
    ts = sorted(dirs)
    every = sorted(set(ts).union(other_times))
    if len(ts) < 2 or len(every) < 3:
        return dirs, []
    gaps = sorted(b - a for a, b in zip(every, every[1:]))
    half = 0.5 * gaps[len(gaps) // 2]
    # groups of consecutive samples closer than half a spacing (several stops over one stretch)
    groups = [[ts[0]]]
    for a, b in zip(ts, ts[1:]):
        if b - a < half:
            groups[-1].append(b)
        else:
            groups.append([b])
    kept, dropped = dict(dirs), []
    for g in groups:
        if len(g) < 2:
            continue
        mtimes = [os.path.getmtime(dirs[t]) for t in g]
        if len(set(mtimes)) < len(mtimes):
            print(f"profiles.py: warning: samples {', '.join('%g' % t for t in g)} have equal file times "
                  "(copied without them?): the later time is kept")
        newest = max(range(len(g)), key=lambda i: (mtimes[i], g[i]))
        for i, t in enumerate(g):
            if i != newest:
                del kept[t]
                dropped.append(t)
    return kept, sorted(dropped)


def read_set(path):
    with open(path) as f:
        lines = [l.strip() for l in f if l.strip()]
    header = re.split(r"[,\s]+", lines[0].lstrip("#").strip())
    rows = [[float(v) for v in re.split(r"[,\s]+", l)] for l in lines[1:] if not l.startswith("#")]
    return header, rows

STORE = "compacted.csv.gz"   # a function's samples folded by compactSamples.py


def sample_dirs(base):
    """{time: folder} of the sample folders of a sets function object (the names that are times)."""
    dirs = {}
    for d in glob.glob(os.path.join(base, "*")):
        try:
            dirs[float(os.path.basename(d))] = d
        except ValueError:
            pass
    return dirs


def read_store(base):
    """The compacted samples of a function, {set: {time: {column: values}}} ({} without a store).
    The file: gzip text, '#' comment lines, a header line time,set,<columns> and one row per time,
    set and point, in that order."""
    path = os.path.join(base, STORE)
    if not os.path.exists(path):
        return {}
    series = {}
    with gzip.open(path, "rt") as f:
        rows = (l for l in f if l.strip() and not l.startswith("#"))
        header = next(rows, "").strip().split(",")
        if header[:2] != ["time", "set"]:
            raise ValueError(f"{path}: not a store of compacted samples (header {','.join(header[:2])!r})")
        cols = header[2:]
        for line in rows:
            v = line.strip().split(",")
            if len(v) != len(header):
                raise ValueError(f"{path}: a row of {len(v)} values, the header has {len(header)}: {line.strip()}")
            rec = series.setdefault(v[1], {}).setdefault(float(v[0]), {c: [] for c in cols})
            for c, x in zip(cols, v[2:]):
                rec[c].append(float(x))
    return series


def read_series(base, t0, t1, store=None):
    """The samples of one sets function object in (t0, t1], from its sample folders and its store
    of compacted samples: {set name: {time: {column: values}}}, the times used and the superseded
    ones dropped in the window. store: the function's read_store, when the caller has read it."""
    store = read_store(base) if store is None else store
    dirs, superseded = drop_superseded(sample_dirs(base), [t for byt in store.values() for t in byt])
    series = {name: {t: rec for t, rec in byt.items() if t0 < t <= t1 + 1e-9} for name, byt in store.items()}
    stored = set(t for byt in series.values() for t in byt)
    both = sorted(stored.intersection(dirs))
    if both:
        print(f"profiles.py: warning: {base}: {len(both)} sample time(s) both compacted and in folders "
              f"(first {both[0]:g}): the folders are read")
        for byt in series.values():
            for t in both:
                byt.pop(t, None)
    times = sorted(t for t in dirs if t0 < t <= t1 + 1e-9)
    for t in times:
        for path in glob.glob(os.path.join(dirs[t], "z*.csv")):
            setname = os.path.basename(path).split("_")[0]
            header, rows = read_set(path)
            rec = series.setdefault(setname, {}).setdefault(t, {})
            for j, col in enumerate(header):
                rec[col] = [r[j] for r in rows]
    times = sorted(stored.union(times))
    series = {name: byt for name, byt in series.items() if byt}
    return series, times, [t for t in superseded if t0 < t <= t1 + 1e-9]


def depth_average(series):
    """Sets z<h>d<i> (one per cell column across the thickness, the same y points) -> one set z<h>
    per height whose columns are the means over the columns i at each y and time: what a
    measurement through the bed's depth sees (Mueller et al.'s MR profiles are depth averages).
    Sets z<h> (compacted samples, averaged when they were folded) are taken as they are."""
    out, averaged = {}, {}
    for name, byt in series.items():
        if re.match(r"z[0-9.]+$", name):
            averaged[name] = byt
            continue
        m = re.match(r"(z[0-9.]+)d(\d+)$", name)
        if not m:
            continue
        dst = out.setdefault(m.group(1), {})
        for t, rec in byt.items():
            acc = dst.setdefault(t, {"_n": 0})
            for col, vals in rec.items():
                if col in ("y", "distance"):
                    acc[col] = vals
                else:
                    acc[col] = [a + v for a, v in zip(acc[col], vals)] if col in acc else list(vals)
            acc["_n"] += 1
    for byt in out.values():
        for rec in byt.values():
            n = rec.pop("_n")
            for col in rec:
                if col not in ("y", "distance"):
                    rec[col] = [v / n for v in rec[col]]
    for name, byt in averaged.items():
        out.setdefault(name, {}).update(byt)
    return out


def write_profiles(case, series, t0, t1, nb, min_batch, variants, info, lag1_all):
    """For each set (height) and each variant (name, what, column name, needed columns, mean
    function builder) whose columns the samples have: the time mean over B whole batches and the
    batch-means SEM, written to results/profile_<name>_z<h>mm.csv."""
    for setname, byt in sorted(series.items()):
        h = setname[1:]
        ts = sorted(byt)
        y = byt[ts[0]].get("y") or byt[ts[0]].get("distance")
        n = len(ts)
        B = max(1, min(nb, n // min_batch))
        size = n // B
        used = B * size
        dt = (ts[-1] - ts[0]) / (n - 1) if n > 1 else float("nan")
        lag1 = {}
        def batch_stats(name, values_fn):
            """values_fn(list of times) -> per-point value; mean over the used samples, batch-means
            SEM per point (nan below two batches), and the batch means' lag-1 correlation"""
            allv = values_fn(ts[:used])
            bm = [values_fn(ts[b * size:(b + 1) * size]) for b in range(B)]
            sem, corr = [], []
            for k in range(len(allv)):
                xs = [m[k] for m in bm]
                if B < 2 or any(x != x for x in xs):
                    sem.append(float("nan"))
                    continue
                mu = sum(xs) / B
                var = sum((x - mu) ** 2 for x in xs) / (B - 1)
                sem.append(math.sqrt(var / B))
                if B > 2 and var > 0:
                    corr.append(sum((xs[b] - mu) * (xs[b + 1] - mu) for b in range(B - 1)) / ((B - 1) * var))
            lag1[name] = sum(corr) / len(corr) if corr else float("nan")
            return allv, sem
        for name, what, column_name, needs, builder in variants:
            if not all(c in byt[ts[0]] for c in needs):
                continue
            v, e = batch_stats(name, builder(byt, len(y)))
            with open(os.path.join(case, "results", f"profile_{name}_z{h}mm.csv"), "w") as f:
                f.write(f"# time-averaged {what}, z = {h} mm, window ({t0}, {t1}] s, {used} of {n} samples, "
                        f"{B} batches of {size}\n")
                f.write(f"x_m,{column_name},sem\n")
                for k in range(len(y)):
                    f.write(f"{y[k]:.6g},{v[k]:.6g},{e[k]:.3g}\n")
        corr = ", ".join(f"{k} {c:.2f}" for k, c in sorted(lag1.items()))
        info.append(f"z = {h} mm: {n} samples in ({t0}, {t1}] s (every {dt:.3g} s), {used} used in {B} batches of "
                    f"{size} ({size * dt:.3g} s)" + ("" if B > 1 else ": too few for an error bar (sem nan)")
                    + f"; lag-1 correlation of the batch means: {corr}")
        lag1_all.extend((h, k, c) for k, c in sorted(lag1.items()))


def mean_of(key, transform=lambda v: v):
    """time mean of column key (transformed per value, e.g. 1 - alphaPBinned)"""
    def builder(byt, npts):
        return lambda tl: [sum(transform(byt[t][key][k]) for t in tl) / len(tl) for k in range(npts)]
    return builder


def ratio_of(num_key, den_key):
    """solid-weighted mean: sum over time of num / sum of den, per point"""
    def builder(byt, npts):
        def mean(tl):
            out = []
            for k in range(npts):
                num = sum(byt[t][num_key][k] for t in tl)
                den = sum(byt[t][den_key][k] for t in tl)
                out.append(num / den if den > 1e-12 else float("nan"))
            return out
        return mean
    return builder


# (name, what, column, columns needed, mean builder); mid-thickness, as sampled by `profiles`
MID_THICKNESS = [
    ("voidfraction", "gas volume fraction", "void_fraction", ["alpha"], mean_of("alpha")),
    ("vz", "(solid-weighted) vertical particle velocity", "vz_particle_m_per_s", ["alphaPUs_2", "alphaP"],
     ratio_of("alphaPUs_2", "alphaP")),
    ("vzbinned", "(solid-weighted) vertical particle velocity, particles binned by their centre's cell",
     "vz_particle_m_per_s", ["alphaPUsBinned_2", "alphaPBinned"], ratio_of("alphaPUsBinned_2", "alphaPBinned")),
]
# depth averages of the cell values across the thickness, as sampled by `depthProfiles`; the binned
# ones count each particle in the cell of its centre, the same instrument for every method
DEPTH = [
    ("voidfractiondepthbinned", "gas volume fraction, depth-averaged, particles binned by their centre's cell",
     "void_fraction", ["alphaPBinned"], mean_of("alphaPBinned", lambda v: 1.0 - v)),
    ("vzdepthbinned", "(solid-weighted) vertical particle velocity, depth-averaged, particles binned by their "
     "centre's cell", "vz_particle_m_per_s", ["alphaPUsBinned_2", "alphaPBinned"],
     ratio_of("alphaPUsBinned_2", "alphaPBinned")),
    ("voidfractiondepth", "gas volume fraction of the method under test, depth-averaged", "void_fraction",
     ["alpha"], mean_of("alpha")),
]


def main():
    args = sys.argv[1:]
    if len(args) < 3:
        sys.exit(__doc__)
    nb, min_batch = 10, 5
    if "--batches" in args:
        i = args.index("--batches"); nb = int(args[i + 1]); del args[i:i + 2]
    if "--min-batch" in args:
        i = args.index("--min-batch"); min_batch = int(args[i + 1]); del args[i:i + 2]
    case, t0, t1 = args[0], float(args[1]), float(args[2])
    base = os.path.join(case, "postProcessing", "profiles")
    series, times, dropped = read_series(base, t0, t1)
    if not times:
        sys.exit(f"profiles.py: no samples in ({t0}, {t1}] under {base}")
    os.makedirs(os.path.join(case, "results"), exist_ok=True)
    info, lag1 = [], []
    write_profiles(case, series, t0, t1, nb, min_batch, MID_THICKNESS, info, lag1)
    depth_base = os.path.join(case, "postProcessing", "depthProfiles")
    if os.path.isdir(depth_base):
        dseries, dtimes, _ = read_series(depth_base, t0, t1)
        if dtimes:
            info.append("depth-averaged (every cell column across the thickness):")
            write_profiles(case, depth_average(dseries), t0, t1, nb, min_batch, DEPTH, info, lag1)
    for h, k, c in lag1:
        if c > 0.3:
            print(f"profiles.py: warning: z = {h} mm {k}: batch means correlated ({c:.2f} > 0.3), "
                  "the SEM is too small (a slow circulation: a longer window or longer batches)")
    if dropped:
        info.append(f"{len(dropped)} sample(s) of a stopped segment, superseded by the continued run, not used: "
                    + ", ".join("%g" % t for t in dropped))
    with open(os.path.join(case, "results", "profiles_info.txt"), "w") as f:
        f.write("\n".join(info) + "\n")
    print("\n".join(info))
