#!/usr/bin/env python3
"""Checks liftForce (forceModelCheck's output) against Saffman's (1965) lift in his own form and
Mei's (1992) correction written out here from the paper, independently of the C++ model.

    check_lift.py CHECKER       CHECKER: the forceModelCheck executable
Prints PASS/FAIL lines."""
import math
import subprocess
import sys

checker = sys.argv[1]
rho, nu = 1000.0, 1e-6
mu = rho * nu


def run(particles):
    """forces and standard error of forceModelCheck liftForce on particles (d, vol, v, U, w)"""
    text = "\n".join(" ".join(f"{x:.17g}" for x in (p[0], p[1], *p[2], *p[3], *p[4])) for p in particles)
    r = subprocess.run([checker, "liftForce", "-rho", str(rho), "-nu", str(nu)], input=text + "\n",
                       capture_output=True, text=True)
    if r.returncode != 0:
        print(f"FAIL: forceModelCheck liftForce exited {r.returncode}: {r.stderr.strip()[-400:]}")
        sys.exit(1)
    # the forces are the lines of three numbers; OpenFOAM prints its warnings on standard output too
    forces = []
    for l in r.stdout.split("\n"):
        try:
            f = tuple(map(float, l.split()))
        except ValueError:
            continue
        if len(f) == 3:
            forces.append(f)
    return forces, r.stderr + r.stdout


def shear_particle(d, Rep, beta, n_real=1):
    """a sphere lagging a simple shear u = G y e_x by V = Rep nu/d at its centre, G from beta"""
    V = Rep * nu / d
    G = 2 * beta * Rep * nu / d**2           # beta = Re_s/(2 Re_p), Re_s = G d^2/nu
    vol = n_real * math.pi / 6 * d**3
    return (d, vol, (0.0, 0.0, 0.0), (V, 0.0, 0.0), (0.0, 0.0, -G)), V, G   # curl(G y e_x) = -G e_z


def saffman(d, V, G):
    """Saffman's lift, his form: 6.46 mu a^2 V (G/nu)^1/2 (a = d/2), towards the faster fluid"""
    return 6.46 * mu * (d / 2)**2 * V * math.sqrt(G / nu)


def mei(Rep, beta):
    """Mei (1992): the lift over Saffman's"""
    if Rep <= 40:
        return (1 - 0.3314 * math.sqrt(beta)) * math.exp(-0.1 * Rep) + 0.3314 * math.sqrt(beta)
    return 0.0524 * math.sqrt(beta * Rep)


ok = True
def check(cond, msg):
    global ok
    print(("PASS: " if cond else "FAIL: ") + msg)
    ok = ok and cond


d = 1e-3
# 1. Saffman's creeping-flow limit (Re_p -> 0, Re_s^1/2 >> Re_p): the force is Saffman's, sideways
p, V, G = shear_particle(d, 1e-3, 0.2)
(f, _), err = run([p, p])
fs = saffman(d, V, G)
check(abs(f[1] / fs - 1) < 2e-3 and abs(f[0]) < 1e-12 * fs and abs(f[2]) < 1e-12 * fs,
      f"Saffman's limit (Re_p 1e-3, beta 0.2): F_y = {f[1]:.6g} N against 6.46 mu a^2 V (G/nu)^1/2 = {fs:.6g} N "
      f"(ratio {f[1] / fs:.5f}; Mei's factor there {mei(1e-3, 0.2):.5f})")
check(err.count("0.1 <= Re_p <= 100 (Mei 1992)") == 1,
      "two particles at Re_p = 1e-3: one warning, naming Mei's range 0.1 <= Re_p <= 100")
# 2. Mei's correction over its range, both branches and the branch point
# (just inside the range's ends, where rounding would put the computed Re_p or beta outside)
points = [(Rep, beta) for Rep in (0.11, 0.5, 2, 5, 10, 20, 40, 41, 60, 99) for beta in (0.0051, 0.02, 0.1, 0.39)]
parts = [shear_particle(d, Rep, beta)[0] for Rep, beta in points]
forces, err = run(parts)
worst = 0.0
for (Rep, beta), p, f in zip(points, parts, forces):
    V, G = p[3][0], -p[4][2]
    worst = max(worst, abs(f[1] / (saffman(d, V, G) * mei(Rep, beta)) - 1))
check(worst < 2e-3, f"Mei's correction at {len(points)} points, 0.1 <= Re_p <= 100, 0.005 <= beta <= 0.4: "
      f"largest relative difference {worst:.2e} (Saffman's 1.615 against 6.46/4 = 1.615 exactly)")
check("Warning" not in err, "no range warning inside Mei's range")
r = [f[1] / saffman(d, p[3][0], -p[4][2]) for p, f in zip(parts, forces)]
i40, i41 = points.index((40, 0.1)), points.index((41, 0.1))
check(0.3 < r[i41] / r[i40] < 1.2 and r[points.index((0.11, 0.1))] > r[points.index((10, 0.1))] > r[i40],
      f"the lift ratio falls with Re_p at beta 0.1: {r[points.index((0.11, 0.1))]:.3f} (Re_p 0.11), "
      f"{r[points.index((10, 0.1))]:.3f} (10), {r[i40]:.3f} (40), {r[i41]:.3f} (41)")
# 3. direction and linearity: a particle leading the fluid is pushed the other way; a parcel of 8
#    real particles gets 8 times the force; no slip or no shear, no lift
p, V, G = shear_particle(d, 5, 0.1)
lead = (d, p[1], (2 * V, 0.0, 0.0), (V, 0.0, 0.0), p[4])
parcel = shear_particle(d, 5, 0.1, n_real=8)[0]
still = (d, p[1], (V, 0.0, 0.0), (V, 0.0, 0.0), p[4])
noshear = (d, p[1], (0.0, 0.0, 0.0), (V, 0.0, 0.0), (0.0, 0.0, 0.0))
(fl, fa, fp, f0, f1), err = run([p, lead, parcel, still, noshear])
check(fl[1] > 0 and abs(fa[1] + fl[1]) < 1e-9 * fl[1],
      f"a lagging sphere is lifted towards the faster fluid (+y, {fl[1]:.4g} N), a leading one the other way ({fa[1]:.4g} N)")
check(abs(fp[1] / fl[1] - 8) < 1e-9, f"a parcel of 8 real spheres gets 8 times the force ({fp[1] / fl[1]:.9f})")
check(f0 == (0.0, 0.0, 0.0) and f1 == (0.0, 0.0, 0.0), "no slip or no shear: no lift")
sys.exit(0 if ok else 1)
