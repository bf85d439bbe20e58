#!/usr/bin/python3
"""scene_contact.py -- stiff contact (E = 1e9 Pa): the DEM time-step check and binary collisions.

    scene_contact.py times E nu rho d v          print t_R, t_H (the reference formulas, for the runner)
    scene_contact.py dtcheck <case> <scene> <quiet|warn|fatal|skip>
        <case>/log.dt is the output of dtCheckTest (checkDemTimestep on the case's DEM script and
        couplingProperties). PASS if (a) the printed estimate equals this script's independent
        t_R and t_H to 1e-5, (b) the outcome is the expected one: no warning / a warning naming
        demTimeStepWarnFraction / a FatalIOError naming the couplingProperties file,
        demTimeStepMaxFraction and demTimeStepForce (and the run stopped with a non-zero status).
        "skip": no particles in the DEM yet: a warning that the step was not checked, exit 0.
    scene_contact.py collision <dir> <scene> <E> <dt> <ok|refused> [<dtcheck outcome>]
        <dir>/post/collision.txt from in.collision (two spheres head on at 1 m/s). Measures the
        restitution coefficient (set 0.9), the contact duration against t_H and the largest overlap
        against Hertz's (elastic) maximum compression. "ok": PASS if e within 0.02 of 0.9, duration
        within 10 % of t_H and overlap within 10 % of Hertz. "refused": the time step is one the check
        refuses; PASS if the dtcheck outcome given is "fatal" (the measured e shows why).
Formulas (see src/openfoam/coupling/demTimeStepCheck.H):
    t_R = 0.5 pi d / (0.163 nu + 0.8766) sqrt(2 rho (1 + nu) / E)      (Zhang et al. 2023, eq. 20)
    t_H = 2.87 (m*^2 / (R* E*^2 v))^(1/5), m* = m/2, R* = r/2, E* = E / (2 (1 - nu^2))   (Johnson 1985)
    a_max = (15 m* v^2 / (16 E* R*^0.5))^(2/5)                             (Hertz maximum compression)
"""
import math, os, re, sys


def times(E, nu, rho, d, v):
    r = d / 2
    tR = 0.5 * math.pi * d / (0.163 * nu + 0.8766) * math.sqrt(2 * rho * (1 + nu) / E)
    m = rho * math.pi / 6 * d ** 3
    ms, Rs, Es = m / 2, r / 2, E / (2 * (1 - nu * nu))
    tH = 2.87 * (ms * ms / (Rs * Es * Es * v)) ** 0.2
    amax = (15 * ms * v * v / (16 * Es * math.sqrt(Rs))) ** 0.4
    return tR, tH, amax


def dtcheck(case, scene, expect):
    log = open(os.path.join(case, "log.dt"), errors="replace").read()
    rc = int(open(os.path.join(case, "rc.dt")).read())
    m = re.search(r"ESTIMATE (\S+) (\S+) (\S+) (\S+) (\S+) (\S+) (\S+) (\S+) (\S+) valid (\d)", log)
    problems = []
    if not m:
        print("FAIL: %s: no ESTIMATE line from dtCheckTest (exit %d): %s" % (scene, rc, log.strip()[-300:]))
        return 1
    dt, tR, tH, v, n, rmin, rhomin, rhomax, Emax = (float(x) for x in m.groups()[:9])
    valid = m.group(10) == "1"
    if expect == "skip":
        # no particles (or no materials): a warning that the step was not checked, no stop
        got = "skip" if (not valid and "not checked against the Rayleigh and Hertz times" in log) else \
            ("fatal" if "FOAM FATAL" in log else "other")
        reason = re.search(r"Hertz times: (.*)", log)
        ok = got == "skip" and rc == 0
        print("%s: %s: %d particles -> %s (expected skip, exit %d): %s" % ("PASS" if ok else "FAIL", scene, n, got, rc,
                                                                      reason.group(1).strip() if reason else log[-200:]))
        return 0 if ok else 1
    params = dict(l.rstrip("\n").split("=", 1) for l in open(os.path.join(case, "case.params")) if "=" in l)
    E, rho, d = float(params["YOUNGS_MODULUS"]), float(params["RHO_P"]), float(params["D_MM"]) * 1e-3
    tR_ref, tH_ref, _ = times(E, 0.3, rho, d, float(params["DEM_MAX_IMPACT_VELOCITY"]))
    eR, eH = abs(tR - tR_ref) / tR_ref, abs(tH - tH_ref) / tH_ref
    if eR > 1e-5 or eH > 1e-5:
        problems.append("estimate differs from the reference: t_R %.6g vs %.6g, t_H %.6g vs %.6g" % (tR, tR_ref, tH, tH_ref))
    warned = "FOAM Warning" in log and "demTimeStepWarnFraction" in log
    fatal = "FOAM FATAL IO ERROR" in log
    got = "fatal" if fatal else ("warn" if warned else "quiet")
    if got != expect:
        problems.append("outcome %s, expected %s" % (got, expect))
    if expect == "fatal":
        text = log[log.find("FOAM FATAL IO ERROR"):]
        for word in ("constant/couplingProperties", "demTimeStepMaxFraction", "demTimeStepForce"):
            if word not in text:
                problems.append("the error does not name %s" % word)
        if rc == 0:
            problems.append("exit status 0 after the fatal error")
    elif rc != 0:
        problems.append("exit status %d" % rc)
    frac = dt / min(tR, tH)
    print("%s: %s: dt %.3g s = %.3f x min(t_R %.4g s, t_H %.4g s at %.3g m/s) -> %s (expected %s); estimate vs "
          "reference rel. err %.1e/%.1e%s" % ("FAIL" if problems else "PASS", scene, dt, frac, tR, tH, v, got, expect,
                                             eR, eH, ("; " + "; ".join(problems)) if problems else ""))
    return 1 if problems else 0


def collision(d, scene, E, dt, mode, outcome=None):
    rows = []
    for line in open(os.path.join(d, "post", "collision.txt")):
        if line.startswith("#") or not line.strip():
            continue
        s, dist, v1, v2 = line.split()[:4]
        rows.append((int(s), float(dist), float(v1), float(v2)))
    dia, rho, nu = 2e-3, 2500.0, 0.3
    v_in = rows[0][2] - rows[0][3]
    v_out = rows[-1][3] - rows[-1][2]
    e = v_out / v_in
    contact = [r for r in rows if r[1] < dia]
    dur = len(contact) * dt
    overlap = dia - min(r[1] for r in rows)
    tR, tH, amax = times(E, nu, rho, dia, v_in)
    frac = dt / min(tR, tH)
    meas = "dt = %.3g x min(t_R, t_H): restitution %.4f (set 0.9), contact %d steps = %.3g s vs t_H %.3g s, " \
           "max overlap %.3g m vs Hertz %.3g m" % (frac, e, len(contact), dur, tH, overlap, amax)
    if mode == "ok":
        ok = abs(e - 0.9) <= 0.02 and abs(dur - tH) <= 0.1 * tH and abs(overlap - amax) <= 0.1 * amax
    else:
        ok = outcome == "fatal"
        meas += "; the time-step check %s this step" % ("refuses" if ok else "does NOT refuse (%s)" % outcome)
    print("%s: %s: %s" % ("PASS" if ok else "FAIL", scene, meas))
    return 0 if ok else 1


def main():
    a = sys.argv[1:]
    if a[0] == "times":
        tR, tH, _ = times(*(float(x) for x in a[1:6]))
        print("%.10g %.10g" % (tR, tH))
        return 0
    if a[0] == "dtcheck":
        return dtcheck(a[1], a[2], a[3])
    if a[0] == "collision":
        return collision(a[1], a[2], float(a[3]), float(a[4]), a[5], a[6] if len(a) > 6 else None)
    sys.exit(__doc__)


if __name__ == "__main__":
    sys.exit(main())
