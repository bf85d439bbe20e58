#!/usr/bin/python3
"""initialParticles.py -- the start state of binaryBedKhan as a LIGGGHTS data file (read_data).

    initialParticles.py MODE > DEM/particles.data        MODE: demo, short, long or full

Zhang et al., Phys. Fluids 35, 113330 (2023), Table III: 1146 spheres of 1 mm (atom type 1, "big")
and 42441 of 0.3 mm (type 2, "small"), 2000 kg/m3, in the 10 x 10 x 120 mm tube. Centres are drawn
uniformly and a draw closer than 1.02 (r_i + r_j) to a placed centre, or closer than its radius to
a wall, is rejected (random sequential addition, fixed seed): no particle overlaps another or a
wall.

- full: both species mixed over the whole tube, as the paper ("the particles are uniformly
  distributed in the tube initially"): solid fraction 0.05 per species.
- short (and long): pre-segregated, as the steady state is: the big species in 0 < z < 22 mm (solid fraction
  0.27, about the densest random sequential fill that works here: 0.30 did not fit;
  liquidFluidizedBed starts so too), the small one above it in 22 < z < 52 mm (0.20). Both layers start looser than their fluidized equilibrium at 0.010-0.020
  m/s (big 0.44-0.56, small 0.09-0.25; validation/khan/references.py), so each settles onto its
  layer from above.
- demo: as short with an eighth of the small species (5305) in 22 < z < 25.75 mm (0.20).
"""
import math, random, sys

# the tube (m), particle density, the least centre distance in units of r_i + r_j; Table III species
TUBE = (0.010, 0.010, 0.120)
RHO_P, GAP = 2000.0, 1.02
TABLE3 = (("big", 1, 1.0e-3, 1146), ("small", 2, 0.3e-3, 42441))


def species_layers(mode):
    """[(type, d, N, z_lo, z_hi)] of the start state of a mode: each species' centres in its slab."""
    if mode == "full":
        return [(t, d, n, 0.0, TUBE[2]) for _, t, d, n in TABLE3]
    if mode in ("short", "long"):
        return [(1, 1.0e-3, 1146, 0.0, 0.022), (2, 0.3e-3, 42441, 0.022, 0.052)]
    if mode == "demo":
        return DEMO
    raise SystemExit("initialParticles.py: unknown mode '%s' (demo short long full)" % mode)


DEMO = [(1, 1.0e-3, 1146, 0.0, 0.022), (2, 0.3e-3, 5305, 0.022, 0.02575)]


def place(layers, seed):
    """Random sequential addition of every species into its slab, in the order given. Each placed
    species has a cell list of its own (edge: GAP x its diameter), so a small sphere is checked
    against the few small neighbours of its own cells and the big ones within reach."""
    rng = random.Random(seed)
    grids, out = [], []                       # (cell edge, radius, {cell: [centres]}) per species
    for typ, d, n, zlo, zhi in layers:
        r = 0.5 * d
        mine = (GAP * d, r, {})
        grids.append(mine)
        lo = (r, r, zlo + r)
        hi = (TUBE[0] - r, TUBE[1] - r, zhi - r)
        reach = [(g, int(math.ceil(GAP * (r + rg) / edge)), (GAP * (r + rg)) ** 2) for edge, rg, g in
                 ((e, rr, gg) for e, rr, gg in grids)]
        placed = tries = 0
        while placed < n:
            tries += 1
            if tries > 200 * n:
                raise SystemExit("initialParticles.py: could not place %d spheres of %g m in z %g..%g m "
                                 "(%d placed)" % (n, d, zlo, zhi, placed))
            p = tuple(rng.uniform(a, b) for a, b in zip(lo, hi))
            if any(overlaps(p, g, edge, m, dmin2) for (g, m, dmin2), (edge, _, _) in zip(reach, grids)):
                continue
            mine[2].setdefault(tuple(int(c // mine[0]) for c in p), []).append(p)
            out.append((typ, d, p))
            placed += 1
    return out


def overlaps(p, grid, edge, m, dmin2):
    """Whether a centre of the cell list grid (cell edge edge) lies within sqrt(dmin2) of p; the
    cells within m of p's cell are searched."""
    ci, cj, ck = (int(c // edge) for c in p)
    x, y, z = p
    for i in range(ci - m, ci + m + 1):
        for j in range(cj - m, cj + m + 1):
            for k in range(ck - m, ck + m + 1):
                for q in grid.get((i, j, k), ()):
                    if (x - q[0]) ** 2 + (y - q[1]) ** 2 + (z - q[2]) ** 2 < dmin2:
                        return True
    return False


def main():
    mode = sys.argv[1] if len(sys.argv) > 1 else "short"
    layers = species_layers(mode)
    atoms = place(layers, 20231130)
    print("LIGGGHTS data file: binaryBedKhan start state, mode %s (initialParticles.py)" % mode)
    print()
    print("%d atoms" % len(atoms))
    print("2 atom types")
    print()
    for lo_hi, name in zip(TUBE, ("x", "y", "z")):
        print("0 %g %slo %shi" % (lo_hi, name, name))
    print()
    print("Atoms")
    print()
    for i, (typ, d, (x, y, z)) in enumerate(atoms, 1):
        print("%d %d %g %g %.9g %.9g %.9g" % (i, typ, d, RHO_P, x, y, z))


if __name__ == "__main__":
    main()
