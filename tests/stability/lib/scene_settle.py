#!/usr/bin/python3
"""scene_settle.py -- one particle released from rest: its velocity against the ODE of the drag law.

    scene_settle.py <case> <scene> --tol T [--explicit-case C]

    m dv/dt = -(rho_p - rho_f) V g - K(|v|) v,  K = Di Felice at alpha = 1 (as tutorials/settlingTest):
    K = pi/8 rho_f d^2 (0.63 sqrt|v| + 4.8 sqrt(nu/d))^2 (no added mass: the case has no virtualMassForce).

Measures the particle's vertical velocity in the LIGGGHTS dumps against the ODE (RK4) at the same
times: the largest deviation over the run relative to the ODE's final speed, and the final velocity
relative to the ODE's. PASS: the common run checks and the final relative error <= tol, the
history deviation <= --tol-history (default 2 tol).
With --stiff: the scene is "particle response time far below the CFD step": reports for the case (and
the --explicit-case) whether the particle stayed, blew up or was lost, and its final velocity against
the terminal velocity; PASS only if the case stays within tol of the ODE (i.e. stable and accurate).
"""
import argparse, sys

import stablib  # this folder's (a script's own folder is on its path)
from stablib import ode


def history(case):
    p = stablib.params(case)
    dt = float(p["DEM_TIMESTEP"])
    d = stablib.dumps(case)
    t, vz = [], []
    for s, rows in d.items():
        if rows:
            r = next(iter(rows.values()))
            t.append(s * dt)
            vz.append(r[5])
    return p, t, vz


def assess(case, tol, tol_hist):
    p, t, vz = history(case)
    ok, summary, m = stablib.check_run(case, float(p.get("ALPHA_MIN", 0.3)), int(p["N_PARTICLES"]))
    ref, vt, tau = ode(p, t) if t else ([], float("nan"), float("nan"))
    ci = int(p["COUPLING_INTERVAL"])
    dt_cfd = ci * float(p["DEM_TIMESTEP"])
    res = dict(ok=ok, summary=summary, vt=vt, tau=tau, dt_cfd=dt_cfd, t=t, vz=vz)
    lost = m.get("particles") and min(m["particles"]) == 0
    if not t or m["rc"] != 0 or lost:
        res["state"] = "lost" if lost else "stopped"
        res["ok"] = False
        vmax = max((abs(v) for v in vz), default=float("nan"))
        res["desc"] = "%s (max |v| %.3g m/s = %.3g v_t before)" % (
            "particle LOST from the DEM box" if lost else "run stopped", vmax, vmax / abs(vt))
        return res
    dev = max(abs(a - b) for a, b in zip(vz, ref)) / abs(ref[-1])
    fin = abs(vz[-1] - ref[-1]) / abs(ref[-1])
    res["dev"], res["fin"] = dev, fin
    res["state"] = "stable"
    res["desc"] = "v_z(end) %.5g m/s vs ODE %.5g m/s (err %.2f %%), history max dev %.2f %% (v_t %.4g m/s)" % (
        vz[-1], ref[-1], 100 * fin, 100 * dev, vt)
    res["ok"] = ok and fin <= tol and dev <= tol_hist
    return res


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case")
    ap.add_argument("scene")
    ap.add_argument("--tol", type=float, required=True, help="final velocity, relative to the ODE's")
    ap.add_argument("--tol-history", type=float, help="largest deviation over the run / final speed (default 2 tol)")
    ap.add_argument("--explicit-case")
    ap.add_argument("--particle-side-warning", choices=("yes", "no"),
                    help="assert that the solver warns (or not) about the particle-side explicit range")
    ap.add_argument("--explicit-warning", choices=("yes", "no"),
                    help="the same for the --explicit-case run")
    a = ap.parse_args()
    th = a.tol_history if a.tol_history is not None else 2 * a.tol
    r = assess(a.case, a.tol, th)
    line = "dt_CFD/tau_p %.3g (tau_p %.3g s at v_t), %s" % (r["dt_cfd"] / r["tau"], r["tau"], r["desc"])
    if a.explicit_case:
        re_ = assess(a.explicit_case, a.tol, th)
        line = "implicit: " + line + "; explicit: " + re_["desc"]
    for case, want, label in ((a.case, a.particle_side_warning, "implicit run, particle side:"),
                              (a.explicit_case, a.explicit_warning, "explicit run, particle side:")):
        if case and want:
            w_ok, desc = stablib.check_warning(case, stablib.PARTICLE_SIDE_WARNING, want == "yes", label)
            r["ok"] = r["ok"] and w_ok
            line += "; " + desc
    line += "; " + r["summary"]
    print("%s: %s: %s" % ("PASS" if r["ok"] else "FAIL", a.scene, line))
    return 0 if r["ok"] else 1


if __name__ == "__main__":
    sys.exit(main())
