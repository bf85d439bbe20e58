"""Bubbles of a Mueller-bed run at the sampled heights, against Darton et al.'s (1977) bubble size.

    bubbles.py <case dir> <t_start> <t_end> [-threshold 0.8] [-umf 0.29]

From the depthProfiles samples (every 0.01 s; system/depthProfiles: every cell column across the
10 mm thickness at z = 15 ... 35 mm) averaged over the depth, with the particles binned by the cell
of their centre (1 - alphaPBinned: the same instrument whatever the method): a bubble is a run of
consecutive cells across the width, at least two (two particle diameters: the binned instrument's
single empty cells are not bubbles), whose gas fraction exceeds the threshold (0.8, a common choice:
a bubble holds few particles, the emulsion about 0.4-0.5). Per height: the share of the line in
bubbles (time-averaged), the bubbles per sample, and their mean horizontal chord.
Darton et al. (Trans. Instn Chem. Engrs 55, 274, 1977): D_b = 0.54 (U - U_mf)^0.4 (h + 4 sqrt(A_0))^0.8
g^-0.2 (SI units), with A_0 = 0 for a porous plate; U_mf of the code's drag law at the paper's
settled bed (validation/muller/results/minimumFluidization.csv: 0.29 m/s). A horizontal line cuts a
circle of diameter D at random in a chord of mean pi D/4: the chord to compare. Darton's law is for
three-dimensional beds; in this bed 10 mm deep a bubble wider than the depth is flattened between the
front and back walls, so the comparison says whether the bubbles have the right size class, not more.
Writes <case>/results/bubbles.csv and prints it.
"""
import math
import os
import sys

from muller_profiles import depth_average, read_series

G = 9.81
U_INLET = 0.9


def darton_diameter(h, U, umf, a0=0.0):
    return 0.54 * (U - umf) ** 0.4 * (h + 4 * math.sqrt(a0)) ** 0.8 / G ** 0.2


MIN_CELLS = 2   # a void narrower than two cells (two particle diameters) is not counted as a bubble


def chords(eps, dy, threshold):
    """Widths (m) of the runs of eps > threshold at least MIN_CELLS wide (a run cut by a wall counts as
    it is seen)."""
    out, n = [], 0
    for e in list(eps) + [0.0]:
        if e > threshold:
            n += 1
        else:
            if n >= MIN_CELLS:
                out.append(n * dy)
            n = 0
    return out


def main():
    args = sys.argv[1:]
    threshold, umf = 0.8, 0.29
    for flag in ("-threshold", "-umf"):
        if flag in args:
            i = args.index(flag)
            val = float(args[i + 1])
            del args[i:i + 2]
            threshold, umf = (val, umf) if flag == "-threshold" else (threshold, val)
    if len(args) != 3:
        sys.exit(__doc__)
    case, t0, t1 = args[0], float(args[1]), float(args[2])
    series, times, _ = read_series(os.path.join(case, "postProcessing", "depthProfiles"), t0, t1)
    if not times:
        sys.exit(f"bubbles.py: no depthProfiles samples in ({t0}, {t1}] under {case}/postProcessing")
    rows = []
    for name, byt in sorted(depth_average(series).items(), key=lambda kv: float(kv[0][1:])):
        h = float(name[1:]) / 1000.0      # set z<h>: h in mm
        all_chords, in_bubble, n_points = [], 0, 0
        for t, rec in byt.items():
            if "alphaPBinned" not in rec:
                continue
            y = rec.get("y") or rec.get("distance")
            dy = (y[-1] - y[0]) / (len(y) - 1)
            eps = [1 - a for a in rec["alphaPBinned"]]
            found = chords(eps, dy, threshold)
            all_chords += found
            in_bubble += sum(found) / dy
            n_points += len(eps)
        if not n_points:
            continue
        nt = n_points / len(y)
        db = darton_diameter(h, U_INLET, umf)
        rows.append({"z_mm": 1e3 * h, "samples": int(nt), "bubble_share": in_bubble / n_points,
                     "bubbles_per_sample": len(all_chords) / nt,
                     "mean_chord_mm": 1e3 * sum(all_chords) / len(all_chords) if all_chords else float("nan"),
                     "darton_diameter_mm": 1e3 * db, "darton_mean_chord_mm": 1e3 * math.pi / 4 * db})
    os.makedirs(os.path.join(case, "results"), exist_ok=True)
    out = os.path.join(case, "results", "bubbles.csv")
    with open(out, "w") as f:
        f.write(f"# bubbles.py {case} {t0} {t1} -threshold {threshold} -umf {umf}\n")
        f.write(",".join(rows[0]) + "\n")
        for r in rows:
            f.write(",".join(f"{v:.4g}" for v in r.values()) + "\n")
    print(f"| z (mm) | share of the line in bubbles | bubbles per sample | mean chord (mm) | Darton D_b (mm) | "
          f"its mean chord pi D_b/4 (mm) |\n|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['z_mm']:g} | {r['bubble_share']:.3f} | {r['bubbles_per_sample']:.2f} | {r['mean_chord_mm']:.1f} | "
              f"{r['darton_diameter_mm']:.1f} | {r['darton_mean_chord_mm']:.1f} |")
    print(f"bubbles.py: wrote {out}")
