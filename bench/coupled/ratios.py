#!/usr/bin/python3
"""ratios.py -- the Markdown table of bench/coupled/results/coupled.csv: each target of the performance
issue as a ratio measured in one run, and whether it is met.

    ratios.py coupled.csv > ratios.md

Columns of the CSV (seconds over the same couplings): total_s (the coupled run's time loop), dem_s,
fluid_s, coupling_s (its stage timers but DEM, fluid and the output-only fields),
dem_alone_s (LIGGGHTS alone, frozen coupling forces), fluid_alone_s (coarseDemFoam -frozenParticles'
fluid stage), pimpleFoam_s (pimpleFoam, alpha = 1, same steps).
"""
import csv
import sys


def main():
    rows = list(csv.DictReader(open(sys.argv[1])))
    f = lambda r, k: float(r[k])
    serial = {r["method"]: f(r, "total_s") for r in rows if r["np"] == "1"}
    print("| method | np | coupling / total (target) | total / (DEM alone + fluid alone) (<= 1.07) "
          "| fluid / pimpleFoam per step (<= 1.3) | DEM in run / DEM alone | speed-up np 1 -> 2 (>= 1.8) |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        m, np = r["method"], r["np"]
        share = f(r, "coupling_s") / f(r, "total_s")
        target = 0.15 if m == "gaussian" else 0.05
        parts = f(r, "total_s") / (f(r, "dem_alone_s") + f(r, "fluid_alone_s"))
        fluid = f(r, "fluid_s") / f(r, "pimpleFoam_s")
        dem = f(r, "dem_s") / f(r, "dem_alone_s")
        speed = ""
        if np == "2" and m in serial:
            s = serial[m] / f(r, "total_s")
            speed = "%.2f %s" % (s, "met" if s >= 1.8 else "**missed**")
        mark = lambda ok: "met" if ok else "**missed**"
        print("| %s | %s | %.3f (<= %.2f) %s | %.2f %s | %.2f %s | %.2f | %s |" % (
            m, np, share, target, mark(share <= target), parts, mark(parts <= 1.07), fluid, mark(fluid <= 1.3),
            dem, speed))


if __name__ == "__main__":
    main()
