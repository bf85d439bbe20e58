#!/usr/bin/python3
"""Initial particle positions for the DPMFoam Mueller bed: a loose random packing without overlaps.

    makePositions.py <out file> [--n 9240] [--d 0.0012] [--box 0.010 0.044] [--seed 1]

N spheres of diameter d start on a lattice of spacing about 1.04 d filling the box (thickness x
width Lx x Ly, gravity -z) from the bottom (the top layer's sites picked at random), each moved at
random by up to +-0.25 d in x, y and z, and are then pushed apart pair by pair (and off the walls)
until no two overlap (the minimum centre distance, checked at the end, is at least d). For 9240
spheres of 1.2 mm in 10 x 44 mm: a layer about 41 mm deep, solid fraction about 0.46. (A fully
random start needs hundreds of push sweeps at this fraction; the jittered lattice needs about
100.) The bed settles and fluidizes during the start-up of the run. Deterministic for a given
seed. Writes an OpenFOAM vectorField file (manualInjection positionsFile).
"""
import sys
import numpy as np


def pairs_within(x, cut, lo, hi):
    """All pairs (i, j), i < j, of points x (N x 3) closer than cut; cell lists of size >= cut."""
    n = len(x)
    ncell = np.maximum(((hi - lo) / cut).astype(int), 1)
    c = np.minimum(((x - lo) / (hi - lo) * ncell).astype(int), ncell - 1)
    c = np.maximum(c, 0)
    lin = (c[:, 0] * ncell[1] + c[:, 1]) * ncell[2] + c[:, 2]
    order = np.argsort(lin, kind="stable")
    counts = np.bincount(lin, minlength=ncell.prod())
    m = counts.max()
    occ = -np.ones((ncell.prod(), m), dtype=np.int64)
    start = np.concatenate(([0], np.cumsum(counts)[:-1]))
    rank = np.arange(n) - start[lin[order]]
    occ[lin[order], rank] = order
    I, J = [], []
    offsets = [(0, 0, 0)] + [(a, b, e) for a in (-1, 0, 1) for b in (-1, 0, 1) for e in (-1, 0, 1)
                             if (a, b, e) > (0, 0, 0)]
    for o in offsets:
        cn = c + np.array(o)
        ok = np.all((cn >= 0) & (cn < ncell), axis=1)
        idx = np.nonzero(ok)[0]
        ln = (cn[idx, 0] * ncell[1] + cn[idx, 1]) * ncell[2] + cn[idx, 2]
        cand = occ[ln]                                   # len(idx) x m
        ii = np.repeat(idx, m)
        jj = cand.ravel()
        keep = jj >= 0
        if o == (0, 0, 0):
            keep &= jj > ii
        ii, jj = ii[keep], jj[keep]
        dist2 = np.sum((x[ii] - x[jj]) ** 2, axis=1)
        close = dist2 < cut * cut
        I.append(ii[close]); J.append(jj[close])
    return np.concatenate(I), np.concatenate(J)


def main():
    args = sys.argv[1:]
    if not args or args[0].startswith("-"):
        sys.exit(__doc__)
    out = args[0]
    opt = {"--n": "9240", "--d": "0.0012", "--seed": "1"}
    box = (0.010, 0.044)
    i = 1
    while i < len(args):
        if args[i] == "--box":
            box = (float(args[i + 1]), float(args[i + 2])); i += 3
        elif args[i] in opt:
            opt[args[i]] = args[i + 1]; i += 2
        else:
            sys.exit(f"makePositions.py: unknown option {args[i]}")
    n, d, seed = int(opt["--n"]), float(opt["--d"]), int(opt["--seed"])
    r = d / 2
    lx, ly = box
    s = 1.04 * d                                   # nominal lattice spacing
    nx, ny = int((lx - d) / s) + 1, int((ly - d) / s) + 1
    nz = -(-n // (nx * ny))
    gx, gy = np.linspace(r, lx - r, nx), np.linspace(r, ly - r, ny)
    gz = r + s * np.arange(nz)
    X, Y, Z = np.meshgrid(gx, gy, gz, indexing="ij")
    sites = np.stack([X.ravel(), Y.ravel(), Z.ravel()], axis=1)
    rng = np.random.default_rng(seed)
    full = sites[sites[:, 2] < gz[-1] - 1e-12]
    top = sites[sites[:, 2] >= gz[-1] - 1e-12]
    x = np.concatenate([full, top[rng.permutation(len(top))[:n - len(full)]]])
    lo = np.array([r, r, r])
    hi = np.array([lx - r, ly - r, gz[-1] + 0.3 * d])
    x = np.clip(x + (rng.random(x.shape) - 0.5) * 0.5 * d, lo, hi)
    target = d * (1 + 1e-3)                        # push apart to a small gap, then check >= d
    for it in range(5000):
        I, J = pairs_within(x, target, lo - r, hi + r)
        v = x[I] - x[J]
        dist = np.maximum(np.sqrt(np.sum(v * v, axis=1)), 1e-12)
        if len(I) == 0 or np.max(target - dist) < 0.5e-3 * d:
            break
        push = (0.5 * (target - dist) / dist)[:, None] * v
        disp = np.zeros_like(x)
        np.add.at(disp, I, push)
        np.add.at(disp, J, -push)
        x = np.clip(x + disp, lo, hi)
    I, J = pairs_within(x, 2 * d, lo - r, hi + r)
    dmin = np.min(np.sqrt(np.sum((x[I] - x[J]) ** 2, axis=1)))
    if dmin < d:
        sys.exit(f"makePositions.py: overlapping particles left after {it} sweeps (min distance {dmin / d} d)")
    phi = n * np.pi / 6 * d ** 3 / (lx * ly * (x[:, 2].max() + r))
    with open(out, "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class vectorField; object kinematicCloudPositions; }\n")
        f.write(f"// makePositions.py: {n} spheres d = {d} m, jittered lattice relaxed to no overlap, seed {seed}\n")
        f.write(f"{n}\n(\n")
        for p in x:
            f.write(f"({p[0]:.8e} {p[1]:.8e} {p[2]:.8e})\n")
        f.write(")\n")
    print(f"makePositions.py: {n} particles below z = {(x[:, 2].max() + r) * 1e3:.1f} mm (solid fraction {phi:.3f}), "
          f"{it} sweeps, min centre distance {dmin / d:.5f} d")


main()
