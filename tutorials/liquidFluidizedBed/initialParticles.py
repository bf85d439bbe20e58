#!/usr/bin/python3
"""initialParticles.py -- the start state of liquidFluidizedBed: 1146 spheres of d = 1 mm at random,
non-overlapping positions (random sequential addition, fixed seed), as LIGGGHTS commands.

    initialParticles.py [-cg F] [-width W] [-species small] > DEM/particles.in

-cg F (coarse graining, Radl et al. 2011 as Weaver & Miskovic 2023 use it): round(1146 / F^3) grains
of d = F mm in the same box, with the same rejection distance in grain diameters (1.02 d): the
same solid volume within the rounding (F = 2: 143 grains, -0.17 %; F = 3: 42 grains, -1.0 %).
-width W: a tube W mm wide (default 10) with (W/10)^2 times the particles, the same solid fraction.
-species small: the binary bed's small species instead (Table III: 42441 spheres of 0.3 mm, the same
solid volume 600 mm3), in the same box: the same solid fraction, 0.273.

The centres are drawn uniformly in the box 0.5 < x, y < 9.5 mm, 0.5 < z < 21.5 mm (no particle
touches a wall) and a draw closer than 1.02 d to a placed centre is rejected. The particles fill
22 mm: solid fraction 600 mm3 / (100 mm2 x 22 mm) = 0.273 (voidage 0.727), a suspension looser
than every bed of the tutorial (equilibrium voidage 0.50-0.59), so every run settles onto its
equilibrium from above, as a sediment builds a fluidized bed from below. A lattice start was tried
first and kept its layers: its planes of 9 x 9 particles settled as plates with water gaps between
them and did not mix in 1 s (README). The same file serves every run (fixed seed).
"""
import random, sys

CG = float(sys.argv[sys.argv.index("-cg") + 1]) if "-cg" in sys.argv else 1.0
WIDTH = float(sys.argv[sys.argv.index("-width") + 1]) * 1e-3 if "-width" in sys.argv else 10e-3
SMALL = "-species" in sys.argv and sys.argv[sys.argv.index("-species") + 1] == "small"
N0, D0 = (42441, 0.3e-3) if SMALL else (1146, 1e-3)   # Table III of Zhang et al. (2023)
N, D, RHO_P = round(N0 * (WIDTH / 10e-3) ** 2 / CG ** 3), CG * D0, 2000.0
LO, HI_XY, HI_Z, GAP = D / 2, WIDTH - D / 2, 22e-3 - D / 2, 1.02 * D
rng = random.Random(20231130)
cell = GAP                                    # cell list of edge >= the rejection distance
grid = {}
sites = []
while len(sites) < N:
    p = (rng.uniform(LO, HI_XY), rng.uniform(LO, HI_XY), rng.uniform(LO, HI_Z))
    key = tuple(int(c // cell) for c in p)
    ok = True
    for i in (-1, 0, 1):
        for j in (-1, 0, 1):
            for k in (-1, 0, 1):
                for q in grid.get((key[0] + i, key[1] + j, key[2] + k), ()):
                    if sum((a - b) ** 2 for a, b in zip(p, q)) < GAP * GAP:
                        ok = False
                        break
                if not ok: break
            if not ok: break
        if not ok: break
    if ok:
        grid.setdefault(key, []).append(p)
        sites.append(p)
print("# %d spheres, d = %g m, %g kg/m3: random sequential addition (initialParticles.py)" % (N, D, RHO_P))
for x, y, z in sites:
    print("create_atoms 1 single %.9g %.9g %.9g units box" % (x, y, z))
print("set group all diameter %g density %g" % (D, RHO_P))
