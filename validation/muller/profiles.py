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
Uncertainty: batch means. The window is cut into B consecutive batches (default 10); the standard
error of the mean is std(batch means) / sqrt(B) (for the velocity, the batch ratios). Batches much
longer than the bubble period (~0.1-0.2 s here) make the batch means nearly independent; with short
windows the error bar is itself uncertain, which the output says by giving B and the batch length.
Writes <case>/results/profile_voidfraction_z<h>mm.csv and profile_vz_z<h>mm.csv (x_m = distance
from the left wall, value, sem) and results/profiles_info.txt. Samples from restarted runs (the
same time written twice) are counted once.
"""
import csv, glob, math, os, re, sys

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
    nb = 10
    if "--batches" in args:
        i = args.index("--batches"); nb = int(args[i + 1]); del args[i:i + 2]
    case, t0, t1 = args[0], float(args[1]), float(args[2])
    base = os.path.join(case, "postProcessing", "profiles")
    times = sorted({float(os.path.basename(d)) for d in glob.glob(os.path.join(base, "*"))})
    times = [t for t in times if t0 < t <= t1 + 1e-9]
    if not times:
        sys.exit(f"profiles.py: no samples in ({t0}, {t1}] under {base}")
    # per set: list over time of (y, alpha, alphaP, UsZ*alphaP)
    series = {}
    for t in times:
        d = None
        for cand in glob.glob(os.path.join(base, "*")):
            if abs(float(os.path.basename(cand)) - t) < 1e-9:
                d = cand
        for path in glob.glob(os.path.join(d, "z*.csv")):
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
        B = min(nb, n)
        size = n // B
        def column(t, key):
            return byt[t][key]
        def batch_stats(values_fn):
            """values_fn(list of times) -> per-point value; mean over all and batch-means SEM"""
            allv = values_fn(ts[:B * size])
            bm = [values_fn(ts[b * size:(b + 1) * size]) for b in range(B)]
            sem = []
            for k in range(len(allv)):
                xs = [m[k] for m in bm]
                mu = sum(xs) / B
                var = sum((x - mu) ** 2 for x in xs) / (B - 1) if B > 1 else float("nan")
                sem.append(math.sqrt(var / B) if B > 1 else float("nan"))
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
            v, e = batch_stats(mean_fn)
            with open(os.path.join(case, "results", f"profile_{name}_z{h}mm.csv"), "w") as f:
                f.write(f"# time-averaged {what}, z = {h} mm, window ({t0}, {t1}] s, {n} samples, {B} batches of {size}\n")
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
        info.append(f"z = {h} mm: {n} samples in ({t0}, {t1}] s, {B} batches of {size} samples ({size * 0.01:.3g} s)")
    with open(os.path.join(case, "results", "profiles_info.txt"), "w") as f:
        f.write("\n".join(info) + "\n")
    print("\n".join(info))

main()
