#!/usr/bin/python3
"""packedBedCylinder: pressure drop across the middle of the fixed bed against the Ergun equation,
    dp/dz = 150 mu (1-eps)^2 U / (eps^3 d^2) + 1.75 rho (1-eps) U^2 / (eps^3 d),
with U the superficial velocity, the measured drop net of the fluid's hydrostatic part rho g L (p
includes it: the fluid equation carries alpha g), between the cell layers centred at z = 21 and
67 mm (9 mm inside the bed's ends, beyond any kernel's reach). Cross-section means and eps are
weighted by cell volume (the O-grid's cells differ in size: a plain mean over cells would weight
the core's small cells more). Also reports eps in the ring of cells next to the wall against the
core, the wall's effect on the measured field. Appends to results/summary.csv.
Usage: compare.py <time dir> <U> <method> <np> <wall seconds>
"""
import os, sys

# the project's reader of written fields: etc/python (COARSEDEM_DIR: this file may run from a copy of the tutorial)
TOP = os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(TOP, "etc", "python"))
from foam_fields import FieldFormatError, read_internal_field  # noqa: E402
from ergun import ergun_gradient  # noqa: E402

tdir, U, method, np_, wall = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4], float(sys.argv[5])
rho, nu, d, g = 1.2, 1.5e-5, 2e-3, 9.81
mu = rho * nu
z1, z2 = 0.021, 0.067
R_wall_ring = 0.0096           # cells centred beyond this radius: the ring next to the 11 mm wall

def internal(path):
    try:
        return read_internal_field(path).tolist()
    except FieldFormatError as e:
        raise SystemExit(f"compare.py: {e}")

V = internal("0/V")
C = internal("0/C")
p = internal(os.path.join(tdir, "p"))
alpha = internal(os.path.join(tdir, "alpha"))

def layer_mean(f, z):
    cells = [i for i, c in enumerate(C) if abs(c[2] - z) < 1e-7]
    return sum(f[i] * V[i] for i in cells) / sum(V[i] for i in cells)

def mean_over(cells):
    return sum(alpha[i] * V[i] for i in cells) / sum(V[i] for i in cells)

slab = [i for i, c in enumerate(C) if z1 - 1e-7 <= c[2] <= z2 + 1e-7]
ring = [i for i in slab if (C[i][0] ** 2 + C[i][1] ** 2) ** 0.5 > R_wall_ring]
core = [i for i in slab if (C[i][0] ** 2 + C[i][1] ** 2) ** 0.5 <= R_wall_ring]
L = z2 - z1
dp = rho * (layer_mean(p, z1) - layer_mean(p, z2)) - rho * g * L     # p is kinematic
eps = mean_over(slab)
ergun = ergun_gradient(eps, U, d, mu, rho) * L
err = (dp - ergun) / ergun
os.makedirs("results", exist_ok=True)
new = not os.path.exists("results/summary.csv")
with open("results/summary.csv", "a") as f:
    if new:
        f.write("method,np,U,eps,eps_wall_ring,eps_core,dp_Pa,dp_ergun_Pa,relative_error,wall_time_s\n")
    f.write(f"{method},{np_},{U:g},{eps:.5f},{mean_over(ring):.5f},{mean_over(core):.5f},{dp:.6g},{ergun:.6g},{err:.3e},{wall:.1f}\n")
ok = abs(err) <= 0.05
print(("PASS: " if ok else "FAIL: ") + f"packedBedCylinder/{method}/np{np_}/U={U:g}: dp {dp:.4g} Pa, Ergun {ergun:.4g} Pa "
      f"(eps {eps:.4f}; wall ring {mean_over(ring):.4f}, core {mean_over(core):.4f}), error {100*err:+.2f} % (limit 5 %)")
sys.exit(0 if ok else 1)
