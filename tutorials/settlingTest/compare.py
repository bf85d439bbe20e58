#!/usr/bin/python3
"""settlingTest: compare the DEM particle's velocity history with the analytic ODE of the drag law.

    m dv/dt = -(rho_p - rho_f) V g + K(|v|) (-v)     (v < 0 downwards; buoyancy from grad p / Archimedes)

K is the Di Felice drag coefficient at alpha = 1 (Zhang et al. 2023, eqs. A4-A7), the fluid at rest.
Writes results/summary.csv (quantity, measured, reference, relative error, wall time) and
results/velocity.csv; prints PASS/FAIL for the terminal velocity within 1 %. With -coarse (a sphere
twice as large as its cells, Allrun -coarse): within 3 %, and the velocity smooth across the faces:
over the second half of the free fall (the sphere crossing about 35 cell faces) its largest
deviation from its mean below 0.5 % of v_t (a sphere that samples its own disturbance at each face
jumps there).
Usage: compare.py <case dir> <wall seconds> [A|B] [-coarse]
"""
import os, sys

# the project's Python library, etc/python (COARSEDEM_DIR: this file may run from a copy of the tutorial)
sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."), "etc", "python"))
from settling_ode import settling

case = sys.argv[1] if len(sys.argv) > 1 else "."
wall = float(sys.argv[2]) if len(sys.argv) > 2 else float("nan")
model = sys.argv[3] if len(sys.argv) > 3 else "A"
coarse = "-coarse" in sys.argv[4:]
d, rho_p, rho_f, nu = 2e-3, 2500.0, 1000.0, 1e-6
rows = []
with open(os.path.join(case, "post", "particle.txt")) as f:
    for line in f:
        if line.startswith("#") or not line.strip():
            continue
        t, z, vz = map(float, line.split()[:3])
        rows.append((t, z, vz))
if not rows:
    sys.exit("compare.py: no particle history in post/particle.txt")

# analytic history at the DEM output times
analytic, vt_signed, _ = settling(d, rho_p, rho_f, nu, [r[0] for r in rows])
v_terminal = -vt_signed

os.makedirs(os.path.join(case, "results"), exist_ok=True)
with open(os.path.join(case, "results", "velocity.csv"), "w") as f:
    f.write("t_s,z_m,vz_sim_m_per_s,vz_analytic_m_per_s\n")
    for i, (t, z, vz) in enumerate(rows):
        f.write(f"{t:.6g},{z:.6g},{vz:.6g},{analytic[i]:.6g}\n")

# measured terminal velocity: mean over the last 20 % of the history while still falling freely
# (before the particle gets within 10 d of the bottom)
free = [r for r in rows if r[1] > 10 * d]
tail = free[int(0.8 * len(free)):]
v_sim = -sum(r[2] for r in tail) / len(tail)
err = abs(v_sim - v_terminal) / v_terminal
# history error: max deviation over the free fall, relative to the terminal velocity
hist_err = max(abs(r[2] - analytic[i]) for i, r in enumerate(rows) if r[1] > 10 * d) / v_terminal
# smoothness: the largest deviation from the mean velocity over the second half of the free fall
late = [-r[2] for r in free[len(free) // 2:]]
roughness = max(abs(v - sum(late) / len(late)) for v in late) / v_terminal

with open(os.path.join(case, "results", "summary.csv"), "w") as f:
    f.write("quantity,measured,reference,relative_error,wall_time_s\n")
    f.write(f"terminal_velocity_m_per_s,{v_sim:.6g},{v_terminal:.6g},{err:.3e},{wall:.1f}\n")
    f.write(f"velocity_history_max_deviation_over_vt,{hist_err:.6g},0,{hist_err:.3e},{wall:.1f}\n")
    f.write(f"late_velocity_max_deviation_over_vt,{roughness:.6g},0,{roughness:.3e},{wall:.1f}\n")
print(f"settlingTest: terminal velocity {v_sim:.5f} m/s, analytic {v_terminal:.5f} m/s, error {100*err:.2f} %")
print(f"settlingTest: velocity history max deviation {100*hist_err:.2f} % of v_t")
print(f"settlingTest: second half of the free fall, largest deviation from the mean velocity {100*roughness:.3f} % of v_t")
name = "settlingTest" + ("" if model == "A" else "/model" + model) + ("/coarse_d_dx2" if coarse else "")
tol = 0.03 if coarse else 0.01
ok = err <= tol
print(("PASS: " if ok else "FAIL: ") + f"{name}/terminal_velocity_within_{100*tol:g}pct ({100*err:.2f} %)")
if coarse:
    smooth = roughness <= 0.005
    print(("PASS: " if smooth else "FAIL: ") + f"{name}/smooth_across_faces: largest deviation from the mean "
          f"velocity over the second half of the free fall {100*roughness:.3f} % of v_t (limit 0.5 %)")
    ok = ok and smooth
sys.exit(0 if ok else 1)
