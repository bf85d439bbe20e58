"""dem_series.py -- reading a coupled run's time series: LIGGGHTS' particle dumps, the samples of
OpenFOAM function objects, the DEM walls' forces; batch means of a series.

Used by the liquid-bed and binary-bed post-processing (tutorials/liquidFluidizedBed,
tutorials/binaryBedKhan)."""
import glob
import math
import os
import re

import numpy as np

NB = 5   # batches of the batch-means error


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


def read_fv(path, column=1):
    """(times, values of the given column) of a function object's file: a surfaceFieldValue file, or
    forces' force.dat, whose vectors are in parentheses (v1912: total, pressure, viscous, so the viscous
    z force is column 9). Its last line may be cut short (the run was killed while writing it): left
    out; a bad line anywhere else is an error naming the file."""
    t, v = [], []
    with open(path) as f:
        lines = [l for l in f if l.strip() and not l.startswith("#")]
    for i, line in enumerate(lines):
        s = line.replace("(", " ").replace(")", " ").split()
        try:
            ti, vi = float(s[0]), float(s[column])
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


def read_wall_forces(run, demdt):
    """(t, columns) of post/wallForce.txt (fix ave/time of DEM/tubeWalls.liggghts): z forces of the
    walls wz0 (distributor) wz1 wx0 wx1 wy0 wy1, then the side walls' normal forces. A continued run
    (binaryBedKhan -continue) keeps each earlier start's file as post/wallForce.part<N>.txt, since
    LIGGGHTS starts the file anew: the parts in order, then wallForce.txt, each step from the last
    file that has it (a continued start recomputes the steps after its restart)."""
    post = os.path.join(run, "post")
    parts = sorted(glob.glob(os.path.join(post, "wallForce.part*.txt")),
                   key=lambda p: int(re.search(r"part(\d+)\.txt$", p).group(1)))
    by_step = {}
    for path in parts + [os.path.join(post, "wallForce.txt")]:
        if not os.path.isfile(path):
            continue
        with open(path) as f:
            for line in f:
                if line.startswith("#") or not line.strip():
                    continue
                v = line.split()
                if len(v) == 11:
                    by_step[int(v[0])] = [float(x) for x in v]
    a = np.array([by_step[k] for k in sorted(by_step)])
    if a.ndim != 2 or len(a) == 0:
        raise ValueError("%s: no wall-force samples" % os.path.join(post, "wallForce.txt"))
    return a[:, 0] * demdt, a[:, 1:]


def wall_force_share(wf, weight):
    """The walls' share of a bed's buoyant weight over wall-force samples wf (read_wall_forces'
    columns, the window's rows): the mean of their z forces (the first six columns) over the weight,
    and its batch-means error."""
    z = wf[:, :6].sum(axis=1)
    return float(z.mean()) / weight, batch_sem(z) / weight
