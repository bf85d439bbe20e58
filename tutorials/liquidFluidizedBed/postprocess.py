#!/usr/bin/python3
"""postprocess.py -- bed voidage and frictional pressure drop of one liquidFluidizedBed run.

    postprocess.py RUN -method M -modelType A|B -U U -tstart T0 -tend T1 -demdt DT -wall S -mode short|full
                   [-width W]     (the tube's width in mm, Allrun -width; default 10)
                   [-cellSize DX] (the cells' size in mm, Allrun -cellSize; default 1)
                   [-drag L]      (the run's drag law, Allrun -drag: DiFelice (default), Gidaspow,
                                   KochHill; eps_drag_equilibrium is that law's)

Writes RUN/results/result.csv (the row of results/summary.csv), RUN/results/details.csv (further
numbers), RUN/results/bedHeight.csv (time series over the whole run) and
RUN/results/profile.csv (time-averaged solid fraction profile). In the short mode it prints PASS/FAIL
lines (the test of tests/Alltest liquidbed).

Definitions (independent of the void-fraction method: from the particle positions that LIGGGHTS
dumps every 0.02 s, and the pressure the fluid solver samples every 0.01 s):
- H_c = 2 x the mean height of the particle centres: the height of a uniform bed with the same
  solid centroid. eps_sim (the headline) = eps_H = 1 - V_s/(A H_c): the mean voidage of the bed,
  all particles counted, the layer on the distributor included.
- eps_plateau (details.csv) = 1 - alpha_p over the central part of the bed, 0.2 H_c < z < 0.7 H_c:
  the exact solid volume of the spheres between the two planes (sphere-slab overlap, no binning)
  over A (0.7 - 0.2) H_c. It was meant as the headline (the plateau of the cross-section-averaged
  profile, away from the distributor layer and the diffuse top), but the beds form dense plugs
  (alpha_p ~ 0.6) with water gaps between them (profile.csv): there is no plateau, and the
  central-window average depends on where the gaps fall (it drifts by ~0.02 in 0.4 s where eps_H
  stays within 0.002). The README shows the profiles.
- dp_sim: the bed's frictional pressure drop, the inlet-to-outlet pressure difference less the water's
  hydrostatic head and less the water's own friction on the tube's side walls (the empty-tube loss
  a fluidization experiment subtracts): rho_f p_inlet - rho_f g H_tube - F_wall / A, p_inlet the area
  average of p over the inlet face (z = 0, below the bed), p = 0 at the outlet (z = 120 mm, p is
  kinematic and includes the hydrostatic part), F_wall the z force of the water's viscous stress on the
  side walls (the forces function object wallFriction: nu dev2(grad U) at the walls; in Model A the
  water's stress in the bed is alpha times that, so there it is an upper bound by a factor 1/alpha).
  details.csv: dp_plane, the earlier measure (the inlet face against the cross-section at 30.5 mm above
  the bed, less the head between them, the wall friction not taken off), and wall_friction_Pa.
- dp_weight = (rho_p - rho_f) g V_s / A, V_s from the dumped radii.
- Time averages over the window tstart..tend; the standard error by batch means (5 batches of
  consecutive samples: sem = std(batch means)/sqrt(5)).
- Stationarity: the difference of eps_sim between the second and the first half of the window
  (drift), against eps_sem.
- Where the weight goes (measured by LIGGGHTS, post/wallForce.txt: each wall's force on the
  particles, wall/gran store_force, summed over the particles and averaged over every 10th DEM step):
  support_bottom_Pa = the distributor's upward force / A; side_wall_z_Pa = the z force of the four
  side walls (friction) / A; side_wall_normal_Pa = their normal forces / A; wall_force_share = the
  z force of all six walls over the bed's buoyant weight (dp_weight A). What the walls carry the fluid
  does not: dp_sim / dp_weight + wall_force_share should be 1 (dp_plus_walls_rel_err).
- fluid_share (from the dumped coupling force f_cfd of every particle): the z force of the fluid on
  the particles over their weight m g (the fluid force includes buoyancy: -V grad p with p's
  hydrostatic part in Model A, Archimedes in Model B), over the window; fluid_share_bottom the same
  for the particles whose centre is within d of the distributor; forceProfile.csv by 1 mm layers.
- Contacts (particle pairs closer than the sum of their radii, in the dumps): coordination = contacts
  per particle; contact_persist_0.1s = the share of the contacts at a dump still in contact (the
  same pair) 0.1 s later: near 0 in a fluidized bed, whose contacts are brief collisions; near 1 in a
  bed resting on its contact network (frozen).
- v_rms: the rms particle speed over the particles and the dumps of the window (how lively the bed is);
  v_fluct_rms: the rms of the particle velocity minus its own mean over the window (the motion that is
  not a slow drift of the whole bed).
- Lateral flow (from the fields written in the window, every 0.25 s; nan where none were
  reconstructed): with q = alpha U_z the superficial velocity of a cell and the bed's cells those
  below 0.9 H_c, column_flux_min/max = the smallest and largest column mean of q over the bed's
  height, time-averaged, over U (1 and 1 in a homogeneous bed; a column whose water sinks has a
  negative value); flux_seen = the particle-weighted mean of q (alpha_p q summed over the bed's cells
  over alpha_p summed) over U: the share of the water's flux that passes where the particles are
  (1 in a homogeneous bed; below 1 where the water bypasses the dense columns).
- Lateral clustering (from the dumps): the particle centres of the bed's core (0.15..0.85 H_c) counted
  in boxes of 2.5 mm, layer by layer; count_ratio_2p5mm = the variance of the counts over their mean
  within each layer, averaged over the layers and the window's dumps: about 0.1-0.4 for spheres
  placed at random without overlap (the start state), 1 for independent (Poisson) positions, well
  above 1 where the particles gather into columns or plates. Independent of the mesh.
- Max overlap: d - the smallest centre distance (particle pairs) and r - the smallest wall distance,
  over the dumps in the window, in % of d.
"""
import argparse, glob, math, os, sys

import numpy as np

# the project's Python library, etc/python (COARSEDEM_DIR: this file may run from a copy of the tutorial)
sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."), "etc", "python"))
import liquid_bed_references as ref
from liquid_bed_references import PERSIST_FROZEN
from dem_series import NB, batch_sem, read_dumps, read_fv, read_wall_forces, wall_force_share
from particle_pairs import close_pairs
from foam_fields import FieldFormatError, read_internal_field

A, W, HT = ref.A, 0.010, 0.120
Z_ABOVE = 0.0305
HEADER = "method,modelType,U,eps_sim,eps_sem,eps_drag_equilibrium,eps_richardson_zaki,dp_sim,dp_weight,dp_rel_err,wall_s"


def slab_volume(zc, r, a, b):
    """Solid volume of spheres (centres zc, radii r) between the planes z = a and z = b."""
    lo = np.clip(a - zc, -r, r)
    hi = np.clip(b - zc, -r, r)
    prim = lambda t: math.pi * (r * r * t - t ** 3 / 3)
    return prim(hi) - prim(lo)


def lateral_flow(run, tstart, tend, width, U, hc, dx=0.001, height=HT):
    """(column_flux_min, column_flux_max, flux_seen, number of field times) over the window from the
    fields alpha and U that the run wrote (the docstring's definitions); nans and 0 where none. The
    mesh is the tube's block, round(width/dx) x round(width/dx) x round(height/dx) cells, x fastest."""
    nx, nz = int(round(width / dx)), int(round(height / dx))
    n = nx * nx * nz
    kbed = max(1, int(0.9 * hc / dx))
    cols, seen = [], []
    for d in glob.glob(os.path.join(run, "[0-9]*")):
        try:
            t = float(os.path.basename(d))
        except ValueError:
            continue
        if not (tstart - 1e-9 <= t <= tend + 1e-9) or not os.path.exists(os.path.join(d, "U")):
            continue
        try:
            af = read_internal_field(os.path.join(d, "alpha"), n).reshape(nz, nx, nx)[:kbed]
            uz = read_internal_field(os.path.join(d, "U"), n)[:, 2].reshape(nz, nx, nx)[:kbed]
        except FieldFormatError as e:
            sys.exit("postprocess.py: %s" % e)
        q = af * uz
        cols.append(q.mean(axis=0))
        seen.append(float(np.sum((1 - af) * q) / np.sum(1 - af)))
    if not cols:
        return float("nan"), float("nan"), float("nan"), 0
    c = np.mean(cols, axis=0) / U
    return float(c.min()), float(c.max()), float(np.mean(seen)) / U, len(cols)


def count_ratio(dumps, heights, width, box=0.0025):
    """count_ratio_2p5mm of the docstring: the particle-count variance over its mean in box x box x box
    cells of the bed's core (0.15..0.85 H_c, heights: each dump's H_c), layer by layer, averaged over
    the layers and dumps."""
    nb = max(1, int(round(width / box)))
    idx = lambda v: np.clip((v / box).astype(int), 0, nb - 1)
    ratios = []
    for c, hc in zip(dumps, heights):
        z = c["z"]
        nz = int(0.7 * hc // box)
        core = (z > 0.15 * hc) & (z < 0.15 * hc + nz * box)
        if nz < 1 or not core.any():
            continue
        h = np.zeros((nz, nb * nb))
        np.add.at(h, (np.clip(((z[core] - 0.15 * hc) / box).astype(int), 0, nz - 1),
                      idx(c["x"][core]) * nb + idx(c["y"][core])), 1)
        mean = h.mean(axis=1)
        ok = mean > 0
        ratios.append(float(np.mean(h.var(axis=1)[ok] / mean[ok])))
    return float(np.mean(ratios)) if ratios else float("nan")


def touching(c):
    """(a, b, distance, sum of the radii) of the particle pairs of a dump in contact (a cell list:
    etc/python/particle_pairs.py)."""
    a, b, d = close_pairs(np.stack([c["x"], c["y"], c["z"]], axis=1), c["radius"])
    return a, b, d, c["radius"][a] + c["radius"][b]


def max_overlap(c):
    x, y, z, r = c["x"], c["y"], c["z"], c["radius"]
    _, _, d, rr = touching(c)
    best = float((rr - d).max()) if len(d) else -np.inf
    wall = np.concatenate([r - x, r - (W - x), r - y, r - (W - y), r - z, r - (HT - z)])
    return max(best, float(wall.max())) / (2 * r.mean())


def contact_pairs(c):
    """Set of particle-id pairs in contact (centre distance below the sum of the radii)."""
    ids = c["id"].astype(np.int64)
    a, b, _, _ = touching(c)
    return set(zip(ids[a].tolist(), ids[b].tolist()))


def contact_stats(wd, times, lag):
    """(coordination number, share of contacts still there after lag s) over the window's dumps."""
    coord, persist = [], []
    pairs = [contact_pairs(c) for c in wd]
    for k, (c, pk) in enumerate(zip(wd, pairs)):
        coord.append(2.0 * len(pk) / len(c["z"]))
        later = [j for j in range(k + 1, len(wd)) if abs(times[j] - times[k] - lag) < 1e-6]
        if later and pk:
            persist.append(len(pk & pairs[later[0]]) / len(pk))
    return float(np.mean(coord)), (float(np.mean(persist)) if persist else float("nan"))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run")
    for k in ("method", "modelType", "mode"):
        ap.add_argument("-" + k, required=True)
    for k in ("U", "tstart", "tend", "demdt", "wall"):
        ap.add_argument("-" + k, type=float, required=True)
    ap.add_argument("-width", type=float, default=10.0)
    ap.add_argument("-cellSize", type=float, default=1.0)
    ap.add_argument("-drag", default="DiFelice", choices=ref.DRAG_LAWS)
    a = ap.parse_args()
    global A, W
    W = a.width * 1e-3
    A = W * W
    name = os.path.basename(os.path.normpath(a.run))
    dumps = read_dumps(a.run, a.demdt)
    if not dumps:
        print("FAIL: %s: no particle dumps in %s/post" % (name, a.run))
        return 1
    vs = float(np.sum(math.pi / 6 * (2 * dumps[0][1]["radius"]) ** 3))
    d_p = 2 * float(np.median(dumps[0][1]["radius"]))   # the bed's diameter (1 mm; -species small 0.3 mm)
    n0 = len(dumps[0][1]["z"])
    series = []                               # t, H_c, eps_H, eps_plateau, z_top
    for t, c in dumps:
        z, r = c["z"], c["radius"]
        hc = 2 * float(np.sum(z * r ** 3) / np.sum(r ** 3))
        lo, hi = 0.2 * hc, 0.7 * hc
        ap_ = float(np.sum(slab_volume(z, r, lo, hi))) / (A * (hi - lo))
        series.append((t, hc, 1 - vs / (A * hc), 1 - ap_, float(np.max(z + r))))
    s = np.array(series)
    win = (s[:, 0] >= a.tstart - 1e-9) & (s[:, 0] <= a.tend + 1e-9)
    if win.sum() < 2 * NB:
        print("FAIL: %s: only %d particle dumps in the window %g..%g s" % (name, win.sum(), a.tstart, a.tend))
        return 1
    eps = s[win, 2]
    eps_sim, eps_sem = float(eps.mean()), batch_sem(eps)
    half = len(eps) // 2
    drift = float(eps[half:].mean() - eps[:half].mean())
    eps_pl, eps_pl_sem = float(s[win, 3].mean()), batch_sem(s[win, 3])
    hc_mean = float(s[win, 1].mean())
    hc_sem = batch_sem(s[win, 1])

    # time-averaged solid fraction profile, 0.5 mm bins, up to 30 mm or the highest particle's top
    z_top = max(0.030, math.ceil(1e3 * float(s[win, 4].max())) * 1e-3)
    edges = np.arange(0, z_top + 1e-12, 0.0005)
    prof = np.zeros(len(edges) - 1)
    wd = [c for (t, c), w in zip(dumps, win) if w]
    for c in wd:
        prof += np.array([np.sum(slab_volume(c["z"], c["radius"], edges[i], edges[i + 1]))
                          for i in range(len(edges) - 1)]) / (A * 0.0005)
    prof /= len(wd)
    overlap = max(max_overlap(c) for c in wd[::max(1, len(wd) // 10)])
    # where the weight goes: the walls (LIGGGHTS' wall forces) and the fluid (the coupling force)
    tw, wf = read_wall_forces(a.run, a.demdt)
    ww = (tw >= a.tstart - 1e-9) & (tw <= a.tend + 1e-9)
    if ww.sum() < 2 * NB:
        print("FAIL: %s: only %d wall-force samples in the window" % (name, ww.sum()))
        return 1
    wmean = wf[ww].mean(axis=0)
    weight_buoyant = (ref.RHO_P - ref.RHO_F) * ref.G * vs
    sup_bottom, side_z = wmean[0] / A, float(wmean[2:6].sum()) / A
    sup_side = float(np.abs(wmean[6:10]).sum()) / A
    wall_share, wall_share_sem = wall_force_share(wf[ww], weight_buoyant)
    zbins = np.arange(0, z_top + 1e-12, 0.001)
    carried = np.zeros(len(zbins) - 1); weight_bin = np.zeros(len(zbins) - 1); count_bin = np.zeros(len(zbins) - 1)
    fz_sum = mg_sum = fz_bot = mg_bot = 0.0
    for c in wd:
        mg = ref.RHO_P * math.pi / 6 * (2 * c["radius"]) ** 3 * ref.G
        fz = c["f_cfd[3]"]
        fz_sum += fz.sum(); mg_sum += mg.sum()
        bot = c["z"] < 2 * c["radius"]
        fz_bot += fz[bot].sum(); mg_bot += mg[bot].sum()
        k = np.clip(np.digitize(c["z"], zbins) - 1, 0, len(carried) - 1)
        np.add.at(carried, k, fz); np.add.at(weight_bin, k, mg); np.add.at(count_bin, k, 1)
    fluid_share = fz_sum / mg_sum
    fluid_bottom = fz_bot / mg_bot if mg_bot > 0 else float("nan")
    # particle motion: rms of |v|, and rms of v about each particle's own mean over the window
    v_rms = math.sqrt(float(np.mean([np.mean(c["vx"] ** 2 + c["vy"] ** 2 + c["vz"] ** 2) for c in wd])))
    vstack = np.stack([np.stack([c["vx"], c["vy"], c["vz"]], axis=1) for c in wd
                       if len(c["z"]) == len(wd[0]["z"])])
    v_fluct = math.sqrt(float(np.mean(((vstack - vstack.mean(axis=0)) ** 2).sum(-1))))
    twin = [t for (t, c), w in zip(dumps, win) if w]
    clustering = count_ratio(wd, s[win, 1], W)
    col_min, col_max, flux_seen, n_fields = lateral_flow(a.run, a.tstart, a.tend, W, a.U, hc_mean, dx=1e-3 * a.cellSize)
    coord, persist = contact_stats(wd, twin, 0.1)

    # pressure
    fv = lambda n: os.path.join(a.run, "postProcessing", n, "0", "surfaceFieldValue.dat")
    ti, pi_ = read_fv(fv("pInlet"))
    ta, pa = read_fv(fv("pAbove"))
    m = min(len(ti), len(ta))
    if m == 0 or np.max(np.abs(ti[:m] - ta[:m])) > 1e-9:
        print("FAIL: %s: pressure samples missing or not at the same times" % name)
        return 1
    rho_f, g = ref.RHO_F, ref.G
    dp_pl = rho_f * (pi_[:m] - pa[:m]) - rho_f * g * Z_ABOVE
    tf, fv = read_fv(os.path.join(a.run, "postProcessing", "wallFriction", "0", "force.dat"), column=9)
    k = min(m, len(tf))
    if k == 0 or np.max(np.abs(ti[:k] - tf[:k])) > 1e-9:
        print("FAIL: %s: wall-friction samples missing or not at the pressure's times" % name)
        return 1
    m = k
    dp_pl = dp_pl[:m]
    dp = rho_f * pi_[:m] - rho_f * g * HT - fv[:m] / A
    pw = (ti[:m] >= a.tstart - 1e-9) & (ti[:m] <= a.tend + 1e-9)
    dp_sim, dp_sem = float(dp[pw].mean()), batch_sem(dp[pw])
    dp_plane, wall_friction = float(dp_pl[pw].mean()), float(fv[:m][pw].mean() / A)
    dp_weight = (ref.RHO_P - rho_f) * g * vs / A
    dp_rel = (dp_sim - dp_weight) / dp_weight
    e_eq, e_rz = ref.eps_drag_equilibrium(a.U, a.drag, d_p), ref.eps_richardson_zaki(a.U, d_p)
    n_last = len(dumps[-1][1]["z"])

    res = os.path.join(a.run, "results")
    os.makedirs(res, exist_ok=True)
    with open(os.path.join(res, "result.csv"), "w") as f:
        f.write(HEADER + "\n")
        f.write("%s,%s,%.3f,%.4f,%.4f,%.4f,%.4f,%.3f,%.3f,%.4f,%.1f\n" % (
            a.method, a.modelType, a.U, eps_sim, eps_sem, e_eq, e_rz, dp_sim, dp_weight, dp_rel, a.wall))
    with open(os.path.join(res, "details.csv"), "w") as f:
        f.write("method,modelType,U,eps_plateau,eps_plateau_sem,H_c_mm,H_c_sem_mm,eps_drift,dp_sem,max_overlap_pct_d,"
                "support_bottom_Pa,side_wall_normal_Pa,v_rms_mm_s,n_particles_start,n_particles_end,n_dumps_window,n_dp_samples_window,tstart,tend,"
                "side_wall_z_Pa,wall_force_share,wall_force_share_sem,dp_plus_walls_rel_err,fluid_share,fluid_share_bottom,"
                "v_fluct_rms_mm_s,coordination,contact_persist_0.1s,dp_plane,wall_friction_Pa,"
                "column_flux_min,column_flux_max,flux_seen,n_field_times,count_ratio_2p5mm\n")
        f.write("%s,%s,%.3f,%.4f,%.4f,%.3f,%.3f,%.4f,%.3f,%.3f,%.3f,%.3f,%.3f,%d,%d,%d,%d,%g,%g,"
                "%.3f,%.4f,%.4f,%.4f,%.4f,%.4f,%.3f,%.3f,%.3f,%.3f,%.4f,%.3f,%.3f,%.3f,%d,%.3f\n" % (
            a.method, a.modelType, a.U, eps_pl, eps_pl_sem, 1e3 * hc_mean, 1e3 * hc_sem, drift, dp_sem, 100 * overlap,
            sup_bottom, sup_side, 1e3 * v_rms, n0, n_last, int(win.sum()), int(pw.sum()), a.tstart, a.tend,
            side_z, wall_share, wall_share_sem, dp_rel + wall_share, fluid_share, fluid_bottom,
            1e3 * v_fluct, coord, persist, dp_plane, wall_friction, col_min, col_max, flux_seen, n_fields, clustering))
    with open(os.path.join(res, "forceProfile.csv"), "w") as f:
        f.write("z_mm,particles,fluid_share\n")
        for i in range(len(carried)):
            if count_bin[i] > 0:
                f.write("%.1f,%.2f,%.4f\n" % (1e3 * 0.5 * (zbins[i] + zbins[i + 1]), count_bin[i] / len(wd),
                                              carried[i] / weight_bin[i]))
    with open(os.path.join(res, "bedHeight.csv"), "w") as f:
        f.write("t,H_c_mm,eps_H,eps_plateau,z_top_mm,dp_Pa\n")
        for t, hc, eh, ep, zt in series:
            k = int(np.argmin(np.abs(ti[:m] - t))) if m else 0
            dpt = dp[k] if m and abs(ti[k] - t) < 0.006 else float("nan")
            f.write("%.3f,%.4f,%.4f,%.4f,%.4f,%.3f\n" % (t, 1e3 * hc, eh, ep, 1e3 * zt, dpt))
    with open(os.path.join(res, "profile.csv"), "w") as f:
        f.write("z_mm,alpha_p\n")
        for i, v in enumerate(prof):
            f.write("%.2f,%.4f\n" % (1e3 * 0.5 * (edges[i] + edges[i + 1]), v))

    print("%s: eps_sim %.4f +- %.4f (%s drag equilibrium %.4f: %+.4f; Richardson-Zaki %.4f), eps_plateau %.4f, "
          "H_c %.2f mm, drift in window %+.4f; dp %.2f +- %.2f Pa vs weight %.2f Pa (%+.2f %%); "
          "walls carry %.2f %% of the weight (distributor %.2f Pa, side walls %.2f Pa), dp + walls %+.2f %%; "
          "fluid carries %.3f of the weight (bottom layer %.3f); v_rms %.2f mm/s (fluctuation %.2f), "
          "coordination %.2f, contacts kept over 0.1 s %.2f; water flux by column %.2f..%.2f of U, where the "
          "particles are %.2f (%d field times), particle-count variance / mean in 2.5 mm boxes %.2f; max overlap %.2f %% d; wall %.0f s"
          % (name, eps_sim, eps_sem, a.drag, e_eq, eps_sim - e_eq, e_rz, eps_pl, 1e3 * hc_mean, drift, dp_sim, dp_sem,
             dp_weight, 100 * dp_rel, 100 * wall_share, sup_bottom, side_z, 100 * (dp_rel + wall_share),
             fluid_share, fluid_bottom, 1e3 * v_rms, 1e3 * v_fluct, coord, persist, col_min, col_max, flux_seen,
             n_fields, clustering, 100 * overlap, a.wall))
    if a.mode == "short":
        ok = True
        def check(cond, what):
            nonlocal ok
            ok &= cond
            print("%s: %s: %s" % ("PASS" if cond else "FAIL", name, what))
        check(n_last == n0, "particles kept (%d at the start, %d at the end)" % (n0, n_last))
        # within 2 % and two standard errors of the window's mean pressure drop: a method whose
        # alpha_p jumps as centres cross faces (centre, divided at dx = d) swings the pressure by
        # several Pa over the 0.3 s window
        tol = 0.02 + 2 * dp_sem / dp_weight
        check(abs(dp_rel + wall_share) <= tol,
              "momentum balance: the frictional pressure drop %.2f +- %.2f Pa and the walls' share %.2f %% make up "
              "the bed's buoyant weight %.2f Pa within 2 %% + 2 SEM = %.1f %% (%+.2f %%)" % (
                  dp_sim, dp_sem, 100 * wall_share, dp_weight, 100 * tol, 100 * (dp_rel + wall_share)))
        check(wall_share < 0.02, "the walls carry under 2 %% of the bed's weight (%.2f %%: distributor %.2f Pa, "
              "side walls %.2f Pa)" % (100 * wall_share, sup_bottom, side_z))
        check(abs(fluid_bottom - 1) <= 0.05, "the fluid carries the weight of the layer on the distributor "
              "within 5 %% (%.3f of m g)" % fluid_bottom)
        h_packed = vs / (A * (1 - 0.40))   # m: ref.height for this run's solid and tube
        check(hc_mean > 1.1 * h_packed, "bed expanded: H_c %.2f mm above 1.1 x the packed height %.2f mm "
              "(eps 0.40)" % (1e3 * hc_mean, 1e3 * h_packed))
        check(abs(eps_sim - e_eq) <= 0.02, "bed voidage %.4f within 0.02 of the drag-law equilibrium %.4f "
              "(the start is at 0.727)" % (eps_sim, e_eq))
        # a fluidized bed's contacts are collisions, renewed within a fraction of a second; a bed that
        # rests on a network of lasting contacts (a plug) is frozen, whatever its mean voidage
        check(persist < PERSIST_FROZEN, "particles move: %.2f of the contacts last 0.1 s (a frozen bed: %.1f or "
              "more), velocity fluctuation %.2f mm/s" % (persist, PERSIST_FROZEN, 1e3 * v_fluct))
        return 0 if ok else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
