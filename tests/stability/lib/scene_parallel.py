#!/usr/bin/python3
"""scene_parallel.py -- np = 2 against serial, the processor boundary at x = width/2.

    scene_parallel.py first-step <serial case> <np2 case> <scene>
        One CFD step from the same particles (they move ~1e-8 m): the difference of alpha_f is the
        difference of the kernels at the processor boundary (currently normalised per rank).
        PASS/FAIL on the np = 2 run's own checks (conservation, count, alpha bounds); the serial vs
        np = 2 difference is measured and printed, not asserted.
    scene_parallel.py run <serial case> <np2 case> <scene>
        A fluidized run: the np = 2 run's checks, particles straddling the boundary at the start and
        the number that crossed it during the run (must be > 0: the scene is about crossing), and
        the serial vs np = 2 differences at the end (measured, not asserted). With a force that
        needs dv/dt (virtual mass) every particle must find its velocity of the last coupling after
        the first, also one that changed rank ("dv/dt unknown ... 0 since" at the end).
    scene_parallel.py same-alpha <serial case> <np2 case> <scene>
        As first-step, and the serial and np = 2 alpha_f must agree to 1e-9 (diffusion smoothing
        across the processor boundary: the ranks solve the serial system, to the CG tolerance).
    scene_parallel.py limited <serial case> <np2 case> <scene>
        As same-alpha (where excess volume must cross the processor boundary as it crosses any face),
        and the packing limiter must have engaged in both runs: the same moved volume (as printed)
        in the same number of cells (both taken before its sweeps: they show it engaged, not how).
    scene_parallel.py refused - <np2 case> <scene> [message]
        The np = 2 run must stop with the message (default: the decomposition mismatch).
"""
import math, os, sys

import stablib


DECOMPOSITION_MISMATCH = "must split the domain at the same planes"
SAME_ALPHA_TOL = 1e-9


def refused(par, scene, cause=DECOMPOSITION_MISMATCH):
    """The np = 2 run must stop at once, naming the cause (by default: DEM and CFD split the domain
    differently)."""
    rc = stablib.exit_status(par)
    said = stablib.log_has(par, cause)
    ok = rc != 0 and said
    print("%s: %s: np=2 exit status %d, %s" % ("PASS" if ok else "FAIL", scene, rc,
          ("stopped saying '%s'" % cause) if said else ("no message '%s': " % cause)
          + stablib.failure_reason(par)))
    return 0 if ok else 1


def crossings(d, x0):
    """How many particles were seen on both sides of the plane x = x0 in the dumps d."""
    steps = list(d)
    crossed = 0
    for pid in (d[steps[0]] if steps else {}):
        sides = set()
        for s in steps:
            r = d[s].get(pid)
            if r is not None and abs(r[0] - x0) > 1e-12:
                sides.add(r[0] > x0)
        crossed += len(sides) == 2
    return crossed


def main():
    mode, serial, par, scene = sys.argv[1:5]
    if mode == "refused":
        return refused(par, scene, *sys.argv[5:6])
    p = stablib.params(par)
    n0 = int(p["N_PARTICLES"])
    W = float(p["WIDTH_MM"]) * 1e-3
    ok_s, sum_s, m_s = stablib.check_run(serial, 0.3, n0)
    ok_p, sum_p, m_p = stablib.check_run(par, 0.3, n0)
    ok = ok_p
    parts = ["np=2: " + sum_p]
    if not ok_s:
        parts.append("(serial reference failed: %s)" % sum_s)
    t_s, t_p = stablib.write_times(serial), stablib.write_times(par)
    if t_s and t_p and t_s[-1][1] == t_p[-1][1] and t_s[-1][0] > 0:
        t = t_s[-1][1]
        a_s = stablib.read_scalar_field(serial, t, "alpha")
        # np = 2 fields are per processor: compare in serial cell order after reconstructPar
        a_p = reconstructed(par, t, "alpha")
        diff = None
        if a_p is not None and len(a_p) == len(a_s):
            diff = max(abs(x - y) for x, y in zip(a_s, a_p))
            parts.append("serial vs np=2 at t=%s: max |d alpha_f| %.2e" % (t, diff))
        if mode in ("same-alpha", "limited") and not (diff is not None and diff <= SAME_ALPHA_TOL):
            ok = False
            parts.append("alpha_f differs from serial by more than %g" % SAME_ALPHA_TOL)
        cl_s, cl_p = stablib.coupling_lines(serial), stablib.coupling_lines(par)
        if cl_s and cl_p:
            parts.append("solid volume in cells serial %.12e np=2 %.12e" % (cl_s[-1]["vc"], cl_p[-1]["vc"]))
            if mode == "limited":
                ms, mp = cl_s[-1]["moved"], cl_p[-1]["moved"]
                parts.append("limiter moved serial %.12e m3 in %d cells, np=2 %.12e m3 in %d cells"
                             % (ms, cl_s[-1]["ncells"], mp, cl_p[-1]["ncells"]))
                if not (ms > 0 and abs(ms - mp) <= 1e-12 * ms and cl_s[-1]["ncells"] == cl_p[-1]["ncells"]):
                    ok = False
                    parts.append("the limiter did not act the same in serial and np=2")
        elif mode == "limited":
            ok = False
            parts.append("no coupling report line to read the limiter's work from")
    d = stablib.dumps(par)
    if d:
        steps = list(d)
        first = d[steps[0]]
        straddle = sum(1 for r in first.values() if abs(r[0] - W / 2) < r[6])
        parts.append("%d particles straddle x = %.4g m at the start" % (straddle, W / 2))
        if mode in ("first-step", "same-alpha", "limited") and straddle == 0:
            ok = False
            parts.append("no particle straddles the processor boundary")
        if mode == "run":
            crossed = crossings(d, W / 2)
            parts.append("%d particles crossed it during the run" % crossed)
            unknown = stablib.dvdt_unknown(par)
            if unknown is not None:
                parts.append("dv/dt unknown for %d particles at the first coupling, %d since" % unknown)
                if unknown[1] != 0:
                    ok = False
                    parts.append("particles lost their velocity of the last coupling")
            if crossed == 0:
                ok = False
                parts.append("no particle crossed the processor boundary")
            ds = stablib.dumps(serial)
            if ds:
                last = steps[-1]
                if last in ds:
                    dx = max(math.sqrt(sum((a - b) ** 2 for a, b in zip(d[last][i][:3], ds[last][i][:3])))
                             for i in d[last] if i in ds[last])
                    parts.append("max particle position difference at the end %.2e m" % dx)
    print("%s: %s: %s" % ("PASS" if ok else "FAIL", scene, ", ".join(parts)))
    return 0 if ok else 1


def reconstructed(case, t, name):
    """alpha of an np = 2 run in serial cell order: run reconstructPar if needed."""
    import subprocess
    if not os.path.exists(os.path.join(case, t, name)):
        subprocess.run(["reconstructPar", "-case", case, "-time", t, "-fields", "(" + name + ")"],
                       stdout=open(os.path.join(case, "log.reconstructPar"), "w"), stderr=subprocess.STDOUT)
    if not os.path.exists(os.path.join(case, t, name)):
        return None
    try:
        return stablib.foam_fields.read_internal_field(os.path.join(case, t, name)).tolist()
    except stablib.foam_fields.FieldFormatError:  # uniform: not a reconstructed field to compare
        return None


if __name__ == "__main__":
    sys.exit(main())
