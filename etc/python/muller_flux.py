"""The solid's time-averaged vertical flux through a horizontal plane of the Mueller bed: zero in a
bed whose particles neither leave nor pile up. A check of the MR profiles against each other, and
of a run's profiles against the law, before either is compared with the other.

    fluxBalance.py [-data DIR] [-o CSV] [RUN_RESULTS_DIR ...]

Through the plane z, over the bed's width W and depth D, the net flux of solid volume is
D int_0^W <alpha_p v_z>(x) dx, with <.> the time and depth average. The MR velocity, like
profile_vzdepthbinned of a run, is the solid-weighted mean v(x) = <alpha_p v_z> / <alpha_p> (Mueller
et al. measure the signal of the particles' oil, so a voxel's velocity is weighted by the solid in it);
so the flux is int (1 - eps(x)) v(x) dx with eps the time-averaged gas fraction. Reported: that
integral over int (1 - eps) |v| dx (the net flux as a fraction of the gross: 0 in a steady bed), the
upward and downward parts, and by what factor the upward part would have to change to balance the
downward one (the central upflow peak that balances).

The MR data (0.9 m/s) hold v_z at 15, 25 and 35 mm and the gas fraction at 16.4 and 31.2 mm; each
velocity profile is read with the gas fraction nearest in height (16.4 mm for 15 mm: the gas fraction
of the runs changes little over those 1.4 mm; 31.2 mm for 25 and 35 mm, a rougher pairing), and
with a uniform gas fraction (the MR's mean: weighting by the velocity alone); the 15 mm profile also
with each run's own time-averaged gas fraction at 15 mm. For each run given, its own balance at the
six heights (depth-averaged, binned: the headline profiles).
Writes the CSV (default validation/muller/results/fluxBalance.csv) and prints a table.
"""
import csv
import os
import sys

import numpy as np

from muller_plots import HEIGHTS_MM as HEIGHTS  # the six MR heights, one list

WIDTH = 0.044
# the MR velocity profiles (0.9 m/s) and the MR gas fraction nearest in height
MR_PAIRS = (("15", "16.4"), ("25", "31.2"), ("35", "31.2"))


def read_xy(path):
    with open(path) as f:
        rows = [r for r in csv.reader(l for l in f if l.strip() and not l.startswith("#"))]
    a = np.array([[float(v) for v in r[:2]] for r in rows[1:]])
    return a[:, 0], a[:, 1]


def run_name(results):
    """A run's name from its folder or its results/ folder."""
    p = os.path.normpath(results)
    return os.path.basename(os.path.dirname(p)) if os.path.basename(p) == "results" else os.path.basename(p)


def balance(x_v, v, x_e, eps):
    """(net / gross, upward, downward flux per depth in m2/s, upward factor that balances) of the solid
    flux of velocity profile v(x_v) with gas fraction eps(x_e), both held constant beyond their ends."""
    x = np.linspace(0.0, WIDTH, 881)
    vi, ai = np.interp(x, x_v, v), 1.0 - np.interp(x, x_e, eps)
    up = np.trapz(np.where(vi > 0, ai * vi, 0.0), x)
    down = np.trapz(np.where(vi < 0, ai * vi, 0.0), x)
    return (up + down) / (up - down), up, down, (-down / up if up > 0 else float("nan"))


def main():
    args = sys.argv[1:]
    here = os.path.dirname(os.path.abspath(__file__))
    data = os.path.join(here, "..", "..", "validation", "muller", "data")
    out = os.path.join(here, "..", "..", "validation", "muller", "results", "fluxBalance.csv")
    while args and args[0] in ("-data", "-o"):
        if len(args) < 2:
            sys.exit(__doc__)
        if args[0] == "-data":
            data = args[1]
        else:
            out = args[1]
        args = args[2:]
    rows = []

    def row(source, eps_from, z, b, peak=float("nan")):
        rows.append({"profiles": source, "gas_fraction_from": eps_from, "z_mm": z, "net_over_gross": b[0],
                     "upward_m2_s": b[1], "downward_m2_s": b[2], "balancing_upward_factor": b[3],
                     "balancing_peak_m_s": peak * b[3]})

    # each MR velocity profile with the MR gas fraction nearest in height, and with a uniform one
    mr_v = {}
    for zv, ze in MR_PAIRS:
        fv = os.path.join(data, f"mueller_U0.9_vz_z{zv}mm_MR.csv")
        fe = os.path.join(data, f"mueller_U0.9_voidfraction_z{ze}mm_MR.csv")
        if not (os.path.exists(fv) and os.path.exists(fe)):
            continue
        xv_z, v_z = mr_v[zv] = read_xy(fv)
        xe_z, e_z = read_xy(fe)
        row("MR", f"MR {ze} mm", zv, balance(xv_z, v_z, xe_z, e_z), float(v_z.max()))
        row("MR", "uniform (MR mean)", zv, balance(xv_z, v_z, xe_z, np.full_like(e_z, e_z.mean())), float(v_z.max()))
    xv, v = mr_v["15"]
    for run in args:
        name = run_name(run)
        f = os.path.join(run, "profile_voidfractiondepthbinned_z15mm.csv")
        if os.path.exists(f):
            xs, es = read_xy(f)
            row("MR", "run " + name, "15", balance(xv, v, xs, es), float(v.max()))
        for z in HEIGHTS:
            fv = os.path.join(run, f"profile_vzdepthbinned_z{z}mm.csv")
            fe = os.path.join(run, f"profile_voidfractiondepthbinned_z{z}mm.csv")
            if os.path.exists(fv) and os.path.exists(fe):
                row("run " + name, "run", z, balance(*read_xy(fv), *read_xy(fe)))
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    with open(out, "w") as f:
        f.write("# command: validation/muller/fluxBalance.py " + " ".join(sys.argv[1:]) + "\n")
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{val:.4g}" if isinstance(val, float) else val) for k, val in r.items()})
    print("| profiles | gas fraction from | z (mm) | net / gross | upward / downward | upward factor that balances |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['profiles']} | {r['gas_fraction_from']} | {r['z_mm']} | {r['net_over_gross']:+.3f} | "
              f"{-r['upward_m2_s'] / r['downward_m2_s']:.3f} | {r['balancing_upward_factor']:.2f} |")
    print(f"fluxBalance.py: wrote {out}")
