#!/usr/bin/python3
"""postprocess.py -- species-resolved layers and pressure of one binaryBedKhan run.

    postprocess.py RUN -method M -U U -mode demo|short|long|full -tstart T0 -tend T1 -demdt DT

Reads the particle dumps (RUN/post/dump*.liggghts: id, type, x, y, z, radius), the pressure on the
inlet face (RUN/postProcessing/pInlet/<start>/surfaceFieldValue*.dat), the window means of p and
alphaP (pMean, alphaPMean of the fieldAverage function object) and alphaP at the last written time
(a run on several ranks: reconstructed, as Allrun does), the solver log (wall time) and the case's
own entries (background fields, Young's modulus, ranks), and writes RUN/results/:

- profiles.csv: per 1 mm cell layer z, each species' alpha_p (time mean over the window and its
  batch-means standard error), their sum, the method's own alpha_p (alphaPMean, cross-section mean),
  the pressure and its frictional part;
- layers.csv: per species its plateau alpha_p (+- sem), interior, bottom, top, mean height (+- sem),
  the alpha_p the pressure slope gives over the interior, and the references of its U;
- bed.csv: the whole bed's frictional pressure drop (+- sem) against its buoyant weight, the mixing
  region, the window (window_s: from its first to its last dump), the wall time (wall_s: from the
  solver log's starts, pauses and stretches computed twice left out, as validation/muller/summary.py
  counts it; the summed wall_seconds.txt only where there is no log), the case (background
  fields on/off, Young's modulus, MPI ranks), the stage costs (coupling share of the stage timers,
  DEM / fluid and coupling / fluid) and the commit(s) of commit.txt: so a copy of results/ is all
  validation/khan/compare.py needs;
- axis_end.csv: alpha_p along the tube's axis at the last dump / written time (Zhang et al. Fig. 16);
- (bed.csv) the largest overlap of two particles, in % of the smaller one's diameter, at the
  window's first, middle and last dump (a check that the DEM sees every contact);
- (bed.csv) the solver's own per-species binning (alphaPBinned.type1, .type2 of binnedSpeciesFields,
  at the last written time) against this script's binning of the dump of that time: how many
  particles of each species lie in another cell (from the volume that differs), and how many have a
  dumped centre within 1e-6 m of a cell face, where the dump's rounding may move them (-1: no fields);
  a WARNING when more moved than that;
- (bed.csv) the fluid's shear force on the tube's side walls over the buoyant weight
  (fluid_wall_shear_share, +- sem, from the written times in the window: fluid_wall_shear_writes) and
  what the bed's balance leaves, dp_balance_residual = (dp - weight)/weight + walls' share - shear:
  the frictional pressure drop carries the particles' weight less the walls' support, and the fluid's
  own friction on the walls (2.4-3.2 % of the weight at 0.025 m/s in the 10 mm tube); nan without
  the walls' forces;
- series.csv: per dump, each species' count, mean height, highest particle and count in the top cell
  layer, and the pressure drop;
- messages.txt: the WARNING lines (also printed).

Definitions (independent of the void-fraction method: particles binned by the cell of their centre):
- alpha_p,s(z_k) = sum of the volumes of species s whose centre lies in the cell layer k
  (k dx <= z < (k + 1) dx, dx = 1 mm) / (A dx), A = 10 x 10 mm; the species is told by its radius
  (the Table III diameter nearest to it).
- Window: the dumps with tstart <= t <= tend. Time means over them; standard errors by batch means
  (the window's dumps in 5 consecutive batches: sem = std(batch means) / sqrt(5)). A run whose last
  dump lies more than one dump interval before tend stopped early: FAIL (continue it first).
- A species' layer: from its time-mean profile, the heights z05 and z95 below which 5 % and 95 % of
  its volume lie; the interior is the central 60 % of z05..z95 (the layers of cells whose centres lie
  there). plateau = the mean alpha_p,s over the interior; its sem from the same interior mean per
  batch. top (bottom) = walking up (down) from the interior's densest cell, the first height where
  alpha_p,s falls below half the plateau, linear between cell centres (the distributor, 0, when it
  never does below; a dense layer with a long dilute tail has its top inside the interior).
- mean height: the volume-weighted mean centre height of the species per dump, time mean (+- sem);
  its drift: the mean over the window's second half minus that over its first half (a layer still
  settling or expanding drifts by more than its sem).
- Mixing region: the cell layers where both species' alpha_p exceeds 10 % of its own plateau. Its
  width per dump (the number of such layers x dx, from the instantaneous binned profiles) is averaged
  over the window (mixing_width_mm, +- sem); mixing_width_mean_profile_mm is the same count on the
  time-mean profiles (wider when the interface moves).
- dp = rho_f p_inlet - rho_f g L (p is kinematic and holds the hydrostatic part; the outlet holds
  p = 0; L = 120 mm): the frictional pressure drop over the tube. dp_weight = (rho_p - rho_f) g V_s/A
  from the dumped radii (both species). p_frictional(z) = rho_f pMean(z) - rho_f g (L - z), and
  alpha_p from its slope over a layer's interior: -(d p_frictional/dz) / ((rho_p - rho_f) g).
- Axis: the four cells around x = y = 5 mm (the tube's axis, on their common edge), per cell layer:
  the method's alphaP at the last written time, and each species binned in those cells at the last dump.

- Pressure samples: each start of the solver writes postProcessing/pInlet/<its start time>/, in
  surfaceFieldValue.dat, or surfaceFieldValue_<t>.dat when that folder holds one already (a second
  start from the same write time); a later start's samples replace the earlier ones from its first
  sample on. A gap in the window's samples (a step of more than twice the usual one) is a WARNING.

Bad input is reported by name and time, never clipped (WARNING lines, messages.txt):
- a species whose particles are smaller than the method's kernel allows: bigParticle when its
  expanded diameter 2 n R is below the cell size (its kernel is its host cell: the centre method; the
  paper's statement for its small particles); diffusion when the bandwidth b is more than 6 of its
  diameters (the b = 6 d rule: its alpha_p is smeared over b/d of its diameters); sizeAwareDiffusion
  when its class's bandwidth is below the cell size (no smoothing beyond a cell);
- a layer that leaves the tube: a species with particles in the top cell layer (z > L - dx), or fewer
  particles than at the start, named with the first dump time it happens and whether in the window.
"""
import argparse, math, os, re, sys

import numpy as np

# the project's Python library, etc/python (COARSEDEM_DIR: this file may run from a copy of the tutorial):
# the references of the two species; the dump, function-object and wall-force readers and batch means
# of the monodisperse bed's post-processing; the field reader; contacts; the wall time and stage
# timers of a run from its solver log, as the Mueller validation reads them
sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."), "etc", "python"))
import khan_references as ref  # noqa: E402
import foam_fields as _fields  # noqa: E402
from dem_series import NB, batch_sem, read_dumps, read_wall_forces, wall_force_share  # noqa: E402
from khan_pressure import fluid_wall_shear, frictional_dp, sample_gaps  # noqa: E402
from khan_layers import layer  # noqa: E402
from particle_pairs import close_pairs  # noqa: E402
from solver_log import NOT_COUPLING, run_wall, stage_times  # noqa: E402

NX = NY = 10
NZ = 120
DX = ref.HEIGHT / NZ
SPECIES = list(ref.SPECIES)                 # big, small
MIX_FRACTION = 0.10                         # mixing region: both above 10 % of their plateau
DUMP_TOL = 1e-6                             # m: the rounding of a dumped coordinate, at most (6 digits)


def species_index(radius):
    """Index into SPECIES of each particle: the Table III diameter nearest to its own."""
    ds = np.array([ref.SPECIES[s][0] for s in SPECIES])
    return np.argmin(np.abs(2 * radius[:, None] - ds[None, :]), axis=1)


def binned(c, sp, cells=None):
    """alpha_p per cell layer of each species (array [species, NZ]) from one dump; cells: a mask of
    the particles to count and the area they are counted over, default all and A."""
    keep = np.ones(len(c["z"]), bool) if cells is None else cells[0]
    area = ref.A if cells is None else cells[1]
    k = np.clip((c["z"] // DX).astype(int), 0, NZ - 1)
    v = 4.0 / 3 * math.pi * c["radius"] ** 3
    return np.array([np.bincount(k[keep & (sp == s)], weights=v[keep & (sp == s)], minlength=NZ)
                     for s in range(len(SPECIES))]) / (area * DX)


def batches(x):
    """The batch means of a series (first axis: dumps)."""
    return [b.mean(axis=0) for b in np.array_split(np.asarray(x), NB)]


def sem_of(x):
    """Batch-means standard error of a series, element-wise along the first axis."""
    x = np.asarray(x)
    if len(x) < 2 * NB:
        return np.full(x.shape[1:], np.nan) if x.ndim > 1 else float("nan")
    return np.std(batches(x), axis=0, ddof=1) / math.sqrt(NB)


def drift(x):
    """Mean of the window's second half minus that of its first half (stationarity)."""
    x = np.asarray(x)
    h = len(x) // 2
    return float(x[h:].mean() - x[:h].mean()) if h else float("nan")


def read_internal_field(path):
    """The internalField of a volScalarField on the 10 x 10 x 120 block, ascii or binary, as an array."""
    return _fields.read_internal_field(path, NX * NY * NZ)


def layers_of(field):
    """Cross-section mean per cell layer of a field on the 10 x 10 x 120 block (x fastest)."""
    return field.reshape(NZ, NY, NX).mean(axis=(1, 2))


def written_times(run):
    out = []
    for d in os.listdir(run):
        try:
            t = float(d)
        except ValueError:
            continue
        if t > 0 and os.path.isdir(os.path.join(run, d)):
            out.append((t, d))
    return sorted(out)


def coupling_entries(run):
    """The entries of RUN/constant/couplingProperties this script needs (word or number), by a
    plain regular-expression read: voidFractionModel, smoothingModel, the bigParticle expansion
    factor, the diffusion bandwidth and the size-aware bandwidth / d."""
    with open(os.path.join(run, "constant", "couplingProperties")) as f:
        text = re.sub(r"//.*", "", f.read())
    def entry(pattern, default=None):
        m = re.search(pattern, text)
        return m.group(1) if m else default
    return dict(model=entry(r"\bvoidFractionModel\s+(\w+)\s*;"),
                smoothing=entry(r"\bsmoothingModel\s+(\w+)\s*;", "off"),
                n=float(entry(r"bigParticleProps\s*\{[^}]*expansionFactor\s+([0-9.eE+-]+)", "0")),
                b=float(entry(r"diffusionProps\s*\{[^}]*bandwidth\s+([0-9.eE+-]+)", "nan")),
                b_over_d=float(entry(r"sizeAwareDiffusionProps\s*\{[^}]*bandwidthOverD\s+([0-9.eE+-]+)", "nan")))


def kernel_messages(entries, first, t0):
    """WARNING lines for the species too small for the method's kernel (see the module's doc)."""
    out = []
    sp = species_index(first["radius"])
    for s, name in enumerate(SPECIES):
        if not (sp == s).any():
            continue
        d = float(2 * first["radius"][sp == s].mean())
        what = "species %s (d = %.2f mm, %d particles, present at t = %g s)" % (name, 1e3 * d, int((sp == s).sum()), t0)
        if entries["model"] == "bigParticle" and entries["smoothing"] == "off" and entries["n"] >= 1 and \
                2 * entries["n"] * 0.5 * d < DX:
            out.append("%s: its particles are smaller than the bigParticle kernel reach allows: the expanded "
                       "diameter 2 n R = %.3f mm (n = %g) is below the cell size %.1f mm, so its kernel is its "
                       "host cell (the centre method) for every one of them" % (what, 1e3 * entries["n"] * d,
                                                                                entries["n"], 1e3 * DX))
        if entries["smoothing"] == "diffusion" and entries["b"] > 6 * d * (1 + 1e-9):
            out.append("%s: its particles are smaller than the diffusion bandwidth allows: b = %.2f mm is %.1f of "
                       "its diameters (the b = 6 d rule of Sun & Xiao 2015 holds for d >= %.2f mm), so its alpha_p "
                       "is smeared over %.1f diameters" % (what, 1e3 * entries["b"], entries["b"] / d,
                                                           1e3 * entries["b"] / 6, entries["b"] / d))
        if entries["smoothing"] == "sizeAwareDiffusion" and entries["b_over_d"] * d < DX:
            out.append("%s: its particles are smaller than the size-aware diffusion allows: its bandwidth "
                       "%.2f mm (%g d) is below the cell size %.1f mm, so it is not smoothed beyond its cells"
                       % (what, 1e3 * entries["b_over_d"] * d, entries["b_over_d"], 1e3 * DX))
    return out


def leaving_messages(dumps, tstart, tend):
    """WARNING lines for the species that reach the top cell layer or lose particles, with the first
    dump time; and (t, per species: count, particles in the top layer) per dump for series.csv."""
    n0 = None
    first_top, first_loss, per_dump = {}, {}, []
    for t, c in dumps:
        sp = species_index(c["radius"])
        counts = [int((sp == s).sum()) for s in range(len(SPECIES))]
        in_top = [int(((sp == s) & (c["z"] > ref.HEIGHT - DX)).sum()) for s in range(len(SPECIES))]
        n0 = n0 or counts
        per_dump.append((counts, in_top))
        for s, name in enumerate(SPECIES):
            if in_top[s] and name not in first_top:
                first_top[name] = (t, in_top[s], counts[s])
            if counts[s] < n0[s] and name not in first_loss:
                first_loss[name] = (t, n0[s] - counts[s])
    out = []
    where = lambda t: "in the averaging window %g..%g s" % (tstart, tend) if tstart <= t <= tend else \
        "before the averaging window" if t < tstart else "after the averaging window"
    for name, (t, k, n) in first_top.items():
        out.append("species %s leaves the tube: %d of its %d particles in the top cell layer (z > %.0f mm) at "
                   "t = %g s (%s); its layer is held by the top wall from then on, not a free layer"
                   % (name, k, n, 1e3 * (ref.HEIGHT - DX), t, where(t)))
    for name, (t, k) in first_loss.items():
        out.append("species %s lost %d particles by t = %g s (%s)" % (name, k, t, where(t)))
    return out, per_dump


def pair_overlap(c):
    """(largest overlap of two particles / the smaller one's diameter, pairs above 5 % of it) of a
    dump (the touching pairs from a cell list: etc/python/particle_pairs.py)."""
    r = c["radius"]
    a, b, d = close_pairs(np.stack([c["x"], c["y"], c["z"]], axis=1), r)
    rel = (r[a] + r[b] - d) / (2 * np.minimum(r[a], r[b]))
    return (max(0.0, float(rel.max())) if len(rel) else 0.0), int((rel > 0.05).sum())


def stage_costs(segs):
    """(coupling share, DEM / fluid, coupling / fluid) from the stage timers of the solver log's
    segments (summary.log_segments, as run_wall returns them). Coupling:
    every stage of the last "Stage timers" line but DEM, fluid and fields; its share is over the sum
    of all stages. A continued run's log holds one start per (re)start, each timing from its own
    start: their last lines are summed (a -continue at the end time adds a start of no steps, whose
    line alone would be its set-up); pauses left out (summary.log_segments). nan without any line."""
    nan = float("nan")
    stages = stage_times(segs)
    if not stages:
        return nan, nan, nan
    total = sum(stages.values())
    coupling = sum(v for k, v in stages.items() if k not in NOT_COUPLING)
    fluid = stages.get("fluid", 0.0)
    return (coupling / total if total > 0 else nan, stages.get("DEM", 0.0) / fluid if fluid > 0 else nan,
            coupling / fluid if fluid > 0 else nan)


def commit_of(run):
    """The commits the run was made with (commit.txt, one line per start: commit [date]), joined by
    '+', or 'unknown'."""
    path = os.path.join(run, "commit.txt")
    seen = []
    for line in open(path) if os.path.isfile(path) else []:
        if line.split() and line.split()[0] not in seen:
            seen.append(line.split()[0])
    return "+".join(seen) or "unknown"


def case_entries(run):
    """(background fields on/off, Young's modulus in Pa, MPI ranks, neighbour-list style, model A or B)
    of the run's own case files: couplingProperties' backgroundFields and modelType, DEM/in.liggghts'
    youngsModulus and `neighbor` style, decomposeParDict's numberOfSubdomains (1 without one)."""
    def find(rel, pattern, default):
        path = os.path.join(run, rel)
        if not os.path.isfile(path):
            return default
        m = re.search(pattern, re.sub(r"//.*", "", open(path).read()), re.M)
        return m.group(1) if m else default
    background = find(os.path.join("constant", "couplingProperties"), r"^\s*backgroundFields\s+(\w+)\s*;", "off")
    young = float(find(os.path.join("DEM", "in.liggghts"), r"youngsModulus\s+peratomtype\s+([0-9.eE+-]+)", "nan"))
    ranks = int(find(os.path.join("system", "decomposeParDict"), r"numberOfSubdomains\s+(\d+)\s*;", "1"))
    neighbour = find(os.path.join("DEM", "in.liggghts"), r"^\s*neighbor\s+\S+\s+(\w+)", "unknown")
    model = find(os.path.join("constant", "couplingProperties"), r"^\s*modelType\s+(\w+)\s*;", "A")
    return ("on" if background in ("on", "true", "yes") else "off"), young, ranks, neighbour, model


def write_csv(path, header, rows, fmt):
    with open(path, "w") as f:
        f.write(header + "\n")
        for r in rows:
            f.write(fmt % tuple(r) + "\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run")
    for k in ("method", "mode"):
        ap.add_argument("-" + k, required=True)
    for k in ("U", "tstart", "tend", "demdt"):
        ap.add_argument("-" + k, type=float, required=True)
    a = ap.parse_args()
    name = os.path.basename(os.path.normpath(a.run))
    res = os.path.join(a.run, "results")
    os.makedirs(res, exist_ok=True)
    dumps = read_dumps(a.run, a.demdt)
    if not dumps:
        print("FAIL: %s: no particle dumps in %s/post" % (name, a.run))
        return 1
    warnings = kernel_messages(coupling_entries(a.run), dumps[0][1], dumps[0][0])
    leave, per_dump = leaving_messages(dumps, a.tstart, a.tend)
    warnings += leave

    z = (np.arange(NZ) + 0.5) * DX
    win = [(t, c) for t, c in dumps if a.tstart - 1e-9 <= t <= a.tend + 1e-9]
    if len(win) < 2 * NB:
        print("FAIL: %s: only %d particle dumps in the window %g..%g s (at least %d needed)"
              % (name, len(win), a.tstart, a.tend, 2 * NB))
        return 1
    every = float(np.median(np.diff([t for t, _ in win])))
    if win[-1][0] < a.tend - every - 1e-9:
        print("FAIL: %s: the run stopped at t = %g s (its last particle dump), before its window's end %g s: "
              "continue it first (Allrun ... -continue)" % (name, win[-1][0], a.tend))
        return 1
    window_s = win[-1][0] - win[0][0]
    background, young, ranks, neighbour, model = case_entries(a.run)
    wall, _, _, segs, _ = run_wall(a.run)      # the log read once: wall time and stage timers
    costs = stage_costs(segs)
    profs, heights = [], []                     # [dump][species][NZ], [dump][species]
    for t, c in win:
        sp = species_index(c["radius"])
        profs.append(binned(c, sp))
        v = c["radius"] ** 3
        heights.append([float(np.sum(c["z"][sp == s] * v[sp == s]) / max(np.sum(v[sp == s]), 1e-300))
                        for s in range(len(SPECIES))])
    profs, heights = np.array(profs), np.array(heights)
    mean, sem = profs.mean(axis=0), sem_of(profs)
    bprofs = batches(profs)
    lay = [layer(z, mean[s], [b[s] for b in bprofs]) for s in range(len(SPECIES))]

    # mixing region: instantaneous per dump, averaged; and on the time-mean profiles
    thr = [MIX_FRACTION * l["plateau"] for l in lay]
    both = lambda p: (p[0] > thr[0]) & (p[1] > thr[1])
    widths = np.array([both(p).sum() * DX for p in profs])
    mix_mean_prof = both(mean)
    mix_zone = (float(z[mix_mean_prof][0] - 0.5 * DX), float(z[mix_mean_prof][-1] + 0.5 * DX)) \
        if mix_mean_prof.any() else (float("nan"), float("nan"))

    # contacts: the largest overlap of two particles at the window's first, middle and last dump
    overlaps = [pair_overlap(win[i][1]) for i in sorted({0, len(win) // 2, len(win) - 1})]
    worst_overlap, worst_pairs = max(o[0] for o in overlaps), max(o[1] for o in overlaps)
    if worst_overlap > 0.10:
        # the cause the run's own DEM script points to: multi-level lists that find no contacts, or
        # contacts too soft for the bed's collisions
        cause = ("contacts are missed: DEM/in.liggghts uses 'neighbor ... multi', a stub in LIGGGHTS 3.8.0 "
                 "(use bin)" if neighbour == "multi" else
                 "the contacts (E = %g Pa, neighbour lists '%s') are too soft for the bed's collisions: "
                 "a stiffer -young, or a calmer bed" % (young, neighbour))
        warnings.append("particles overlap by up to %.0f %% of the smaller diameter (%d pairs above 5 %%) in the "
                        "window: %s" % (100 * worst_overlap, worst_pairs, cause))

    # pressure: the inlet series, the window means of p and alphaP
    t_dp, dp = frictional_dp(a.run)
    pw = (t_dp >= a.tstart - 1e-9) & (t_dp <= a.tend + 1e-9)
    if pw.sum() < 2 * NB:
        print("FAIL: %s: only %d pressure samples in the window" % (name, pw.sum()))
        return 1
    gaps = sample_gaps(t_dp[pw])
    if gaps:
        warnings.append("%d gap(s) in the inlet pressure samples of the window (%s): the pressure drop is the mean of "
                        "the samples there are" % (len(gaps), ", ".join("%g..%g s" % g for g in gaps[:5])))
    dp_sim, dp_sem = float(dp[pw].mean()), batch_sem(dp[pw])
    first = dumps[0][1]
    sp0 = species_index(first["radius"])
    vol = [float(np.sum(4.0 / 3 * math.pi * first["radius"][sp0 == s] ** 3)) for s in range(len(SPECIES))]
    dp_ref = ref.dp_weight(sum(vol))
    weight = dp_ref * ref.A                     # N
    # where the weight goes: the walls' z forces on the particles (DEM/tubeWalls.liggghts), their
    # window mean over the bed's buoyant weight; nan for a run made before the walls stored them
    wall_share = wall_share_sem = float("nan")
    if os.path.isfile(os.path.join(a.run, "post", "wallForce.txt")):
        tw, wf = read_wall_forces(a.run, a.demdt)
        ww = (tw >= a.tstart - 1e-9) & (tw <= a.tend + 1e-9)
        if ww.sum() >= 2 * NB:
            wall_share, wall_share_sem = wall_force_share(wf[ww], weight)
        if wall_share > 0.03:
            warnings.append("the walls carry %.1f %% of the bed's buoyant weight in the window (distributor %.1f %%): "
                            "a packed or jammed layer, not a fluidized one" % (100 * wall_share,
                                                                              100 * float(wf[ww, 0].mean()) / weight))
    times = written_times(a.run)
    last_t, last_dir = times[-1] if times else (float("nan"), None)
    # the fluid's shear on the side walls: the part of the frictional pressure drop that is not drag on
    # the particles (the bed's balance: dp A = (weight - walls' support) + fluid wall shear)
    t_sh, f_sh = fluid_wall_shear(a.run, times, a.tstart, a.tend, model == "A", (NX, NY, NZ), DX)
    shear_share = float(f_sh.mean()) / weight if len(f_sh) else float("nan")
    shear_sem = batch_sem(f_sh) / weight if len(f_sh) >= 2 * NB else float("nan")
    p_z = alpha_solver = np.full(NZ, np.nan)
    if last_dir and os.path.isfile(os.path.join(a.run, last_dir, "pMean")):
        p_z = ref.RHO_F * layers_of(read_internal_field(os.path.join(a.run, last_dir, "pMean")))
        alpha_solver = layers_of(read_internal_field(os.path.join(a.run, last_dir, "alphaPMean")))
    else:
        warnings.append("no window means (pMean, alphaPMean) at the last written time %s: p(z) and the method's "
                        "alpha_p(z) left out" % last_dir)
    p_fric = p_z - ref.RHO_F * ref.G * (ref.HEIGHT - z)
    dpdz_alpha = []
    for l in lay:
        zi, pi = z[l["inner"]], p_fric[l["inner"]]
        ok = len(zi) >= 2 and np.isfinite(pi).all()
        dpdz_alpha.append(float(-np.polyfit(zi, pi, 1)[0] / ((ref.RHO_P - ref.RHO_F) * ref.G)) if ok else float("nan"))

    # the solver's own per-species binning (binnedSpeciesFields) against this script's, at the last
    # written time and the dump of that time: the particles binned into another cell than the solver's
    # (from the volume that differs), against those whose dumped centre lies within DUMP_TOL of a
    # cell face, where the dump's rounding may put it either side
    fields_check = [(-1, -1)] * len(SPECIES)
    at_write = [c for t, c in dumps if abs(t - last_t) < 0.5 * a.demdt]
    for s, name_s in enumerate(SPECIES):
        path = os.path.join(a.run, last_dir, "alphaPBinned.type%d" % (s + 1)) if last_dir else ""
        if at_write and os.path.isfile(path):
            c = at_write[0]
            k = (np.clip((c["x"] // DX).astype(int), 0, NX - 1) + NX * np.clip((c["y"] // DX).astype(int), 0, NY - 1)
                 + NX * NY * np.clip((c["z"] // DX).astype(int), 0, NZ - 1))
            m = species_index(c["radius"]) == s
            v = 4.0 / 3 * math.pi * c["radius"][m] ** 3
            mine = np.bincount(k[m], weights=v, minlength=NX * NY * NZ) / DX ** 3
            moved = int(round(np.abs(mine - read_internal_field(path)).sum() * DX ** 3 / v.mean() / 2))
            near = sum(np.abs(c[q][m] / DX - np.round(c[q][m] / DX)) * DX < DUMP_TOL for q in ("x", "y", "z"))
            fields_check[s] = (moved, int((near > 0).sum()))
    for s, (moved, near) in enumerate(fields_check):
        if moved > near:
            warnings.append("the solver's alphaPBinned.type%d at t = %g s has %d particles of species %s in other cells "
                            "than the dump of that time, more than the %d whose dumped centre lies within %g m of a "
                            "cell face" % (s + 1, last_t, moved, SPECIES[s], near, DUMP_TOL))

    # alpha_p on the axis at the end: the method's alphaP (last written time), the species at the last dump
    axis_solver = np.full(NZ, np.nan)
    if last_dir and os.path.isfile(os.path.join(a.run, last_dir, "alphaP")):
        f = read_internal_field(os.path.join(a.run, last_dir, "alphaP")).reshape(NZ, NY, NX)
        axis_solver = f[:, NY // 2 - 1:NY // 2 + 1, NX // 2 - 1:NX // 2 + 1].mean(axis=(1, 2))
    t_end, c_end = dumps[-1]
    near = (np.abs(c_end["x"] - 0.5 * ref.WIDTH) < DX) & (np.abs(c_end["y"] - 0.5 * ref.WIDTH) < DX)
    axis_species = binned(c_end, species_index(c_end["radius"]), (near, 4 * DX * DX))

    # the balance's residual, of the weight: what neither the particles' weight (less the walls'
    # support) nor the fluid's wall shear accounts for in the frictional pressure drop
    balance = (dp_sim - dp_ref) / dp_ref + wall_share - shear_share

    # files
    cols = ",".join("alpha_%s,alpha_%s_sem" % (s, s) for s in SPECIES)
    write_csv(os.path.join(res, "profiles.csv"),
              "z_mm,%s,alpha_total,alphaP_method_mean,p_mean_Pa,p_frictional_Pa" % cols,
              [[1e3 * z[k]] + [x for s in range(len(SPECIES)) for x in (mean[s][k], sem[s][k])] +
               [mean[:, k].sum(), alpha_solver[k], p_z[k], p_fric[k]] for k in range(NZ)],
              "%.1f" + ",%.5f,%.5f" * len(SPECIES) + ",%.5f,%.5f,%.3f,%.3f")
    rows = []
    for s, name_s in enumerate(SPECIES):
        d = ref.SPECIES[name_s][0]
        l = lay[s]
        rows.append([name_s, 1e3 * d, int((sp0 == s).sum()), 1e9 * vol[s], l["plateau"], l["sem"],
                     1e3 * l["interior_lo"], 1e3 * l["interior_hi"], 1e3 * l["bottom"], 1e3 * l["top"],
                     1e3 * heights[:, s].mean(), 1e3 * sem_of(heights[:, s]), 1e3 * drift(heights[:, s]), dpdz_alpha[s],
                     ref.alpha_richardson_zaki(a.U, d), ref.alpha_drag_equilibrium(a.U, d)])
    write_csv(os.path.join(res, "layers.csv"),
              "species,d_mm,N,V_s_mm3,alpha_p_plateau,alpha_p_sem,interior_lo_mm,interior_hi_mm,bottom_mm,top_mm,"
              "mean_height_mm,mean_height_sem_mm,mean_height_drift_mm,alpha_p_from_dp,alpha_p_richardson_zaki,"
              "alpha_p_drag_equilibrium",
              rows, "%s,%.1f,%d,%.3f,%.5f,%.5f,%.1f,%.1f,%.2f,%.2f,%.3f,%.3f,%.3f,%.5f,%.5f,%.5f")
    write_csv(os.path.join(res, "bed.csv"),
              "method,U,mode,tstart,tend,window_s,n_dumps_window,n_dp_samples_window,dp_pa,dp_sem_pa,dp_weight_pa,"
              "dp_rel_err,mixing_width_mm,mixing_width_sem_mm,mixing_width_mean_profile_mm,mixing_lo_mm,mixing_hi_mm,"
              "t_end_dump,t_last_write,max_overlap_pct_d,n_pairs_overlap_over_5pct,binned_fields_moved_big,"
              "binned_fields_near_face_big,binned_fields_moved_small,binned_fields_near_face_small,wall_s,n_warnings,"
              "background,young_pa,ranks,coupling_share,dem_per_fluid,coupling_per_fluid,commit,wall_force_share,wall_force_share_sem,"
              "dem_dt_s,fluid_wall_shear_share,fluid_wall_shear_share_sem,fluid_wall_shear_writes,dp_balance_residual",
              [[a.method, a.U, a.mode, a.tstart, a.tend, window_s, len(win), int(pw.sum()), dp_sim, dp_sem,
                dp_ref, (dp_sim - dp_ref) / dp_ref, 1e3 * widths.mean(), 1e3 * sem_of(widths),
                1e3 * mix_mean_prof.sum() * DX, 1e3 * mix_zone[0], 1e3 * mix_zone[1], t_end, last_t,
                100 * worst_overlap, worst_pairs] + list(fields_check[0]) + list(fields_check[1]) + [wall, len(warnings), background, young, ranks] + list(costs) + [commit_of(a.run), wall_share, wall_share_sem, a.demdt,
                shear_share, shear_sem, len(f_sh), balance]],
              "%s,%.3f,%s,%g,%g,%g,%d,%d,%.3f,%.3f,%.3f,%.5f,%.2f,%.2f,%.1f,%.1f,%.1f,%g,%g,%.3f,%d,%d,%d,%d,%d,%.1f,%d,%s,%g,%d,"
              "%.4f,%.3f,%.4f,%s,%.5f,%.5f,%g,%.5f,%.5f,%d,%.5f")
    write_csv(os.path.join(res, "axis_end.csv"),
              "z_mm,alphaP_method_t%g,%s" % (last_t, ",".join("alpha_%s_binned_t%g" % (s, t_end) for s in SPECIES)),
              [[1e3 * z[k], axis_solver[k]] + [axis_species[s][k] for s in range(len(SPECIES))] for k in range(NZ)],
              "%.1f,%.5f" + ",%.5f" * len(SPECIES))
    series = []
    for (t, c), (counts, in_top) in zip(dumps, per_dump):
        sp = species_index(c["radius"])
        k = int(np.argmin(np.abs(t_dp - t))) if len(t_dp) else 0
        row = [t]
        for s in range(len(SPECIES)):
            m = sp == s
            row += [counts[s], 1e3 * float(c["z"][m].mean()) if m.any() else float("nan"),
                    1e3 * float((c["z"][m] + c["radius"][m]).max()) if m.any() else float("nan"), in_top[s]]
        row.append(dp[k] if len(t_dp) and abs(t_dp[k] - t) < 0.006 else float("nan"))
        series.append(row)
    write_csv(os.path.join(res, "series.csv"),
              "t," + ",".join("n_%s,mean_z_%s_mm,highest_%s_mm,n_%s_top_layer" % (s, s, s, s) for s in SPECIES) + ",dp_pa",
              series, "%.4f" + ",%d,%.3f,%.3f,%d" * len(SPECIES) + ",%.3f")
    with open(os.path.join(res, "messages.txt"), "w") as f:
        for w in warnings:
            f.write("WARNING %s: %s\n" % (name, w))

    for w in warnings:
        print("WARNING %s: %s" % (name, w))
    for s, name_s in enumerate(SPECIES):
        r = rows[s]
        print("%s: %-5s plateau alpha_p %.4f +- %.4f (Richardson-Zaki %.4f, drag equilibrium %.4f, pressure slope %.4f), "
              "layer %.1f..%.1f mm, mean height %.2f +- %.2f mm (drift in the window %+.2f mm)"
              % (name, name_s, r[4], r[5], r[14], r[15], r[13], r[8], r[9], r[10], r[11], r[12]))
    print("%s: the walls carry %.2f +- %.2f %% of the buoyant weight" % (name, 100 * wall_share, 100 * wall_share_sem))
    print("%s: the fluid's shear on the tube walls %.2f +- %.2f %% of the buoyant weight (%d written times); "
          "dp - weight + walls - shear = %+.2f %% of the weight" % (name, 100 * shear_share, 100 * shear_sem, len(f_sh),
                                                                    100 * balance))
    print("%s: frictional dp %.2f +- %.2f Pa against the buoyant weight %.2f Pa (%+.2f %%); mixing region %.2f +- %.2f mm "
          "(on the mean profiles %.1f mm, %.1f..%.1f mm); largest overlap %.2f %% d; window %g..%g s, %d dumps; wall %.0f s"
          % (name, dp_sim, dp_sem, dp_ref, 100 * (dp_sim - dp_ref) / dp_ref, 1e3 * widths.mean(), 1e3 * sem_of(widths),
             1e3 * mix_mean_prof.sum() * DX, 1e3 * mix_zone[0], 1e3 * mix_zone[1], 100 * worst_overlap, win[0][0],
             win[-1][0], len(win), wall))
    return 0


if __name__ == "__main__":
    sys.exit(main())
