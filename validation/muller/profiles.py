#!/usr/bin/python3
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
Writes <case>/results/profile_voidfraction_z<h>mm.csv and profile_vz_z<h>mm.csv (x_m = distance
from the left wall, value, sem) and results/profiles_info.txt. Samples from restarted runs (the
same time written twice, or the stretch between a stopped run's last write and its stop sampled
again by the continued run) are counted once (drop_superseded).
"""
import csv, glob, math, os, re, sys

def drop_superseded(dirs):
    """A run stopped after its last write and continued from it samples that stretch of time again,
    at instants shifted by up to a CFD step (a function object counts its interval from the run's
    start). Both samples stay on disk; the stopped segment's are from an abandoned trajectory. Of two
    samples closer than half the usual spacing the one written later is kept. Returns (the kept
    {time: dir}, the dropped times)."""
    ts = sorted(dirs)
    if len(ts) < 3:
        return dirs, []
    gaps = sorted(b - a for a, b in zip(ts, ts[1:]))
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
    dirs = {float(os.path.basename(d)): d for d in glob.glob(os.path.join(base, "*"))}
    dirs, superseded = drop_superseded(dirs)
    times = sorted(t for t in dirs if t0 < t <= t1 + 1e-9)
    if not times:
        sys.exit(f"profiles.py: no samples in ({t0}, {t1}] under {base}")
    dropped = [t for t in superseded if t0 < t <= t1 + 1e-9]   # reported with the info at the end
    # per set: list over time of (y, alpha, alphaP, UsZ*alphaP)
    series = {}
    for t in times:
        for path in glob.glob(os.path.join(dirs[t], "z*.csv")):
            name = os.path.basename(path)
            setname = name.split("_")[0]
            header, rows = read_set(path)
            rec = series.setdefault(setname, {}).setdefault(t, {})
            for j, col in enumerate(header):
                rec[col] = [r[j] for r in rows]
    os.makedirs(os.path.join(case, "results"), exist_ok=True)
    info = []
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
        def column(t, key):
            return byt[t][key]
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
        def mean_alpha(tl):
            return [sum(column(t, "alpha")[k] for t in tl) / len(tl) for k in range(len(y))]
        def mean_ratio(num_key, den_key):
            def mean(tl):
                out = []
                for k in range(len(y)):
                    num = sum(column(t, num_key)[k] for t in tl)
                    den = sum(column(t, den_key)[k] for t in tl)
                    out.append(num / den if den > 1e-12 else float("nan"))
                return out
            return mean
        def write(name, what, column_name, mean_fn):
            v, e = batch_stats(name, mean_fn)
            with open(os.path.join(case, "results", f"profile_{name}_z{h}mm.csv"), "w") as f:
                f.write(f"# time-averaged {what}, z = {h} mm, window ({t0}, {t1}] s, {used} of {n} samples, "
                        f"{B} batches of {size}\n")
                f.write(f"x_m,{column_name},sem\n")
                for k in range(len(y)):
                    f.write(f"{y[k]:.6g},{v[k]:.6g},{e[k]:.3g}\n")
        if "alpha" in byt[ts[0]]:
            write("voidfraction", "gas volume fraction", "void_fraction", mean_alpha)
        if "alphaPUs_2" in byt[ts[0]] and "alphaP" in byt[ts[0]]:
            write("vz", "(solid-weighted) vertical particle velocity", "vz_particle_m_per_s",
                  mean_ratio("alphaPUs_2", "alphaP"))
        if "alphaPUsBinned_2" in byt[ts[0]] and "alphaPBinned" in byt[ts[0]]:
            write("vzbinned", "(solid-weighted) vertical particle velocity, particles binned by their centre's cell",
                  "vz_particle_m_per_s", mean_ratio("alphaPUsBinned_2", "alphaPBinned"))
        corr = ", ".join(f"{k} {c:.2f}" for k, c in sorted(lag1.items()))
        info.append(f"z = {h} mm: {n} samples in ({t0}, {t1}] s (every {dt:.3g} s), {used} used in {B} batches of "
                    f"{size} ({size * dt:.3g} s)" + ("" if B > 1 else ": too few for an error bar (sem nan)")
                    + f"; lag-1 correlation of the batch means: {corr}")
        for k, c in sorted(lag1.items()):
            if c > 0.3:
                print(f"profiles.py: warning: z = {h} mm {k}: batch means correlated ({c:.2f} > 0.3), "
                      "the SEM is too small (a slow circulation: a longer window or longer batches)")
    if dropped:
        info.append(f"{len(dropped)} sample(s) of a stopped segment, superseded by the continued run, not used: "
                    + ", ".join("%g" % t for t in dropped))
    with open(os.path.join(case, "results", "profiles_info.txt"), "w") as f:
        f.write("\n".join(info) + "\n")
    print("\n".join(info))

if __name__ == "__main__":
    main()
