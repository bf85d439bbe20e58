#!/usr/bin/python3
"""postprocess.py -- bed voidage and frictional pressure drop of one liquidFluidizedBed run.

    postprocess.py RUN -method M -modelType A|B -U U -tstart T0 -tend T1 -demdt DT -wall S -mode short|full
                   [-width W]     (the tube's width in mm, Allrun -width; default 10)
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
- dp_sim = rho_f (p_inlet - p_above) - rho_f g z_above: the area average of p over the inlet face
  (z = 0, below the bed) minus that over the cross-section z_above = 30.5 mm (above the bed),
  less the hydrostatic head of the water between them (p is kinematic and includes it).
- dp_weight = (rho_p - rho_f) g V_s / A, V_s from the dumped radii.
- Time averages over the window tstart..tend; the standard error by batch means (5 batches of
  consecutive samples: sem = std(batch means)/sqrt(5)).
- Stationarity: the difference of eps_sim between the second and the first half of the window
  (drift), against eps_sem.
- Wall support: the normal force of the distributor (z = 0) and of the side walls on the particles,
  per tube area, from the dumped overlaps with the Hertz law of wall/gran (F = 4/3 E* sqrt(r)
  delta^1.5, E* = E / (2 (1 - nu^2)), E = 1e6 Pa, nu = 0.23; damping left out), averaged over the
  window. What the distributor carries is weight the fluid does not: dp_sim + bottom support
  (+ at most friction 0.1 x the side-wall normal force) should make up dp_weight.
- v_rms: the rms particle speed over the particles and the dumps of the window (how lively the bed is).
- Max overlap: d - the smallest centre distance (particle pairs) and r - the smallest wall distance,
  over the dumps in the window, in % of d.
"""
import argparse, glob, math, os, re, sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import references as ref

A, W, HT = ref.A, 0.010, 0.120
Z_ABOVE = 0.0305
HEADER = "method,modelType,U,eps_sim,eps_sem,eps_drag_equilibrium,eps_richardson_zaki,dp_sim,dp_weight,dp_rel_err,wall_s"
NB = 5


def slab_volume(zc, r, a, b):
    """Solid volume of spheres (centres zc, radii r) between the planes z = a and z = b."""
    lo = np.clip(a - zc, -r, r)
    hi = np.clip(b - zc, -r, r)
    prim = lambda t: math.pi * (r * r * t - t ** 3 / 3)
    return prim(hi) - prim(lo)


def read_dumps(run, demdt):
    out = []
    for f in glob.glob(os.path.join(run, "post", "dump*.liggghts")):
        with open(f) as fh:
            lines = fh.readlines()
        step = int(lines[1])
        cols = lines[8].split()[2:]
        a = np.loadtxt(lines[9:])
        if a.ndim != 2 or a.shape[0] == 0:
            continue
        c = {k: a[:, i] for i, k in enumerate(cols)}
        out.append((step * demdt, c))
    out.sort(key=lambda x: x[0])
    return out


def read_fv(path):
    """(times, values) of a surfaceFieldValue file. Its last line may be cut short (the run was
    killed while writing it): left out; a bad line anywhere else is an error naming the file."""
    t, v = [], []
    with open(path) as f:
        lines = [l for l in f if l.strip() and not l.startswith("#")]
    for i, line in enumerate(lines):
        s = line.split()
        try:
            ti, vi = float(s[0]), float(s[1])
        except (IndexError, ValueError):
            if i == len(lines) - 1:
                break
            raise ValueError("%s: unreadable sample line %r" % (path, line.rstrip("\n")))
        t.append(ti)
        v.append(vi)
    return np.array(t), np.array(v)


def batch_sem(x):
    x = np.asarray(x)
    if len(x) < 2 * NB:
        return float("nan")
    means = [b.mean() for b in np.array_split(x, NB)]
    return float(np.std(means, ddof=1) / math.sqrt(NB))


def max_overlap(c):
    x, y, z, r = c["x"], c["y"], c["z"], c["radius"]
    p = np.stack([x, y, z], axis=1)
    best = 0.0
    for i in range(0, len(x), 256):          # blocks of rows, so memory stays small
        d = np.sqrt(((p[i:i + 256, None, :] - p[None, :, :]) ** 2).sum(-1))
        rr = r[i:i + 256, None] + r[None, :]
        idx = np.arange(i, min(i + 256, len(x)))
        d[np.arange(len(idx)), idx] = np.inf
        best = max(best, float((rr - d).max()))
    wall = np.concatenate([r - x, r - (W - x), r - y, r - (W - y), r - z, r - (HT - z)])
    return max(best, float(wall.max())) / (2 * r.mean())


E_YOUNG, NU_POISSON = 1e6, 0.23       # DEM/in.liggghts


def wall_support(c):
    """(distributor, side walls) normal force on the particles / A (Pa), Hertz from the overlaps."""
    es = E_YOUNG / (2 * (1 - NU_POISSON ** 2))
    r = c["radius"]
    f = lambda delta: 4.0 / 3 * es * np.sqrt(r) * np.clip(delta, 0, None) ** 1.5
    bottom = float(f(r - c["z"]).sum())
    side = float(sum(f(r - v).sum() for v in (c["x"], W - c["x"], c["y"], W - c["y"])))
    return bottom / A, side / A


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run")
    for k in ("method", "modelType", "mode"):
        ap.add_argument("-" + k, required=True)
    for k in ("U", "tstart", "tend", "demdt", "wall"):
        ap.add_argument("-" + k, type=float, required=True)
    ap.add_argument("-width", type=float, default=10.0)
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

    # time-averaged solid fraction profile, 0.5 mm bins
    edges = np.arange(0, 0.030 + 1e-12, 0.0005)
    prof = np.zeros(len(edges) - 1)
    wd = [c for (t, c), w in zip(dumps, win) if w]
    for c in wd:
        prof += np.array([np.sum(slab_volume(c["z"], c["radius"], edges[i], edges[i + 1]))
                          for i in range(len(edges) - 1)]) / (A * 0.0005)
    prof /= len(wd)
    overlap = max(max_overlap(c) for c in wd[::max(1, len(wd) // 10)])
    sup = np.array([wall_support(c) for c in wd])
    sup_bottom, sup_side = float(sup[:, 0].mean()), float(sup[:, 1].mean())
    # particle velocity fluctuation: rms of |v| over the particles and the dumps of the window
    v_rms = math.sqrt(float(np.mean([np.mean(c["vx"] ** 2 + c["vy"] ** 2 + c["vz"] ** 2) for c in wd])))

    # pressure
    fv = lambda n: os.path.join(a.run, "postProcessing", n, "0", "surfaceFieldValue.dat")
    ti, pi_ = read_fv(fv("pInlet"))
    ta, pa = read_fv(fv("pAbove"))
    m = min(len(ti), len(ta))
    if m == 0 or np.max(np.abs(ti[:m] - ta[:m])) > 1e-9:
        print("FAIL: %s: pressure samples missing or not at the same times" % name)
        return 1
    rho_f, g = ref.RHO_F, ref.G
    dp = rho_f * (pi_[:m] - pa[:m]) - rho_f * g * Z_ABOVE
    pw = (ti[:m] >= a.tstart - 1e-9) & (ti[:m] <= a.tend + 1e-9)
    dp_sim, dp_sem = float(dp[pw].mean()), batch_sem(dp[pw])
    dp_weight = (ref.RHO_P - rho_f) * g * vs / A
    dp_rel = (dp_sim - dp_weight) / dp_weight
    e_eq, e_rz = ref.eps_drag_equilibrium(a.U, a.drag), ref.eps_richardson_zaki(a.U)
    n_last = len(dumps[-1][1]["z"])

    res = os.path.join(a.run, "results")
    os.makedirs(res, exist_ok=True)
    with open(os.path.join(res, "result.csv"), "w") as f:
        f.write(HEADER + "\n")
        f.write("%s,%s,%.3f,%.4f,%.4f,%.4f,%.4f,%.3f,%.3f,%.4f,%.1f\n" % (
            a.method, a.modelType, a.U, eps_sim, eps_sem, e_eq, e_rz, dp_sim, dp_weight, dp_rel, a.wall))
    with open(os.path.join(res, "details.csv"), "w") as f:
        f.write("method,modelType,U,eps_plateau,eps_plateau_sem,H_c_mm,H_c_sem_mm,eps_drift,dp_sem,max_overlap_pct_d,"
                "support_bottom_Pa,side_wall_normal_Pa,v_rms_mm_s,n_particles_start,n_particles_end,n_dumps_window,n_dp_samples_window,tstart,tend\n")
        f.write("%s,%s,%.3f,%.4f,%.4f,%.3f,%.3f,%.4f,%.3f,%.3f,%.3f,%.3f,%.3f,%d,%d,%d,%d,%g,%g\n" % (
            a.method, a.modelType, a.U, eps_pl, eps_pl_sem, 1e3 * hc_mean, 1e3 * hc_sem, drift, dp_sem, 100 * overlap,
            sup_bottom, sup_side, 1e3 * v_rms, n0, n_last, int(win.sum()), int(pw.sum()), a.tstart, a.tend))
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
          "distributor carries %.2f Pa, side-wall normal %.2f Pa; max overlap %.2f %% d; wall %.0f s"
          % (name, eps_sim, eps_sem, a.drag, e_eq, eps_sim - e_eq, e_rz, eps_pl, 1e3 * hc_mean, drift, dp_sim, dp_sem,
             dp_weight, 100 * dp_rel, sup_bottom, sup_side, 100 * overlap, a.wall))
    if a.mode == "short":
        ok = True
        def check(cond, what):
            nonlocal ok
            ok &= cond
            print("%s %s: %s" % ("PASS" if cond else "FAIL", name, what))
        check(n_last == n0, "particles kept (%d at the start, %d at the end)" % (n0, n_last))
        check(abs(dp_rel) <= 0.05, "frictional pressure drop %.2f Pa within 5 %% of the bed's buoyant weight "
              "%.2f Pa (%+.2f %%)" % (dp_sim, dp_weight, 100 * dp_rel))
        h_packed = vs / (A * (1 - 0.40))   # m: ref.height for this run's solid and tube
        check(hc_mean > 1.1 * h_packed, "bed expanded: H_c %.2f mm above 1.1 x the packed height %.2f mm "
              "(eps 0.40)" % (1e3 * hc_mean, 1e3 * h_packed))
        check(abs(eps_sim - e_eq) <= 0.05, "bed voidage %.4f within 0.05 of the drag-law equilibrium %.4f "
              "(the start is at 0.727)" % (eps_sim, e_eq))
        return 0 if ok else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
