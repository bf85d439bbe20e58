#!/usr/bin/env python3
"""bench/cases/ratios.py RUNS_CSV CASES_CSV: the cost table of bench/cases/run.sh.
bench/cases/ratios.py -methods METHODS_CSV: the methods' table of run.sh -methods (printed).

Reads the runs (one row per case, settings and rank count, or several: run.sh -pairs N writes the
baseline and tutorial rows of a case and rank count in turn, and the k-th baseline row is paired
with the k-th tutorial row) and writes CASES_CSV, one row per case and rank count measured with both
settings: the baseline's and the tutorial's wall seconds per simulated second (medians over the
pairs), their ratio (the median of the pairs' ratios; issue 44's target: at most 0.5 on 2 ranks), each
one's DEM / fluid / coupling shares (of the stage timers' sums over its runs), the number of pairs
and the smallest and largest pair's ratio. Prints the same as markdown, and per case and settings
the 2-rank speed-up of the run, of its DEM stage and of its fluid stage (medians).

With -methods: the k-th run of a method is paired with the k-th run of centre (PCM) on the same case
and rank count (run.sh runs them in rounds), and per case, rank count and method it prints the median
cost per simulated second, the median of the rounds' ratios to centre's, the DEM / fluid / coupling
shares, and the coupling's seconds per simulated second with what they add to centre's as a share of
centre's run (Zhang et al. 2023, §V.C, compare the methods' total cost with PCM's: at most 5 % more)."""
import csv
import statistics
import sys

TARGET = 0.5
STAGES = ("dem_s", "fluid_s", "coupling_s")


def shares(runs):
    tot = [sum(float(r[k]) for r in runs) for k in STAGES]
    s = sum(tot)
    return [v / s if s > 0 else float("nan") for v in tot]


def median(runs, key):
    return statistics.median(float(r[key]) for r in runs)


def main(runs_csv, cases_csv):
    rows = list(csv.DictReader(open(runs_csv)))
    by = {}
    for r in rows:
        by.setdefault((r["case"], r["settings"], r["np"]), []).append(r)
    keys = []
    for r in rows:
        if (r["case"], r["np"]) not in keys:
            keys.append((r["case"], r["np"]))
    table = []
    for case, np_ in keys:
        b, t = by.get((case, "baseline", np_), []), by.get((case, "tutorial", np_), [])
        n = min(len(b), len(t))
        if n == 0:
            continue
        ratios = [float(t[k]["wall_per_simulated_s"]) / float(b[k]["wall_per_simulated_s"]) for k in range(n)]
        table.append((case, np_, b[:n], t[:n], ratios))
    fields = ["case", "np", "simulated_s", "baseline_wall_per_simulated_s", "tutorial_wall_per_simulated_s",
              "cost_ratio_to_baseline"] + ["%s_%s_share" % (s, k[:-2]) for s in ("baseline", "tutorial") for k in STAGES] \
             + ["pairs", "cost_ratio_min", "cost_ratio_max"]
    with open(cases_csv, "w", newline="") as out:
        w = csv.writer(out, lineterminator="\n")
        w.writerow(fields)
        for case, np_, b, t, ratios in table:
            w.writerow([case, np_, t[0]["simulated_s"], "%.6g" % median(b, "wall_per_simulated_s"),
                        "%.6g" % median(t, "wall_per_simulated_s"), "%.4f" % statistics.median(ratios)]
                       + ["%.4f" % v for v in shares(b) + shares(t)]
                       + [len(ratios), "%.4f" % min(ratios), "%.4f" % max(ratios)])
    pct = lambda runs: "/".join("%.0f %%" % (100 * v) for v in shares(runs))
    print("Cost per simulated second (wall s of the time loop / simulated s; medians over the pairs) and "
          "stage shares (DEM, fluid, coupling; of the stage timers' sums)\n")
    print("| case | np | pairs | baseline s/s | tutorial s/s | tutorial / baseline (median; smallest-largest pair) | "
          "baseline DEM/fluid/coupling | tutorial DEM/fluid/coupling |")
    print("|---|---|---|---|---|---|---|---|")
    for case, np_, b, t, ratios in table:
        ratio = statistics.median(ratios)
        mark = "" if np_ != "2" else (" met" if ratio <= TARGET else " **missed** (<= %.1f)" % TARGET)
        spread = "" if len(ratios) == 1 else " (%.2f-%.2f)" % (min(ratios), max(ratios))
        print("| %s | %s | %d | %.0f | %.0f | %.2f%s%s | %s | %s |" % (
            case, np_, len(ratios), median(b, "wall_per_simulated_s"), median(t, "wall_per_simulated_s"), ratio,
            spread, mark, pct(b), pct(t)))
    print("\n2-rank speed-up (np 1 / np 2, medians) of the run, of its DEM stage and of its fluid stage\n")
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
        sp = lambda k: "%.2f" % (median(one, k) / median(two, k)) if median(two, k) > 0 else "nan"
        print("| %s | %s | %s | %s | %s |" % (key[0], key[1], sp("wall_s"), sp("dem_s"), sp("fluid_s")))


def methods_table(methods_csv):
    rows = list(csv.DictReader(open(methods_csv)))
    by, order = {}, []
    for r in rows:
        key = (r["case"], r["np"], r["method"])
        if key not in by:
            order.append(key)
        by.setdefault(key, []).append(r)
    print("Each method's cost on the same state, the tutorial's settings (wall s of the time loop per simulated s; "
          "medians over the rounds) against centre's (PCM) in the same round, and its coupling stages\n")
    print("| case | np | method | rounds | s/s | / centre (smallest-largest round) | DEM/fluid/coupling | "
          "coupling s/s | coupling added to centre's, of centre's run |")
    print("|---|---|---|---|---|---|---|---|---|")
    per_s = lambda r, k: float(r[k]) / float(r["simulated_s"])
    for case, np_, method in order:
        runs, pcm = by[(case, np_, method)], by.get((case, np_, "centre"), [])
        n = min(len(runs), len(pcm))
        if n == 0:
            continue
        ratio = [float(runs[k]["wall_per_simulated_s"]) / float(pcm[k]["wall_per_simulated_s"]) for k in range(n)]
        added = [(per_s(runs[k], "coupling_s") - per_s(pcm[k], "coupling_s")) / float(pcm[k]["wall_per_simulated_s"])
                 for k in range(n)]
        spread = "" if n == 1 else " (%.2f-%.2f)" % (min(ratio), max(ratio))
        print("| %s | %s | %s | %d | %.0f | %.2f%s | %s | %.1f | %+.1f %% |" % (
            case, np_, method, n, median(runs[:n], "wall_per_simulated_s"), statistics.median(ratio), spread,
            "/".join("%.0f %%" % (100 * v) for v in shares(runs[:n])),
            statistics.median(per_s(r, "coupling_s") for r in runs[:n]), 100 * statistics.median(added)))


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "-methods":
        methods_table(sys.argv[2])
    elif len(sys.argv) == 3:
        main(sys.argv[1], sys.argv[2])
    else:
        sys.exit("usage: ratios.py runs.csv cases.csv | ratios.py -methods methods.csv")
