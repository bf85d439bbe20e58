#!/usr/bin/env python3
"""bench/demStep/collision.py: does the DEM step resolve a collision? Two equal spheres meet head-on
in LIGGGHTS (in.collision: Hertz, tangential history, the case's material) at several impact speeds,
with DEM steps at several fractions of the Rayleigh time (Zhang et al. 2023, eq. 20). Per run: the
restitution coefficient the contact gave (relative speed after / before), the largest overlap over
d, and the number of steps in contact. A step resolves the contact when these do not move from their
values at the finest step.

    collision.py CASE [-o CSV]      CASE: khan (0.3 mm, E 1e5 Pa, nu 0.23, e 0.1, 2000 kg/m3: the
                                    binary bed's small spheres at the validation runs' stiffness)
                                    or muller (1.2 mm, E 1e7 Pa, nu 0.33, e 0.9, 1000 kg/m3: Table II)
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = {  # E (Pa), nu, e, rho (kg/m3), d (m), relative impact speeds (m/s)
    "khan": dict(E=1e5, nu=0.23, e=0.1, rho=2000.0, d=0.3e-3, speeds=(0.01, 0.1, 1.0)),
    "muller": dict(E=1e7, nu=0.33, e=0.9, rho=1000.0, d=1.2e-3, speeds=(0.1, 1.0, 3.0)),
}
STEPS = {"khan": (1e-5, 2e-5, 4e-5), "muller": (3e-6, 6e-6, 1e-5)}  # the tutorials' DEM steps: before issue 44, then 2x, then 4x (khan) and 3.3x (muller)
FRACTIONS = (0.02, 0.05, 0.0875, 0.10, 0.15, 0.175, 0.20, 0.25, 0.30, 0.35, 0.40)
ROW = re.compile(r"^\s*\d+\s+(\S+)\s+(\S+)\s*$")


def rayleigh(c):
    return 0.5 * math.pi * c["d"] / (0.163 * c["nu"] + 0.8766) * math.sqrt(2 * c["rho"] * (1 + c["nu"]) / c["E"])


def hertz(c, v):
    """Hertz contact time of two equal spheres at relative speed v (as demTimeStepCheck.H)."""
    m = c["rho"] * math.pi / 6 * c["d"] ** 3
    estar = c["E"] / (2 * (1 - c["nu"] ** 2))
    return 2.87 * ((m / 2) ** 2 / ((c["d"] / 4) * estar ** 2 * v)) ** 0.2


def collide(lig, c, v, dt):
    x0 = 0.51 * c["d"]  # a gap of 2 % of d
    n = int(((2 * x0 - c["d"]) / v + 3 * hertz(c, v)) / dt) + 10
    args = [lig, "-echo", "none", "-log", "none", "-in", os.path.join(HERE, "in.collision")]
    for k, val in dict(E=c["E"], nu=c["nu"], e=c["e"], rho=c["rho"], d=c["d"], v=v / 2, x0=x0, dt=repr(dt), n=n).items():
        args += ["-var", k, str(val)]
    out = subprocess.run(args, capture_output=True, text=True)
    rows = [ROW.match(l) for l in out.stdout.splitlines()]
    rows = [(float(m.group(1)), float(m.group(2))) for m in rows if m]
    if out.returncode != 0 or not rows:
        sys.exit("collision.py: LIGGGHTS failed (%s)\n%s" % (" ".join(args), out.stdout[-2000:] + out.stderr[-2000:]))
    overlaps = [o for o, _ in rows]
    if overlaps[-1] > 0:
        sys.exit("collision.py: the spheres are still in contact at the end (v %g m/s, dt %g s)" % (v, dt))
    return rows[-1][1] / v, max(overlaps) / c["d"], sum(1 for o in overlaps if o > 0)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case", choices=sorted(CASES))
    ap.add_argument("-o", default=None, help="CSV to write (default: stdout)")
    a = ap.parse_args()
    lig = shutil.which("liggghts")
    if not lig:
        sys.exit("collision.py: no liggghts on PATH (source etc/bashrc)")
    c = CASES[a.case]
    tR = rayleigh(c)
    lines = ["case,E,nu,e_set,rho,d,v_rel,t_hertz,fraction_of_rayleigh,dt,e_eff,max_overlap_over_d,steps_in_contact"]
    steps = sorted([f * tR for f in FRACTIONS] + list(STEPS[a.case]))
    for v in c["speeds"]:
        for dt in steps:
            e_eff, ov, ns = collide(lig, c, v, dt)
            lines.append("%s,%g,%g,%g,%g,%g,%g,%.4e,%.4f,%.4e,%.4f,%.5f,%d" % (
                a.case, c["E"], c["nu"], c["e"], c["rho"], c["d"], v, hertz(c, v), dt / tR, dt, e_eff, ov, ns))
    text = "\n".join(lines) + "\n"
    if a.o:
        open(a.o, "w").write(text)
    sys.stdout.write(text)


if __name__ == "__main__":
    main()
