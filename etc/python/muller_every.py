"""Every set-up on every quantity: the Mueller-bed runs against every MR profile held at their inlet
velocity, the physics checks, and the recommendation rule of validation/muller/results/README.md.

    everyQuantity.py [-U 0.9] [-o OUT_PREFIX] RUN_RESULTS_DIR ...

For each run's results folder (profile_*.csv from profiles.py; pressure.csv from pressureDrop.py where
the run has it): the RMS error of the headline instrument (depth-averaged, particles binned by the cell
of their centre) against each MR file of validation/muller/data at U, with the run's mean batch SEM;
the peak of v_z at 15, 25 and 35 mm and its minimum at 15 mm (the near-wall downflow); the solid's net flux at 15 mm over the gross (muller_flux: 0 in a
steady bed); the pressure drop against the weight, the walls' share and the expansion.

The rule (written before the runs it judges): a set-up is WORSE than another on a profile when its RMS
error exceeds the other's by more than twice their combined batch SEM, sqrt(sem_a^2 + sem_b^2); a
set-up may be recommended only if no other set-up is better than it on any profile by that margin, and
it passes the physics checks (pressure drop within 2 % of the weight; net flux within 0.05 of the
gross). Writes OUT_PREFIX.csv and OUT_PREFIX.md (default validation/muller/results/everyQuantity).
"""
import csv
import math
import os
import sys

import muller_compare
from muller_flux import balance, read_xy, run_name

PEAK_HEIGHTS = ("15", "25", "35")


def measure(results, data, U):
    """{column: value} of one run."""
    row = {"run": run_name(results)}
    for r in muller_compare.compare(results, data, U, None):
        if r["quantity"].endswith("_depth_binned") or r["quantity"].endswith("_depth_binned_m_per_s"):
            key = ("gas" if r["quantity"].startswith("void") else "vz") + "_z" + str(r["z_mm"])
            row[key + "_rms"], row[key + "_sem"] = r["rms_error"], r["mean_batch_sem"]
    for z in PEAK_HEIGHTS:
        f = os.path.join(results, f"profile_vzdepthbinned_z{z}mm.csv")
        if os.path.exists(f):
            x, v = read_xy(f)
            row[f"vz_peak_z{z}"] = float(v.max())
            if z == "15":
                row["vz_min_z15"] = float(v.min())   # the near-wall downflow
    fv = os.path.join(results, "profile_vzdepthbinned_z15mm.csv")
    fe = os.path.join(results, "profile_voidfractiondepthbinned_z15mm.csv")
    if os.path.exists(fv) and os.path.exists(fe):
        row["net_flux_z15"] = balance(*read_xy(fv), *read_xy(fe))[0]
    fp = os.path.join(results, "pressure.csv")
    if os.path.exists(fp):
        with open(fp) as f:
            p = next(csv.DictReader(f))
        for k in ("dp_rel_err", "dp_sem_pa", "wall_force_share", "expansion_2zbar_over_settled"):
            if p.get(k) not in (None, ""):
                row[k] = float(p[k])
    return row


def worse(a, b, key):
    """Whether run a is worse than run b on profile key beyond twice their combined SEM."""
    if key + "_rms" not in a or key + "_rms" not in b:
        return False
    margin = 2 * math.sqrt(a.get(key + "_sem", 0) ** 2 + b.get(key + "_sem", 0) ** 2)
    return a[key + "_rms"] - b[key + "_rms"] > margin


def verdicts(rows):
    profiles = sorted({k[:-4] for r in rows for k in r if k.endswith("_rms")})
    for a in rows:
        beaten = []
        for k in profiles:
            by = [b["run"] for b in rows if b is not a and worse(a, b, k)]
            if by:
                beaten.append(f"{k} (beaten by {len(by)}: {', '.join(by)})")
        checks = []
        if "dp_rel_err" in a and abs(a["dp_rel_err"]) > 0.02:
            checks.append(f"pressure drop {100 * a['dp_rel_err']:+.1f} %")
        if "net_flux_z15" in a and abs(a["net_flux_z15"]) > 0.05:
            checks.append(f"net flux {a['net_flux_z15']:+.2f}")
        a["verdict"] = "not worse on any profile" if not beaten else "worse on " + "; ".join(beaten)
        if checks:
            a["verdict"] += "; fails " + ", ".join(checks)
    return profiles


def main():
    args = sys.argv[1:]
    here = os.path.dirname(os.path.abspath(__file__))
    data = os.path.join(here, "..", "..", "validation", "muller", "data")
    out = os.path.join(here, "..", "..", "validation", "muller", "results", "everyQuantity")
    U = 0.9
    while args and args[0] in ("-U", "-o", "-data"):
        if len(args) < 2:
            sys.exit(__doc__)
        if args[0] == "-U":
            U = float(args[1])
        elif args[0] == "-o":
            out = args[1]
        else:
            data = args[1]
        args = args[2:]
    if not args:
        sys.exit(__doc__)
    rows = [measure(r, data, U) for r in args]
    profiles = verdicts(rows)
    cols = ["run"] + [k + s for k in profiles for s in ("_rms", "_sem")] + \
        [f"vz_peak_z{z}" for z in PEAK_HEIGHTS] + ["vz_min_z15", "net_flux_z15", "dp_rel_err", "dp_sem_pa",
                                                   "wall_force_share", "expansion_2zbar_over_settled", "verdict"]
    cols = [c for c in cols if any(c in r for r in rows)]
    fmt = lambda v: f"{v:.4g}" if isinstance(v, float) else str(v)
    with open(out + ".csv", "w") as f:
        f.write("# command: validation/muller/everyQuantity.py -U %g %s\n" % (U, " ".join(args)))
        w = csv.writer(f)
        w.writerow(cols)
        for r in rows:
            w.writerow([fmt(r[c]) if c in r else "" for c in cols])
    with open(out + ".md", "w") as f:
        f.write(f"Every set-up on every MR profile at U = {U} m/s (RMS error, depth-averaged binned instrument, "
                "± mean batch SEM) and the physics checks; the rule: muller_every.py's docstring.\n\n")
        heads = ["run"] + [k for k in profiles] + [f"v_z peak {z} mm" for z in PEAK_HEIGHTS
                                                     if f"vz_peak_z{z}" in cols] + \
            (["v_z min 15 mm"] if "vz_min_z15" in cols else []) + \
            [h for c, h in (("net_flux_z15", "net flux 15 mm"), ("dp_rel_err", "dp - weight"),
                            ("wall_force_share", "walls' share"), ("expansion_2zbar_over_settled", "expansion"))
             if c in cols] + ["verdict"]
        f.write("| " + " | ".join(heads) + " |\n|" + "---|" * len(heads) + "\n")
        for r in rows:
            cells = [r["run"]] + [f"{r[k + '_rms']:.3f} ± {r.get(k + '_sem', float('nan')):.3f}" if k + "_rms" in r else "-"
                                  for k in profiles]
            cells += [f"{r[f'vz_peak_z{z}']:.3f}" if f"vz_peak_z{z}" in r else "-" for z in PEAK_HEIGHTS if f"vz_peak_z{z}" in cols]
            if "vz_min_z15" in cols:
                cells.append(f"{r['vz_min_z15']:.3f}" if "vz_min_z15" in r else "-")
            for c, scale, unit in (("net_flux_z15", 1, ""), ("dp_rel_err", 100, " %"), ("wall_force_share", 100, " %"),
                                   ("expansion_2zbar_over_settled", 1, "")):
                if c in cols:
                    cells.append(f"{scale * r[c]:+.3g}{unit}" if c in r else "-")
            cells.append(r["verdict"])
            f.write("| " + " | ".join(cells) + " |\n")
    print(open(out + ".md").read())
