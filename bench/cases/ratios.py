#!/usr/bin/env python3
"""bench/cases/ratios.py RUNS_CSV CASES_CSV: the cost table of bench/cases/run.sh.

Reads the runs (one row per case, settings and rank count) and writes CASES_CSV, one row per case and
rank count measured with both settings: the baseline's and the tutorial's wall seconds per simulated
second, their ratio (issue 44's target: at most 0.5 on 2 ranks) and each one's stage shares (DEM,
fluid, coupling, of the stage timers' sum). Prints the same as markdown, and per case and settings
the 2-rank speed-up of the run, of its DEM stage and of its fluid stage."""
import csv
import sys

TARGET = 0.5
STAGES = ("dem_s", "fluid_s", "coupling_s")


def shares(r):
    tot = sum(float(r[k]) for k in STAGES)
    return [float(r[k]) / tot if tot > 0 else float("nan") for k in STAGES]


def main(runs_csv, cases_csv):
    rows = list(csv.DictReader(open(runs_csv)))
    by = {(r["case"], r["settings"], r["np"]): r for r in rows}
    f = lambda r, k: float(r[k])
    pairs = []
    for r in rows:
        key = (r["case"], r["np"])
        b, t = by.get((key[0], "baseline", key[1])), by.get((key[0], "tutorial", key[1]))
        if b and t and key not in [k for k, _, _ in pairs]:
            pairs.append((key, b, t))
    fields = ["case", "np", "simulated_s", "baseline_wall_per_simulated_s", "tutorial_wall_per_simulated_s",
              "cost_ratio_to_baseline"] + ["%s_%s_share" % (s, k[:-2]) for s in ("baseline", "tutorial") for k in STAGES]
    with open(cases_csv, "w", newline="") as out:
        w = csv.writer(out, lineterminator="\n")
        w.writerow(fields)
        for (case, np_), b, t in pairs:
            ratio = f(t, "wall_per_simulated_s") / f(b, "wall_per_simulated_s")
            w.writerow([case, np_, t["simulated_s"], b["wall_per_simulated_s"], t["wall_per_simulated_s"], "%.4f" % ratio]
                       + ["%.4f" % v for v in shares(b) + shares(t)])
    pct = lambda r: "/".join("%.0f %%" % (100 * v) for v in shares(r))
    print("Cost per simulated second (wall s of the time loop / simulated s) and stage shares "
          "(DEM, fluid, coupling; of the stage timers' sum)\n")
    print("| case | np | baseline s/s | tutorial s/s | tutorial / baseline | baseline DEM/fluid/coupling | "
          "tutorial DEM/fluid/coupling |")
    print("|---|---|---|---|---|---|---|")
    for (case, np_), b, t in pairs:
        ratio = f(t, "wall_per_simulated_s") / f(b, "wall_per_simulated_s")
        mark = "" if np_ != "2" else (" met" if ratio <= TARGET else " **missed** (<= %.1f)" % TARGET)
        print("| %s | %s | %.0f | %.0f | %.2f%s | %s | %s |" % (
            case, np_, f(b, "wall_per_simulated_s"), f(t, "wall_per_simulated_s"), ratio, mark, pct(b), pct(t)))
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
    if len(sys.argv) != 3:
        sys.exit("usage: ratios.py runs.csv cases.csv")
    main(sys.argv[1], sys.argv[2])
