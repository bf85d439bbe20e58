#!/usr/bin/python3
"""particleJet: statistics of the runs and the checks of the reduced Hardalupas jet.

  ./postprocess.py [-o results] runs/gas runs/cg1B runs/cg2B runs/cg3B runs/cg3A

Per run, over its averaging window (post/runInfo.txt: tAverage ... the run's endTime):
  - the grains crossing each counting plane (post/station_<tag>.txt, fix massflow/mesh: every grain
    once, as a laser-Doppler instrument sees them: flux-weighted) in radial bins of 0.1 D to 1.5 D:
    count, mean and rms axial velocity (with the standard error of the mean), mass flux G (real
    solid mass per area and time: a grain carries cg^3 particles' mass) and G / G_max;
  - the solid mass flow fed (the coupling's particle inventory), through each plane, and out;
  - the gas: UMean on the axis and across the jet (postProcessing/gasProfiles), U_c / U_0 with U_0
    the centreline velocity at the exit, and the jet's half-width at 19 D.
Writes <o>/summary.csv (one row per run), <o>/profiles.csv (one row per run, plane and bin),
<o>/checks.md (the targets of the issue against the unscaled run) and <o>/profiles.png, gas.png."""
import argparse
import glob
import math
import os
import re
import sys

D = 0.015
U_EXIT = 13.0                     # the bulk velocity at the exit: the scale of the velocity targets
MDOT_FEED = 0.634e-3              # kg/s, the feed's mass rate (mass loading 0.23)
STATIONS = [("m5D", -5.0), ("0.1D", 0.1), ("5D", 5.0), ("10D", 10.0), ("19D", 19.0)]
BIN = 0.1                         # radial bin width, in D
NBIN = 15                         # bins out to 1.5 D
MIN_GRAINS = 50                   # a bin compared between runs needs at least this many in each


def read_info(run):
    info = {}
    for line in open(os.path.join(run, "post", "runInfo.txt")):
        k, _, v = line.strip().partition(" ")
        info[k] = v
    ctrl = open(os.path.join(run, "system", "controlDict")).read()
    info["endTime"] = re.search(r"^endTime\s+([^;]+);", ctrl, re.M).group(1)
    wall = 0
    wall_file = os.path.join(run, "post", "wall.txt")
    if os.path.exists(wall_file):
        wall = sum(int(l.split()[1]) for l in open(wall_file) if l.startswith("wall_s"))
    else:   # the solver's own clock (of its last segment)
        clocks = re.findall(r"ClockTime = (\d+) s", open(os.path.join(run, "log.coarseDemFoam"), errors="replace").read())
        wall = int(clocks[-1]) if clocks else 0
    info["wall_s"] = wall
    return info


def read_crossings(run, tag, t0, t1, offset):
    """(diameter, r, u) of every grain that crossed plane <tag> in (t0, t1] (run time)."""
    rows = []
    files = sorted(glob.glob(os.path.join(run, "post", "station_%s.txt*" % tag)))
    for f in files:
        for line in open(f):
            if line.startswith("#") or not line.strip():
                continue
            c = line.split()
            t = float(c[1]) + offset
            if t0 < t <= t1:
                d, y, z, u = float(c[2]), float(c[4]), float(c[5]), float(c[6])
                rows.append((d, math.hypot(y, z), u))
    return rows


def inventory(run):
    """[(time, entered kg, left-through-outlets kg)] at every write time of the run's log."""
    out, t = [], None
    for line in open(os.path.join(run, "log.coarseDemFoam"), errors="replace"):
        if line.startswith("Time = "):
            t = float(line.split()[2])
        elif line.startswith("Particle inventory:") and t is not None:
            ent = sum(float(x) for x in re.findall(r"entered \w+ \d+ \(([-+.eE0-9]+) kg\)", line))
            left = sum(float(x) for x in re.findall(r"left \w+ \d+ \(([-+.eE0-9]+) kg\)", line))
            out.append((t, ent, left))
    return out


def rate_between(inv, t0, t1, col):
    """Mass rate (kg/s) of an inventory column between the write times nearest t0 and t1."""
    if not inv:
        return float("nan")
    a = min(inv, key=lambda r: abs(r[0] - t0))
    b = min(inv, key=lambda r: abs(r[0] - t1))
    return (b[col] - a[col]) / (b[0] - a[0]) if b[0] > a[0] else float("nan")


def grain_mass(d, rho):
    """A grain's mass: cg^3 real particles' (the solid mass it stands for)."""
    return rho * math.pi / 6 * d ** 3


def station_stats(rows, rho, T):
    bins = []
    for i in range(NBIN):
        r0, r1 = i * BIN * D, (i + 1) * BIN * D
        sel = [r for r in rows if r0 <= r[1] < r1]
        n = len(sel)
        area = math.pi * (r1 * r1 - r0 * r0)
        mass = sum(grain_mass(d, rho) for d, _, _ in sel)
        mean = sum(u for _, _, u in sel) / n if n else float("nan")
        var = sum((u - mean) ** 2 for _, _, u in sel) / (n - 1) if n > 1 else float("nan")
        bins.append({"r_D": (i + 0.5) * BIN, "n": n, "u": mean, "u_rms": math.sqrt(var) if n > 1 else float("nan"),
                     "u_sem": math.sqrt(var / n) if n > 1 else float("nan"), "G": mass / (area * T)})
    gmax = max(b["G"] for b in bins) or float("nan")
    for b in bins:
        b["G_Gmax"] = b["G"] / gmax
    # half-width of the mass flux: where G falls to half its maximum (linear between bin centres)
    hw = float("nan")
    k = max(range(NBIN), key=lambda i: bins[i]["G"])
    for i in range(k, NBIN - 1):
        g0, g1 = bins[i]["G_Gmax"], bins[i + 1]["G_Gmax"]
        if g0 >= 0.5 > g1:
            hw = bins[i]["r_D"] + (g0 - 0.5) / (g0 - g1) * BIN
            break
    mdot = sum(grain_mass(d, rho) for d, _, _ in rows) / T
    # the mass flux's rms radius (all grains inside 1.5 D): its width without a noisy maximum
    inner = [r for _, r, _ in rows if r < NBIN * BIN * D]
    r_rms = math.sqrt(sum(r * r for r in inner) / len(inner)) / D if inner else float("nan")
    return bins, hw, mdot, len(rows), r_rms


def read_gas(run):
    """UMean (axial component) on the axis [(x/D, U)] and across the jet at 19 D [(r/D, U)], at the last sample time."""
    times = sorted(glob.glob(os.path.join(run, "postProcessing", "gasProfiles", "*")),
                   key=lambda p: float(os.path.basename(p)))
    if not times:
        return None, None
    last = times[-1]

    def read(setname):
        f = [p for p in glob.glob(os.path.join(last, setname + "_*.xy")) if "UMean" in p and "kMean" not in p]
        if not f:
            return None
        # columns: coordinate, then the vector fields in the file name's order (U, UMean)
        names = os.path.basename(f[0])[len(setname) + 1:-3].split("_")
        j = 1 + 3 * names.index("UMean")
        return [(float(c[0]) / D, float(c[j])) for c in (l.split() for l in open(f[0]) if l.strip())]
    return read("axis"), read("r19D")


def interp(pts, x):
    for (x0, y0), (x1, y1) in zip(pts, pts[1:]):
        if x0 <= x <= x1:
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    return float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("-o", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "results"))
    ap.add_argument("-window", nargs=2, type=float, metavar=("T0", "T1"),
                    help="average over (T0, T1] instead of each run's tAverage ... endTime")
    a = ap.parse_args()
    os.makedirs(a.o, exist_ok=True)
    res = {}
    for run in a.runs:
        info = read_info(run)
        name = info["name"]
        t0, t1 = a.window if a.window else (float(info["tAverage"]), float(info["endTime"]))
        T = t1 - t0
        r = {"info": info, "T": T, "stations": {}, "gas": read_gas(run)}
        if info["laden"] == "1":
            inv = inventory(run)
            r["mdot_in"] = rate_between(inv, t0, t1, 1)
            r["mdot_out"] = rate_between(inv, t0, t1, 2)
            for tag, _ in STATIONS:
                rows = read_crossings(run, tag, t0, t1, float(info["demTimeOffset"]))
                r["stations"][tag] = station_stats(rows, 2950.0, T)
        res[name] = r

    # summary.csv
    ref = res.get("cg1B")
    base_wall = ref["info"]["wall_s"] if ref else 0
    head = ["run", "cg", "modelType", "window_s", "wall_s", "speedup_vs_cg1B", "mdot_feed_gps", "mdot_in_gps", "mdot_out_gps"]
    head += ["mdot_%s_gps" % t for t, _ in STATIONS]
    head += ["grains_%s" % t for t, _ in STATIONS]
    head += ["Up_axis_%s_mps" % t for t, _ in STATIONS]
    head += ["flux_halfwidth_%s_D" % t for t, _ in STATIONS]
    head += ["flux_rms_radius_%s_D" % t for t, _ in STATIONS]
    head += ["Uc_over_U0_10D", "Uc_over_U0_15D", "Uc_over_U0_19D", "gas_halfwidth_19D_D", "U0_mps"]
    lines = [",".join(head)]
    profile_lines = ["run,station,r_over_D,grains,Up_mean_mps,Up_sem_mps,Up_rms_mps,G_kg_m2s,G_over_Gmax"]
    for name, r in res.items():
        info = r["info"]
        row = [name, info["cg"], info["modelType"], "%g" % r["T"], str(info["wall_s"]),
               "%.2f" % (base_wall / info["wall_s"]) if base_wall and info["wall_s"] and info["laden"] == "1" else ""]
        if r["stations"]:
            row += ["%.4f" % (MDOT_FEED * 1e3), "%.4f" % (r["mdot_in"] * 1e3), "%.4f" % (r["mdot_out"] * 1e3)]
            row += ["%.4f" % (r["stations"][t][2] * 1e3) for t, _ in STATIONS]
            row += ["%d" % r["stations"][t][3] for t, _ in STATIONS]
            row += ["%.3f" % r["stations"][t][0][0]["u"] for t, _ in STATIONS]
            row += ["%.3f" % r["stations"][t][1] for t, _ in STATIONS]
            row += ["%.4f" % r["stations"][t][4] for t, _ in STATIONS]
            for t, _ in STATIONS:
                for b in r["stations"][t][0]:
                    profile_lines.append("%s,%s,%.2f,%d,%.4f,%.4f,%.4f,%.6g,%.4f" % (
                        name, t, b["r_D"], b["n"], b["u"], b["u_sem"], b["u_rms"], b["G"], b["G_Gmax"]))
        else:
            row += [""] * (3 + 6 * len(STATIONS))
        axis, r19 = r["gas"]
        if axis:
            U0 = interp(axis, 0.0)
            uc = [interp(axis, x) / U0 for x in (10.0, 15.0, 19.0)]
            hw = float("nan")
            if r19:
                uc19 = r19[0][1]
                for (x0, y0), (x1, y1) in zip(r19, r19[1:]):
                    if y0 >= 0.5 * uc19 > y1:
                        hw = x0 + (y0 - 0.5 * uc19) / (y0 - y1) * (x1 - x0)
                        break
            row += ["%.4f" % v for v in uc] + ["%.3f" % hw, "%.3f" % U0]
            r["gas_numbers"] = uc + [hw, U0]
        else:
            row += [""] * 5
        lines.append(",".join(row))
    open(os.path.join(a.o, "summary.csv"), "w").write("\n".join(lines) + "\n")
    open(os.path.join(a.o, "profiles.csv"), "w").write("\n".join(profile_lines) + "\n")
    checks(res, a.o)
    plots(res, a.o)
    print("postprocess.py: wrote %s/summary.csv, profiles.csv, checks.md, profiles.png, gas.png" % a.o)


def compare(r, ref, tag):
    """Largest |Up - Up_ref| / U_exit over the bins with MIN_GRAINS grains in both, with its SEM."""
    worst = (0.0, 0.0, float("nan"))
    for b, c in zip(r["stations"][tag][0], ref["stations"][tag][0]):
        if b["n"] >= MIN_GRAINS and c["n"] >= MIN_GRAINS:
            d = abs(b["u"] - c["u"]) / U_EXIT
            sem = math.hypot(b["u_sem"], c["u_sem"]) / U_EXIT
            if d > worst[0]:
                worst = (d, sem, b["r_D"])
    return worst


def flux_compare(r, ref, tag):
    """Largest |G - G_ref| / max(G_ref) over bins with MIN_GRAINS grains in both, with its counting
    (Poisson) error, at that bin; the two rms radii of the flux."""
    gmax = max(c["G"] for c in ref["stations"][tag][0])
    worst = (0.0, 0.0)
    for b, c in zip(r["stations"][tag][0], ref["stations"][tag][0]):
        if b["n"] >= MIN_GRAINS and c["n"] >= MIN_GRAINS:
            d = abs(b["G"] - c["G"]) / gmax
            err = math.hypot(b["G"] / math.sqrt(b["n"]), c["G"] / math.sqrt(c["n"])) / gmax
            if d > worst[0]:
                worst = (d, err)
    return worst[0], worst[1], r["stations"][tag][4], ref["stations"][tag][4]


def checks(res, out):
    L = ["# particleJet: the checks (postprocess.py)", ""]
    L.append("Velocities are compared in bins of 0.1 D holding at least %d grains in both runs; the error"
             " of a difference is the two bins' standard errors of the mean combined." % MIN_GRAINS)
    L.append("")
    L.append("| check | run | target | measured | met |")
    L.append("|---|---|---|---|---|")
    for name, r in res.items():
        if not r["stations"]:
            continue
        worst = max(abs(r["stations"][t][2] / MDOT_FEED - 1) for t, _ in STATIONS)
        L.append("| solid mass flow through every plane vs the feed's 0.634 g/s | %s | within 3 %% | largest deviation %.1f %% (fed %.4f, out %.4f g/s) | %s |"
                 % (name, 100 * worst, r["mdot_in"] * 1e3, r["mdot_out"] * 1e3, "yes" if worst <= 0.03 else "no"))
    ref = res.get("cg1B")
    if ref and ref["stations"]:
        for name in ("cg2B", "cg3B"):
            if name in res:
                for tag, x in STATIONS[1:]:
                    d, sem, rd = compare(res[name], ref, tag)
                    L.append("| mean particle axial velocity profile vs cg1B, x = %g D | %s | within 3 %% of U_exit | %.2f %% (± %.2f %%) at r = %.2f D | %s |"
                             % (x, name, 100 * d, 100 * sem, rd, "yes" if d <= 0.03 else "no"))
        for name in ("cg2B", "cg3B"):
            if name not in res:
                continue
            for tag, x in STATIONS[1:]:
                g, gerr, w, w_ref = flux_compare(res[name], ref, tag)
                L.append("| mass-flux profile G vs cg1B (per bin, over cg1B's largest), x = %g D | %s | within 0.10 | %.3f (counting error ± %.3f) | %s |"
                         % (x, name, g, gerr, "yes" if g <= 0.10 else
                            "no: %.1f counting errors (a longer window would tell)" % (g / gerr)))
                L.append("| rms radius of the mass flux vs cg1B, x = %g D | %s | within 5 %% | %.3f D vs %.3f D (%+.1f %%) | %s |"
                         % (x, name, w, w_ref, 100 * (w / w_ref - 1), "yes" if abs(w / w_ref - 1) <= 0.05 else "no"))
            if res[name].get("gas_numbers") and ref.get("gas_numbers"):
                a, b = res[name]["gas_numbers"], ref["gas_numbers"]
                d = max(abs(a[i] / b[i] - 1) for i in range(3))
                L.append("| gas centreline velocity vs cg1B at 10, 15, 19 D | %s | within 2 %% | largest %.2f %% | %s |"
                         % (name, 100 * d, "yes" if d <= 0.02 else "no"))
    if "cg3A" in res and "cg3B" in res:
        for tag, x in STATIONS[1:]:
            d, sem, rd = compare(res["cg3A"], res["cg3B"], tag)
            L.append("| Model A vs Model B (cg 3), x = %g D | cg3A | within 1 %% of U_exit | %.3f %% (± %.2f %%) at r = %.2f D | %s |"
                     % (x, 100 * d, 100 * sem, rd, "yes" if d <= 0.01 else "no"))
    gas = res.get("gas")
    if gas and gas.get("gas_numbers"):
        uc10, uc15, uc19, hw, U0 = gas["gas_numbers"]
        lo, hi = 5.8 / 19.0, 6.06 / 15.0
        L.append("| gas centreline U_c/U_0 at 19 D (round jet: B D/(x - x0), B 5.8-6.06, x0 0-4 D) | gas | %.3f-%.3f (±10 %% for a coarse RANS: %.3f-%.3f) | %.3f (U_0 %.2f m/s) | %s |"
                 % (lo, hi, 0.9 * lo, 1.1 * hi, uc19, U0, "yes" if 0.9 * lo <= uc19 <= 1.1 * hi else "no"))
        L.append("| gas half-width at 19 D | gas | about 1.4-1.8 D (spreading rate 0.094, x0 0-4 D) | %.2f D | %s |"
                 % (hw, "yes" if 1.4 * 0.9 <= hw <= 1.8 * 1.1 else "no"))
        for name in ("cg1B",):
            if name in res and res[name].get("gas_numbers"):
                g = res[name]["gas_numbers"]
                L.append("| two-way coupling: gas U_c/U_0 laden minus gas only, 10 / 19 D | %s | report | %+.4f / %+.4f | |"
                         % (name, g[0] - uc10, g[2] - uc19))
    open(os.path.join(out, "checks.md"), "w").write("\n".join(L) + "\n")


def plots(res, out):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("postprocess.py: no matplotlib, no PNGs", file=sys.stderr)
        return
    laden = [(n, r) for n, r in res.items() if r["stations"]]
    if laden:
        fig, ax = plt.subplots(2, len(STATIONS), figsize=(3.2 * len(STATIONS), 6), sharey="row")
        for j, (tag, x) in enumerate(STATIONS):
            for name, r in laden:
                bins = [b for b in r["stations"][tag][0] if b["n"] >= 10]
                ax[0, j].errorbar([b["r_D"] for b in bins], [b["u"] / U_EXIT for b in bins],
                                  yerr=[b["u_sem"] / U_EXIT for b in bins], marker="o", ms=3, label=name)
                ax[1, j].plot([b["r_D"] for b in r["stations"][tag][0]], [b["G_Gmax"] for b in r["stations"][tag][0]], marker="o", ms=3, label=name)
            ax[0, j].set_title("x = %g D" % x)
            ax[1, j].set_xlabel("r / D")
        ax[0, 0].set_ylabel("U_p / U_exit")
        ax[1, 0].set_ylabel("G / G_max")
        ax[0, 0].legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "profiles.png"), dpi=110)
    fig, ax = plt.subplots(figsize=(6, 4))
    for name, r in res.items():
        axis = r["gas"][0]
        if axis:
            U0 = interp(axis, 0.0)
            ax.plot([p[0] for p in axis], [p[1] / U0 for p in axis], label=name)
    xs = [x / 2.0 for x in range(16, 41)]   # the far-field law, from 8 D on
    ax.fill_between(xs, [5.8 / (x - 0) for x in xs], [6.06 / (x - 4) for x in xs], color="0.85", label="round jet, B 5.8-6.06, x0 0-4 D")
    ax.set_xlabel("x / D")
    ax.set_ylabel("U_c / U_0")
    ax.set_ylim(0, 1.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "gas.png"), dpi=110)


if __name__ == "__main__":
    main()
