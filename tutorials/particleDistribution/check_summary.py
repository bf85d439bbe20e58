#!/usr/bin/python3
"""Check the particleDistribution results against the findings of Zhang et al. 2023 (Phys. Fluids 35,
113330), section V.A, at dx/d = 1. Standard library only.

    ./check_summary.py [results/summary.csv]

Prints one PASS/FAIL line per criterion; exit status 0 if all pass, 1 if any fails, 2 if the file is
missing or malformed.
"""
import csv
import math
import os
import sys

HEADER = ["method", "dx_over_d", "n_expand", "mean", "std", "min", "max", "conservation_rel_err", "seconds",
          "seconds_per_particle"]
REGION_MEAN = 0.3
MESH_DX = [2.0, 1.0, ((160.0 / 239.0) ** 2 * (4.0 / 6.0)) ** (1.0 / 3.0), 0.5]  # Table I: V_c^(1/3)/d
METHODS = [("centre", ""), ("divided", ""), ("bigParticle", ""), ("bigParticle", "2"), ("bigParticle", "3"),
           ("bigParticle", "4"), ("bigParticle", "5"), ("twoGrid", ""), ("gaussian", ""), ("exact", ""),
           ("diffusion", "")]

failures = 0


def report(ok, text):
    global failures
    print("%s: particleDistribution/%s" % ("PASS" if ok else "FAIL", text))
    if not ok:
        failures += 1


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                               "results", "summary.csv")
    try:
        with open(path, newline="") as f:
            reader = csv.reader(f)
            header = next(reader)
            rows = [dict(zip(header, r)) for r in reader if r]
    except (OSError, StopIteration) as e:
        print("FAIL: particleDistribution/read %s: %s" % (path, e))
        return 2
    report(header == HEADER, "header is exactly %s" % ",".join(HEADER))
    if header != HEADER:
        return 1
    try:
        for r in rows:
            for key in HEADER[1:]:
                if key != "n_expand":
                    r[key] = float(r[key])
    except ValueError as e:
        print("FAIL: particleDistribution/numbers in %s: %s" % (path, e))
        return 2

    def find(method, n_expand, dx):
        hits = [r for r in rows if r["method"] == method and r["n_expand"] == n_expand and
                abs(r["dx_over_d"] - dx) <= 1e-2 * dx]
        return hits[0] if len(hits) == 1 else None

    # every method on every mesh, once
    missing = ["%s%s@%.3g" % (m, "_n" + n if n else "", dx) for dx in MESH_DX for m, n in METHODS
               if find(m, n, dx) is None]
    report(not missing, "all %d (method, mesh) rows present exactly once%s" %
           (len(MESH_DX) * len(METHODS), "" if not missing else "; missing/duplicated: " + " ".join(missing)))

    # conservation, every row
    worst = max(rows, key=lambda r: r["conservation_rel_err"] if math.isfinite(r["conservation_rel_err"])
                else math.inf)
    ok = all(math.isfinite(r["conservation_rel_err"]) and r["conservation_rel_err"] <= 1e-12 for r in rows)
    report(ok, "conservation: every row rel err <= 1e-12 (worst %.3e: %s n=%s dx/d=%.3g)" %
           (worst["conservation_rel_err"], worst["method"], worst["n_expand"] or "-", worst["dx_over_d"]))

    div, big5, dif = find("divided", "", 1.0), find("bigParticle", "5", 1.0), find("diffusion", "", 1.0)
    if div is None or big5 is None or dif is None:
        report(False, "rows divided, bigParticle n=5 and diffusion at dx/d = 1 exist")
        return 1

    report(div["std"] > 0.1, "divided dx/d=1: std %.4f > 0.1" % div["std"])
    report(div["min"] < 0.1, "divided dx/d=1: min %.4f < 0.1" % div["min"])
    report(div["max"] > 0.5, "divided dx/d=1: max %.4f > 0.5" % div["max"])
    report(big5["std"] <= 0.075, "bigParticle n=5 dx/d=1: std %.4f <= 0.075" % big5["std"])
    report(big5["std"] <= 0.5 * div["std"],
           "bigParticle n=5 dx/d=1: std %.4f <= half of divided's (%.4f)" % (big5["std"], 0.5 * div["std"]))
    report(abs(big5["mean"] - REGION_MEAN) <= 0.02,
           "bigParticle n=5 dx/d=1: mean %.4f within 0.02 of %.1f" % (big5["mean"], REGION_MEAN))
    report(dif["std"] <= 0.02, "diffusion b=6d dx/d=1: std %.4f <= 0.02" % dif["std"])
    report(abs(dif["mean"] - REGION_MEAN) <= 0.02,
           "diffusion b=6d dx/d=1: mean %.4f within 0.02 of %.1f" % (dif["mean"], REGION_MEAN))
    print("%d failed" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
