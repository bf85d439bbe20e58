#!/usr/bin/python3
"""scene_drag.py -- stiff drag, fluid side: a dense suspension of small heavy particles settling.

    scene_drag.py <implicit case> <explicit case> <scene> [--reference <case>]

The CFD step is below the particle response time (the particle update, explicit over the coupling
interval, is stable) but the fluid-side drag coefficient is large: dt Ksl / alpha_f = (dt/tau_p) x
alpha_p rho_p / (alpha_f rho_f) >> 2, beyond the stable range of an explicit drag source.
Measures for both runs how far they got (CFD steps, blow-up), the largest Courant number and the
largest particle speed; with --reference (the implicit run with a 10x smaller CFD step) the mean
particle displacement at the end against the reference.
PASS: the implicit run completes with the common checks (conservation, count, alpha bounds, no NaN),
its largest Courant number stays below 0.5, its particles stay below 5 x the isolated terminal speed,
and (with a reference) its mean displacement is within 10 % of the reference's. The explicit run is
measured, not asserted.
"""
import argparse, math, sys

import stablib


def mean_z(rows):
    return sum(r[2] for r in rows.values()) / max(1, len(rows))


def describe(case):
    p = stablib.params(case)
    steps, co = stablib.progress(case)
    n_total = int(round(float(p["END_TIME"]) / (int(p["COUPLING_INTERVAL"]) * float(p["DEM_TIMESTEP"]))))
    d = stablib.dumps(case)
    vmax = max((math.sqrt(r[3] ** 2 + r[4] ** 2 + r[5] ** 2) for rows in d.values() for r in rows.values()),
               default=float("nan"))
    rc = stablib.exit_status(case)
    state = "completed %d CFD steps" % steps if rc == 0 else "BLEW UP at CFD step %d of %d (exit %d)" % (steps, n_total, rc)
    return dict(p=p, steps=steps, co=co, d=d, vmax=vmax, rc=rc,
                desc="%s, max Co %.3g, max particle speed %.3g m/s" % (state, max(co) if co else float("nan"), vmax))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("implicit")
    ap.add_argument("explicit")
    ap.add_argument("scene")
    ap.add_argument("--reference")
    a = ap.parse_args()
    im, ex = describe(a.implicit), describe(a.explicit)
    p = im["p"]
    _, vt, tau = stablib.ode(p, [0.0])
    dt = int(p["COUPLING_INTERVAL"]) * float(p["DEM_TIMESTEP"])
    ok, summary, m = stablib.check_run(a.implicit, float(p.get("ALPHA_MIN", 0.3)), int(p["N_PARTICLES"]))
    parts = ["dt_CFD %.3g s = %.2f tau_p (isolated, v_t %.3g m/s)" % (dt, dt / tau, abs(vt)),
             "implicitDrag true: " + im["desc"], "implicitDrag false: " + ex["desc"]]
    if im["co"] and not max(im["co"]) < 0.5:
        ok = False
        parts.append("implicit max Co >= 0.5")
    if not im["vmax"] < 5 * abs(vt):
        ok = False
        parts.append("implicit particle speed above 5 v_t")
    if a.reference and im["d"]:
        ref = describe(a.reference)
        last = max(im["d"])
        t_end = last * float(p["DEM_TIMESTEP"])
        pr = ref["p"]
        match = [s for s in ref["d"] if abs(s * float(pr["DEM_TIMESTEP"]) - t_end) < 1e-9]
        if match and ref["rc"] == 0:
            dz = mean_z(im["d"][last]) - mean_z(im["d"][min(im["d"])])
            dzr = mean_z(ref["d"][match[0]]) - mean_z(ref["d"][min(ref["d"])])
            rel = abs(dz - dzr) / abs(dzr)
            parts.append("mean displacement %.4g mm vs %.4g mm with a 10x smaller CFD step (%.1f %%)" %
                         (1e3 * dz, 1e3 * dzr, 100 * rel))
            if rel > 0.1:
                ok = False
        else:
            ok = False
            parts.append("reference run unusable: " + ref["desc"])
    # the solver must say when explicit fluid drag is beyond its range, and only then
    for case, expected, label in ((a.implicit, False, "implicit run:"), (a.explicit, True, "explicit run:")):
        w_ok, desc = stablib.check_warning(case, stablib.FLUID_SIDE_WARNING, expected, label)
        ok = ok and w_ok
        parts.append(desc + " (fluid side)")
    parts.append(summary)
    print("%s: %s: %s" % ("PASS" if ok else "FAIL", a.scene, "; ".join(parts)))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
