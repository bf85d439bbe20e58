#!/usr/bin/python3
"""ErgunTest: pressure drop across the middle of the fixed bed against the Ergun equation,
    dp/dz = 150 mu (1-eps)^2 U / (eps^3 d^2) + 1.75 rho (1-eps) U^2 / (eps^3 d),
with U the superficial velocity, the measured drop taken net of the fluid's hydrostatic part
rho g L (p includes it: the fluid equation carries alpha g), and eps the mean fluid fraction of the cells between the two
measuring planes (z = 15.95 and 28.05 mm, cell centres, 4 mm inside the bed's ends so that the
kernel's smoothing of the bed edges stays out). The means are plain means over cells, which are
volume-weighted means only because this mesh's cells are all equal: on a graded or curved mesh weight
by cell volume (tutorials/packedBedCylinder/compare.py does). Appends a row to results/summary.csv
(modelType, np, U, eps, dp_Pa, dp_ergun_Pa, relative_error = dp/Ergun - 1, wall_time_s).
Usage: compare.py <time dir> <U> <wall seconds> [model type, default A] [ranks, default 1]
"""
import os, sys

# the project's reader of written fields: etc/python (COARSEDEM_DIR: this file may run from a copy of the tutorial)
TOP = os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(TOP, "etc", "python"))
from foam_fields import FieldFormatError, read_internal_field  # noqa: E402
from ergun import ergun_gradient  # noqa: E402

tdir, U, wall = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
model = sys.argv[4] if len(sys.argv) > 4 else "A"
nranks = int(sys.argv[5]) if len(sys.argv) > 5 else 1
rho, nu, d = 1.2, 1.5e-5, 1e-3
mu = rho * nu
nx, ny, nz, dz = 10, 10, 50, 1.1e-3

def read_scalar(path):
    try:
        return read_internal_field(path, nx * ny * nz)
    except FieldFormatError as e:
        sys.exit(f"compare.py: {e}")

p = read_scalar(os.path.join(tdir, "p"))
alpha = read_scalar(os.path.join(tdir, "alpha"))
def layer_mean(f, k):
    return sum(f[k * nx * ny:(k + 1) * nx * ny]) / (nx * ny)
k1, k2 = 14, 25                       # cell centres at 15.95 mm and 28.05 mm
L = (k2 - k1) * dz
g = 9.81
dp = rho * (layer_mean(p, k1) - layer_mean(p, k2)) - rho * g * L   # p is kinematic
eps = sum(layer_mean(alpha, k) for k in range(k1, k2 + 1)) / (k2 - k1 + 1)
ergun = ergun_gradient(eps, U, d, mu, rho) * L
err = (dp - ergun) / ergun
os.makedirs("results", exist_ok=True)
new = not os.path.exists("results/summary.csv")
with open("results/summary.csv", "a") as f:
    if new:
        f.write("modelType,np,U,eps,dp_Pa,dp_ergun_Pa,relative_error,wall_time_s\n")
    f.write(f"{model},{nranks},{U:g},{eps:.4f},{dp:.6g},{ergun:.6g},{err:.3e},{wall:.1f}\n")
ok = abs(err) <= 0.05
print(("PASS: " if ok else "FAIL: ") + f"ErgunTest{'' if model == 'A' else '/model' + model}/U={U:g}: dp {dp:.4g} Pa, Ergun {ergun:.4g} Pa (eps {eps:.4f}), error {100*err:+.2f} % (limit 5 %)")
sys.exit(0 if ok else 1)
