#!/usr/bin/python3
"""scene_sources.py -- PASS/FAIL line comparing the fluid's momentum source of two runs of one step.

    scene_sources.py <case alpha-only> <case smoothed sources> <scene name> [fFluid|Ksl]

Both cases start from the same particles and run one CFD step; the second smooths the fluid's sources
(diffusionProps/smoothExchangeFields). At the written step, for the field named (default fFluid, the
explicit force density; Ksl, the implicit drag coefficient, needs writeExchangeFields on):
sum(f V) must be the same in both to 1e-12 of sum |f| V (smoothing moves momentum between cells, it
neither makes nor loses any), and the peak |f| of the smoothed run must be below 0.75 of the other's:
a particle's force is no longer concentrated in its host cell (0.53 measured for fFluid in the suite's
column, whose bed of three layers already spreads the unsmoothed source). Both runs must also pass
the common checks.
"""
import math, sys

import stablib


def source(case, name):
    t = stablib.write_times(case)[-1][1]
    if name == "Ksl":
        f = [(k, 0.0, 0.0) for k in stablib.read_scalar_field(case, t, name)]
    else:
        f = stablib.read_vector_field(case, t, name)
    # the column's cells are all of one size: sums over cells are sums of f V up to that factor
    total = [sum(v[k] for v in f) for k in range(3)]
    scale = sum(math.sqrt(v[0] ** 2 + v[1] ** 2 + v[2] ** 2) for v in f)
    peak = max(math.sqrt(v[0] ** 2 + v[1] ** 2 + v[2] ** 2) for v in f)
    return t, total, scale, peak


def main():
    plain, smoothed, scene = sys.argv[1:4]
    name = sys.argv[4] if len(sys.argv) > 4 else "fFluid"
    n0 = int(stablib.params(smoothed)["N_PARTICLES"])
    ok = True
    parts = []
    for case, label in ((plain, "alpha only"), (smoothed, "sources smoothed")):
        good, summary, _ = stablib.check_run(case, 0.3, n0)
        ok = ok and good
        parts.append("%s: %s" % (label, summary))
    try:
        t0, tot0, sc0, pk0 = source(plain, name)
        t1, tot1, sc1, pk1 = source(smoothed, name)
    except (OSError, ValueError, IndexError) as e:
        print("FAIL: %s: %s unreadable: %s; %s" % (scene, name, e, "; ".join(parts)))
        return 1
    diff = max(abs(a - b) for a, b in zip(tot0, tot1)) / max(sc0, 1e-300)
    parts.append("t=%s: sum %s alpha-only (%.6e %.6e %.6e), smoothed (%.6e %.6e %.6e), differ by %.1e of "
                 "sum |f|" % (t1, name, *tot0, *tot1, diff))
    parts.append("peak |%s| %.4g -> %.4g (x %.3f)" % (name, pk0, pk1, pk1 / pk0 if pk0 > 0 else float("nan")))
    if t0 != t1:
        ok = False
        parts.append("the runs ended at different times")
    if not diff <= 1e-12:
        ok = False
        parts.append("the smoothed source does not carry the same total momentum")
    if not (pk0 > 0 and pk1 < 0.75 * pk0):
        ok = False
        parts.append("the smoothed source's peak is not below 0.75 of the unsmoothed one")
    print("%s: %s: %s" % ("PASS" if ok else "FAIL", scene, ", ".join(parts)))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
