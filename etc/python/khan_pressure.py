"""khan_pressure.py -- the binary bed's frictional pressure drop from the inlet pressure samples of
every start of a run (tutorials/binaryBedKhan/postprocess.py), and the gaps in a sample series."""
import numpy as np

import khan_references as ref
from dem_series import function_series


def frictional_dp(run):
    """(times, rho_f p_inlet - rho_f g L) from every start's pInlet files (dem_series.function_series)."""
    t, p = function_series(run, "pInlet")
    return t, ref.RHO_F * p - ref.RHO_F * ref.G * ref.HEIGHT


def sample_gaps(t):
    """(from, to) of each step of a sample series longer than twice its median step."""
    steps = np.diff(t)
    if not len(steps):
        return []
    usual = float(np.median(steps))
    return [(float(t[i]), float(t[i + 1])) for i in np.nonzero(steps > 2 * usual)[0]]
