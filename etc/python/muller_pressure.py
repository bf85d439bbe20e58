"""The Mueller bed's time-averaged pressure drop against its weight, and the walls' share of it.

    pressureDrop.py <case dir> <t_start> <t_end>

A bubbling bed carries its whole weight on the gas: the time-averaged frictional pressure drop across
it equals the particles' buoyant weight per area of the bed's cross-section (momentum balance of the
column between the distributor and the outlet; the walls' friction on the gas is negligible at these
speeds). What the walls carry instead (the particles' contacts with the distributor, the front and
back walls and the side walls) is measured by the DEM (post/wallForce.txt, DEM/in.liggghts). The
bed's expansion: twice the particles' mean height (post/bedHeight.txt; the height of a bed of uniform
solid fraction with that mean) over the settled bed's 30 mm (Zhang et al. 2023 §V.B).

Reads postProcessing/pInlet (the inlet's area-averaged kinematic p; the outlet holds p = 0) and
post/wallForce.txt over t_start < t <= t_end. The frictional pressure drop is rho_g (p_inlet - g H)
(the gas column's own weight, rho_g g H = 1.41 Pa, taken off). The bed (Mueller et al. 2008; Zhang et
al. 2023 Table II): 9240 spheres of 1.2 mm, 1000 kg/m3, in air of 1.2 kg/m3, cross-section 44 x 10 mm.
Batch-means errors over 10 batches. Writes <case>/results/pressure.csv (one row) and prints it.
"""
import math
import os
import sys

import numpy as np

from dem_series import (batch_sem, dem_script_step, dem_time_anchor, function_series, read_post_series,
                        read_wall_forces, wall_force_share)

N_PARTICLES = 9240
DIAMETER = 1.2e-3          # m
RHO_P = 1000.0             # kg/m3
RHO_G = 1.2                # kg/m3 (constant/transportProperties)
G = 9.81                   # m/s2
AREA = 0.044 * 0.010       # m2, the bed's cross-section
HEIGHT = 0.120             # m, inlet to outlet
SETTLED_HEIGHT = 0.030     # m, the packed bed's height (Zhang et al. 2023 §V.B)
BATCHES = 10


def buoyant_weight():
    """The particles' weight less the gas's buoyancy, N."""
    return N_PARTICLES * math.pi / 6 * DIAMETER ** 3 * (RHO_P - RHO_G) * G


def summary(case, t0, t1):
    t, p = function_series(case, "pInlet")
    w = (t > t0 + 1e-12) & (t <= t1 + 1e-12)
    if w.sum() < 2 * BATCHES:
        raise ValueError(f"{case}: {int(w.sum())} pressure samples in ({t0}, {t1}] s, fewer than {2 * BATCHES} "
                         "(postProcessing/pInlet: the controlDict's pInlet function)")
    dp = RHO_G * (p[w] - G * HEIGHT)
    weight = buoyant_weight()
    anchor = dem_time_anchor(case)   # the DEM step's time: the shipped state's steps do not start at 0
    dem_dt = dem_script_step(case, "materials.liggghts")   # the run's own (6e-6 s before 1e-5 s)
    row = {"t_start": t0, "t_end": t1, "samples": int(w.sum()),
           "dp_pa": float(dp.mean()), "dp_sem_pa": batch_sem(dp, BATCHES),
           "weight_per_area_pa": weight / AREA}
    row["dp_rel_err"] = row["dp_pa"] / row["weight_per_area_pa"] - 1
    try:
        tw, wf = read_wall_forces(case, dem_dt, anchor)
        ww = (tw > t0 + 1e-12) & (tw <= t1 + 1e-12)
        share, share_sem = wall_force_share(wf[ww], weight) if ww.sum() >= 2 else (float("nan"),) * 2
        # each wall's share: distributor, lid, front and back (x), side walls (y)
        parts = wf[ww][:, :6].mean(axis=0) / weight if ww.sum() else np.full(6, np.nan)
        row.update({"wall_force_share": share, "wall_force_share_sem": share_sem,
                    "distributor_share": parts[0], "front_back_share": parts[2] + parts[3],
                    "side_walls_share": parts[4] + parts[5]})
        row["dp_plus_walls_rel_err"] = (row["dp_pa"] * AREA + share * weight) / weight - 1
    except (OSError, ValueError) as e:
        print(f"pressureDrop.py: no wall forces ({e}): the walls' share not measured")
    try:
        tz, z = read_post_series(case, "bedHeight", 1, dem_dt, anchor)
        wz = (tz > t0 + 1e-12) & (tz <= t1 + 1e-12)
        # a bed of uniform solid fraction from 0 to H has its particles' mean height at H / 2
        row.update({"mean_particle_height_mm": 1e3 * float(z[wz, 0].mean()),
                    "expansion_2zbar_over_settled": 2 * float(z[wz, 0].mean()) / SETTLED_HEIGHT})
    except (OSError, ValueError) as e:
        print(f"pressureDrop.py: no bed heights ({e}): the expansion not measured")
    return row


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    case, t0, t1 = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    try:
        row = summary(case, t0, t1)
    except ValueError as e:
        sys.exit(f"pressureDrop.py: {e}")
    os.makedirs(os.path.join(case, "results"), exist_ok=True)
    with open(os.path.join(case, "results", "pressure.csv"), "w") as f:
        f.write(",".join(row) + "\n")
        f.write(",".join(f"{v:.6g}" if isinstance(v, float) else str(v) for v in row.values()) + "\n")
    print(f"pressureDrop.py: frictional pressure drop {row['dp_pa']:.2f} +- {row['dp_sem_pa']:.2f} Pa against the "
          f"bed's weight {row['weight_per_area_pa']:.2f} Pa per area ({100 * row['dp_rel_err']:+.2f} %)"
          + (f"; the walls carry {100 * row['wall_force_share']:.2f} % of the weight "
             f"(distributor {100 * row['distributor_share']:.2f} %, front and back {100 * row['front_back_share']:.2f} %, "
             f"sides {100 * row['side_walls_share']:.2f} %)" if "wall_force_share" in row else "")
          + (f"; mean particle height {row['mean_particle_height_mm']:.2f} mm (expansion "
             f"{row['expansion_2zbar_over_settled']:.3f})" if "mean_particle_height_mm" in row else ""))
