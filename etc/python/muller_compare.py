"""muller_compare.py -- a Mueller-bed run's time-averaged profiles against the MR data (the library
behind validation/muller/compare.py, which runs main()).

    compare.py <run results dir> <data dir> [-U 0.9] [-o out dir]

The run's profiles are results/profile_<quantity>_z<h>mm.csv (from profiles.py), with columns
x_m,<quantity>,sem. Every data file of the data directory's format,
mueller_U<U>_<quantity>_z<h>mm_MR.csv (columns x_m,<quantity>), for the run's U is compared where a
simulated profile at that height exists: the simulation is interpolated linearly to the data's x,
and the RMS and maximum absolute errors are reported, with two readings of the RMS that separate
the model's error from the averaging noise of a short window:
  - symmetrised: the simulated profile averaged with its mirror image about the bed's mid-width,
    (s(x) + s(W - x)) / 2; the bed and its inflow are symmetric, so this removes a slow left-right
    circulation that a short window has not averaged out (and any real asymmetry of the model);
  - noise removed: sqrt(max(RMS^2 - mean SEM^2, 0)), the SEMs interpolated to the data's x: the part
    of the squared error that the simulation's own sampling noise does not explain.
The plain RMS is the headline; the other two say how much of it a longer run could remove.
Writes <out>/errors.csv, <out>/errors.md and one PNG per profile (simulation with its batch-means
error bar vs experiment).
"""
import csv, glob, math, os, re, sys

def read_profile(path):
    xs, ys, es = [], [], []
    with open(path) as f:
        rows = [r for r in csv.reader(l for l in f if not l.startswith("#"))]
    header = rows[0]
    for r in rows[1:]:
        xs.append(float(r[0])); ys.append(float(r[1]))
        es.append(float(r[2]) if len(r) > 2 and r[2] else float("nan"))
    return header, xs, ys, es

def interp(x, xs, ys):
    if x <= xs[0]: return ys[0]
    if x >= xs[-1]: return ys[-1]
    for i in range(1, len(xs)):
        if x <= xs[i]:
            t = (x - xs[i - 1]) / (xs[i] - xs[i - 1])
            return ys[i - 1] + t * (ys[i] - ys[i - 1])

QUANTITY = {"voidfraction": "void_fraction", "vz": "vz_particle_m_per_s",
            "vzbinned": "vz_particle_binned_m_per_s",
            "voidfractiondepthbinned": "void_fraction_depth_binned", "vzdepthbinned": "vz_particle_depth_binned_m_per_s",
            "voidfractiondepth": "void_fraction_depth"}

def compare_one(data_path, sim_path, q, h, U, out):
    """RMS and maximum error of one simulated profile against one data file, and its PNG in out
    (none when out is None)."""
    _, dx, dy, _ = read_profile(data_path)
    _, sx, sy, se = read_profile(sim_path)
    sim = [interp(x, sx, sy) for x in dx]
    err = [s - y for s, y in zip(sim, dy)]
    rms = math.sqrt(sum(e * e for e in err) / len(err))
    mx = max(abs(e) for e in err)
    sem = [e for e in se if not math.isnan(e)]
    mean_sem = sum(sem) / len(sem) if sem else float("nan")
    width = sx[0] + sx[-1]   # the samples are symmetric about the mid-width
    err_sym = [0.5 * (s + interp(width - x, sx, sy)) - y for s, x, y in zip(sim, dx, dy)]
    rms_sym = math.sqrt(sum(e * e for e in err_sym) / len(err_sym))
    noise2 = sum(interp(x, sx, se) ** 2 for x in dx) / len(dx) if sem else float("nan")
    rms_clean = math.sqrt(max(rms * rms - noise2, 0.0)) if sem else float("nan")
    row = {"quantity": QUANTITY.get(q, q), "z_mm": h, "rms_error": rms, "max_error": mx,
           "mean_batch_sem": mean_sem, "n_points": len(dx), "rms_error_symmetrised": rms_sym,
           "rms_error_noise_removed": rms_clean}
    if out is None:
        return row
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(5, 3.6))
        if sem:
            ax.errorbar([x * 1e3 for x in sx], sy, yerr=[0 if math.isnan(e) else 2 * e for e in se],
                        fmt="-", capsize=2, label="simulation (±2 batch SEM)")
        else:   # a single batch: no error bar to draw
            ax.plot([x * 1e3 for x in sx], sy, "-", label="simulation (one batch: no SEM)")
        ax.plot([x * 1e3 for x in dx], dy, "ko", ms=4, label="Müller et al. (MR)")
        ax.set_xlabel("distance from the left wall (mm)")
        ax.set_ylabel({"voidfraction": "time-averaged gas fraction", "vz": "time-averaged particle v_z (m/s)",
                       "vzbinned": "time-averaged particle v_z, binned (m/s)",
                       "voidfractiondepthbinned": "gas fraction, depth-averaged, binned",
                       "vzdepthbinned": "particle v_z, depth-averaged, binned (m/s)",
                       "voidfractiondepth": "gas fraction, depth-averaged"}.get(q, q))
        ax.set_title(f"U = {U} m/s, z = {h} mm: RMS {rms:.3g}")
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(out, f"{q}_z{h}mm.png"), dpi=110)
        plt.close(fig)
    except ImportError:
        pass
    return row


def compare(results, data_dir, U, out):
    """The rows of compare_one for every data file at U; with out, also errors.csv, errors.md and the
    PNGs written there (out None: the rows only)."""
    if out is not None:
        os.makedirs(out, exist_ok=True)
    rows = []
    for path in sorted(glob.glob(os.path.join(data_dir, "mueller_U*_*_z*mm_MR.csv"))):
        m = re.match(r"mueller_U([0-9.]+)_(\w+?)_z([0-9.]+)mm_MR\.csv", os.path.basename(path))
        if not m or abs(float(m.group(1)) - U) > 1e-9:
            continue
        q_data, h = m.group(2), m.group(3)
        if not os.path.exists(os.path.join(results, f"profile_{q_data}_z{h}mm.csv")):
            print(f"compare.py: no simulated profile profile_{q_data}_z{h}mm.csv in {results} for {os.path.basename(path)}")
        # the data's quantity and the variants the run may also have (binned: particles counted in
        # the cell of their centre; depth: averaged over the thickness, as the MR data are)
        for q in (q_data, q_data + "binned", q_data + "depthbinned", q_data + "depth"):
            sim_path = os.path.join(results, f"profile_{q}_z{h}mm.csv")
            if os.path.exists(sim_path):
                rows.append(compare_one(path, sim_path, q, h, U, out))
    if out is None:
        return rows
    with open(os.path.join(out, "errors.csv"), "w") as f:
        f.write("quantity,z_mm,rms_error,max_error,mean_batch_sem,n_points,rms_error_symmetrised,rms_error_noise_removed\n")
        for r in rows:
            f.write(f"{r['quantity']},{r['z_mm']},{r['rms_error']:.5g},{r['max_error']:.5g},{r['mean_batch_sem']:.3g},{r['n_points']},"
                    f"{r['rms_error_symmetrised']:.5g},{r['rms_error_noise_removed']:.5g}\n")
    with open(os.path.join(out, "errors.md"), "w") as f:
        f.write("| quantity | z (mm) | RMS error | max error | mean batch SEM of the simulation | RMS, symmetrised | RMS, noise removed |\n"
                "|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write(f"| {r['quantity']} | {r['z_mm']} | {r['rms_error']:.4f} | {r['max_error']:.4f} | {r['mean_batch_sem']:.4f} | "
                    f"{r['rms_error_symmetrised']:.4f} | {r['rms_error_noise_removed']:.4f} |\n")
    return rows

def main():
    args = sys.argv[1:]
    if len(args) < 2:
        sys.exit(__doc__)
    U, out = 0.9, None
    if "-U" in args:
        i = args.index("-U"); U = float(args[i + 1]); del args[i:i + 2]
    if "-o" in args:
        i = args.index("-o"); out = args[i + 1]; del args[i:i + 2]
    results, data_dir = args[0], args[1]
    rows = compare(results, data_dir, U, out or os.path.join(results, "comparison"))
    for r in rows:
        print(f"{r['quantity']} z={r['z_mm']} mm: RMS {r['rms_error']:.4f}, max {r['max_error']:.4f}")
