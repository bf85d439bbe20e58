"""khan_pressure.py -- the binary bed's frictional pressure drop from the inlet pressure samples of
every start of a run (tutorials/binaryBedKhan/postprocess.py), and the gaps in a sample series."""
import glob
import os
import re

import numpy as np

import khan_references as ref
from dem_series import read_fv


def pressure_files(run):
    """The pInlet files of every start in the order they were written: by start folder, then
    surfaceFieldValue.dat before surfaceFieldValue_<t>.dat (OpenFOAM's name for a second file in
    the same folder, a later start from the same write time), those by their time."""
    def order(path):
        base = os.path.basename(path)
        m = re.match(r"surfaceFieldValue_([-+0-9.eE]+)\.dat$", base)
        return (float(os.path.basename(os.path.dirname(path))), 1 if m else 0, float(m.group(1)) if m else 0.0)
    files = glob.glob(os.path.join(run, "postProcessing", "pInlet", "*", "surfaceFieldValue*.dat"))
    return sorted((f for f in files if re.match(r"surfaceFieldValue(_[-+0-9.eE]+)?\.dat$", os.path.basename(f))),
                  key=order)


def frictional_dp(run):
    """(times, rho_f p_inlet - rho_f g L) from every start's pInlet files (pressure_files; a later
    start's samples replace the earlier ones from its first sample on)."""
    t_all, p_all = np.zeros(0), np.zeros(0)
    for f in pressure_files(run):
        t, p = read_fv(f)
        if len(t):
            keep = t_all < t[0] - 1e-12
            t_all, p_all = np.concatenate([t_all[keep], t]), np.concatenate([p_all[keep], p])
    return t_all, ref.RHO_F * p_all - ref.RHO_F * ref.G * ref.HEIGHT


def sample_gaps(t):
    """(from, to) of each step of a sample series longer than twice its median step."""
    steps = np.diff(t)
    if not len(steps):
        return []
    usual = float(np.median(steps))
    return [(float(t[i]), float(t[i + 1])) for i in np.nonzero(steps > 2 * usual)[0]]
