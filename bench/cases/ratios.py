#!/usr/bin/env python3
"""bench/cases/ratios.py CSV: the cost table of bench/cases/run.sh as markdown, and the CSV's column
cost_ratio_to_baseline (each row's wall s per simulated s over the baseline's of the same case and
rank count, from the same CSV; 1 for a baseline, empty without one) written into the CSV.

Per case and rank count: wall seconds per simulated second with the baseline and the tutorial's
settings and their ratio (issue 44's target: at most 0.5 on 2 ranks), the stage shares of each run;
per case and settings: the 2-rank speed-up of the run, of its DEM stage and of its fluid stage."""
import csv
import sys
from collections import defaultdict

TARGET = 0.5


RATIO = "cost_ratio_to_baseline"


def write_ratio_column(path, rows, by):
    """rewrite the CSV with RATIO as its last column (recomputed if it is there already)"""
    fields = [k for k in rows[0] if k != RATIO] + [RATIO]
    for r in rows:
        b = by.get((r["case"], "baseline", r["np"]))
        r[RATIO] = "%.4f" % (float(r["wall_per_simulated_s"]) / float(b["wall_per_simulated_s"])) if b else ""
    with open(path, "w", newline="") as out:
        w = csv.DictWriter(out, fieldnames=fields, lineterminator="\n")
        w.writeheader()
        w.writerows({k: r.get(k) or "" for k in fields} for r in rows)


def main(path):
    rows = list(csv.DictReader(open(path)))
    by = {(r["case"], r["settings"], r["np"]): r for r in rows}
    write_ratio_column(path, rows, by)
    f = lambda r, k: float(r[k])
    print("Cost per simulated second (wall s of the time loop / simulated s) and stage shares "
          "(DEM, fluid, coupling; of the stage timers' sum)\n")
    print("| case | np | baseline s/s | tutorial s/s | tutorial / baseline | baseline DEM/fluid/coupling | "
          "tutorial DEM/fluid/coupling |")
    print("|---|---|---|---|---|---|---|")
    shares = {}
    for r in rows:
        tot = f(r, "dem_s") + f(r, "fluid_s") + f(r, "coupling_s")
        shares[(r["case"], r["settings"], r["np"])] = "/".join(
            "%.0f %%" % (100 * f(r, k) / tot) if tot > 0 else "nan" for k in ("dem_s", "fluid_s", "coupling_s"))
    seen = []
    for r in rows:
        key = (r["case"], r["np"])
        if key in seen:
            continue
        seen.append(key)
        b, t = by.get((key[0], "baseline", key[1])), by.get((key[0], "tutorial", key[1]))
        if not (b and t):
            continue
        ratio = f(t, "wall_per_simulated_s") / f(b, "wall_per_simulated_s")
        mark = "" if key[1] != "2" else (" met" if ratio <= TARGET else " **missed** (<= %.1f)" % TARGET)
        print("| %s | %s | %.0f | %.0f | %.2f%s | %s | %s |" % (
            key[0], key[1], f(b, "wall_per_simulated_s"), f(t, "wall_per_simulated_s"), ratio, mark,
            shares[(key[0], "baseline", key[1])], shares[(key[0], "tutorial", key[1])]))
    print("\n2-rank speed-up (np 1 / np 2) of the run, of its DEM stage and of its fluid stage\n")
    print("| case | settings | run | DEM | fluid |")
    print("|---|---|---|---|---|")
    done = set()
    for r in rows:
        key = (r["case"], r["settings"])
        if key in done:
            continue
        done.add(key)
        one, two = by.get((key[0], key[1], "1")), by.get((key[0], key[1], "2"))
        if not (one and two):
            continue
        sp = lambda k: "%.2f" % (f(one, k) / f(two, k)) if f(two, k) > 0 else "nan"
        print("| %s | %s | %s | %s | %s |" % (key[0], key[1], sp("wall_s"), sp("dem_s"), sp("fluid_s")))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: ratios.py cases.csv")
    main(sys.argv[1])
