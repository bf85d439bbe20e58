#!/usr/bin/python3
"""settlingVelocity.py RUN [RUN ...] [-window T0 T1]: the mean settling velocity of the particles of
each run (the mean of v_z over all particles and the dumps in the window, from RUN/post/dump*),
for the settling-suspension comparison of coarse-graining factors (results/coarseGraining.md):

    ./Allrun -method bigParticle -modelType A -U 0.0001 -mode short -cg F      (F = 1, 2, 3)
    ./settlingVelocity.py runs/bigParticle_A_U0.0001_short runs/bigParticle_A_U0.0001_short_cg2 ...

With U = 0.0001 m/s (no flow to speak of) the start state, a suspension of solid fraction 0.27,
settles; the default window 0.02-0.10 s is after the start from rest (the particles reach their
hindered velocity in about 0.01 s) and before the sediment at the bottom holds most of them.
"""
import glob, os, sys

import numpy as np


def mean_vz(run, t0, t1, dem_dt=1e-5):
    """(mean v_z, number of particles, number of dumps) over the dumps with t0 <= t <= t1"""
    values, n, dumps = [], 0, 0
    for f in glob.glob(os.path.join(run, "post", "dump*.liggghts")):
        lines = open(f).read().split("\n")
        t = int(lines[1]) * dem_dt
        if not t0 <= t <= t1:
            continue
        n = int(lines[3])
        columns = lines[8].split()[2:]
        data = np.array([[float(x) for x in l.split()] for l in lines[9:9 + n]])
        values.append(data[:, columns.index("vz")].mean())
        dumps += 1
    return (float(np.mean(values)) if values else float("nan")), n, dumps


def main(args):
    t0, t1 = 0.02, 0.10
    if "-window" in args:
        i = args.index("-window"); t0, t1 = float(args[i + 1]), float(args[i + 2]); del args[i:i + 3]
    reference = None
    for run in args:
        v, n, dumps = mean_vz(run, t0, t1)
        reference = v if reference is None else reference
        print("%s: %d particles, mean v_z over %d dumps in %g-%g s: %.5f m/s (%+.1f %% of the first run)"
              % (os.path.basename(run.rstrip("/")), n, dumps, t0, t1, v, 100 * (v / reference - 1)))


if __name__ == "__main__":
    main(sys.argv[1:])
