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


def function_files(run, name):
    """The files of a surfaceFieldValue function object NAME from every start of a run, in the order
    they were written: by start folder, then surfaceFieldValue.dat before surfaceFieldValue_<t>.dat
    (OpenFOAM's name for a second file in the same folder, a later start from the same write time),
    those by their time."""
    def order(path):
        base = os.path.basename(path)
        m = re.match(r"surfaceFieldValue_([-+0-9.eE]+)\.dat$", base)
        return (float(os.path.basename(os.path.dirname(path))), 1 if m else 0, float(m.group(1)) if m else 0.0)
    files = glob.glob(os.path.join(run, "postProcessing", name, "*", "surfaceFieldValue*.dat"))
    return sorted((f for f in files if re.match(r"surfaceFieldValue(_[-+0-9.eE]+)?\.dat$", os.path.basename(f))),
                  key=order)


def function_series(run, name):
    """(times, values) of a surfaceFieldValue function object NAME over every start of a run
    (function_files): a later start's samples replace the earlier ones from its first sample on."""
    t_all, v_all = np.zeros(0), np.zeros(0)
    for f in function_files(run, name):
        t, v = read_fv(f)
        if len(t):
            keep = t_all < t[0] - 1e-12
            t_all, v_all = np.concatenate([t_all[keep], t]), np.concatenate([v_all[keep], v])
    return t_all, v_all


def batch_sem(x, nb=NB):
    """The batch-means standard error of the mean of series x, in nb batches (nan below 2 nb samples)."""
    x = np.asarray(x)
    if len(x) < 2 * nb:
        return float("nan")
    means = [b.mean() for b in np.array_split(x, nb)]
    return float(np.std(means, ddof=1) / math.sqrt(nb))


def dem_script_step(run, script):
    """The DEM step (s) of the run's DEM script DEM/SCRIPT (its timestep line); None when the run has
    no such script or the script no such line (a kept copy of results/ alone)."""
    path = os.path.join(run, "DEM", script)
    if os.path.isfile(path):
        with open(path) as f:
            for line in f:
                if line.split()[:1] == ["timestep"]:
                    return float(line.split()[1])
    return None


def dem_time_anchor(run):
    """(DEM step, time) of the run's latest write that holds a DEM restart (<time>/dem.restart.step,
    in the case or in processor0): the DEM's step count at a time, for series that record steps,
    where the steps do not start at time 0 (a run from a state made with another DEM step).
    (0, 0.0) without such a write."""
    best = (0, 0.0)
    for f in glob.glob(os.path.join(run, "*", "dem.restart.step")) + \
            glob.glob(os.path.join(run, "processor0", "*", "dem.restart.step")):
        try:
            t = float(os.path.basename(os.path.dirname(f)))
            with open(f) as fh:
                step = int(fh.read().split()[0])
        except (ValueError, IndexError):
            continue
        if t >= best[1]:
            best = (step, t)
    return best


def read_post_series(run, name, ncols, demdt, anchor=(0, 0.0)):
    """(t, columns) of a DEM fix ave/time file post/NAME.txt of NCOLS values after the step. A continued
    run keeps each earlier start's file as post/NAME.part<N>.txt (etc/RunFunctions keepPostParts),
    since LIGGGHTS starts the file anew: the parts in order, then NAME.txt, each step from the last
    file that has it (a continued start recomputes the steps after its restart). The time of a step
    from anchor (a DEM step and its time: dem_time_anchor) and the DEM step demdt (ValueError when
    demdt is None: the run's step is not known)."""
    if demdt is None:
        raise ValueError("the run's DEM step is not known (no timestep line in its DEM script)")
    post = os.path.join(run, "post")
    parts = sorted(glob.glob(os.path.join(post, name + ".part*.txt")),
                   key=lambda p: int(re.search(r"part(\d+)\.txt$", p).group(1)))
    by_step = {}
    for path in parts + [os.path.join(post, name + ".txt")]:
        if not os.path.isfile(path):
            continue
        with open(path) as f:
            for line in f:
                if line.startswith("#") or not line.strip():
                    continue
                v = line.split()
                if len(v) == ncols + 1:
                    by_step[int(v[0])] = [float(x) for x in v]
    a = np.array([by_step[k] for k in sorted(by_step)])
    if a.ndim != 2 or len(a) == 0:
        raise ValueError("%s: no samples" % os.path.join(post, name + ".txt"))
    return anchor[1] + (a[:, 0] - anchor[0]) * demdt, a[:, 1:]


def read_wall_forces(run, demdt, anchor=(0, 0.0)):
    """(t, columns) of post/wallForce.txt (fix ave/time of DEM/tubeWalls.liggghts; read_post_series):
    z forces of the walls wz0 (distributor) wz1 wx0 wx1 wy0 wy1, then the side walls' normal forces."""
    return read_post_series(run, "wallForce", 10, demdt, anchor)


def wall_force_share(wf, weight):
    """The walls' share of a bed's buoyant weight over wall-force samples wf (read_wall_forces'
    columns, the window's rows): the mean of their z forces (the first six columns) over the weight,
    and its batch-means error."""
    z = wf[:, :6].sum(axis=1)
    return float(z.mean()) / weight, batch_sem(z) / weight
