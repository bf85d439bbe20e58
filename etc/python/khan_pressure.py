"""khan_pressure.py -- the binary bed's frictional pressure drop from the inlet pressure samples of
every start of a run (tutorials/binaryBedKhan/postprocess.py), the gaps in a sample series, and the
fluid's shear on the tube's side walls, the part of that pressure drop the particles do not take."""
import os

import numpy as np

import foam_fields
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


def fluid_wall_shear(run, times, tstart, tend, model_a, shape, dx):
    """The fluid's shear force on the tube's side walls along z (N) at each written time of the window,
    as the solver's momentum equation puts it there: the laplacian's wall flux
    rho_f nu sw (u_z - 0) / (dx / 2) dx^2 over each wall face of the uniform block of shape (nx, ny, nz)
    cells of size dx, x fastest (no-slip walls; sw = alpha in Model A, 1 in Model B). The transposed
    stress part is left out: its z part at a wall face is nu du_n/dz with u_n = 0 on the wall.
    times: (t, folder name) of the run's written times; a run on several ranks is read from its
    processor folders where a time is not reconstructed; a written time without U or alpha is passed
    over. Returns (t, F) arrays."""
    nx, ny, nz = shape
    n = nx * ny * nz
    i, j = np.arange(n) % nx, (np.arange(n) // nx) % ny
    faces = (i == 0).astype(int) + (i == nx - 1) + (j == 0) + (j == ny - 1)   # a corner cell has two
    out_t, out_f = [], []
    for t, d in times:
        if not (tstart - 1e-9 <= t <= tend + 1e-9):
            continue
        u, alpha = os.path.join(run, d, "U"), os.path.join(run, d, "alpha")
        if all(os.path.isfile(f) or os.path.isfile(f + ".gz") for f in (u, alpha)):
            U, a = foam_fields.read_internal_field(u, n), foam_fields.read_internal_field(alpha, n)
        else:
            U, a = (foam_fields.read_decomposed_field(run, d, f, n) for f in ("U", "alpha"))
            if U is None or a is None:
                continue
        uz = U[:, 2]
        sw = a if model_a else 1.0
        out_t.append(t)
        out_f.append(float(np.sum(faces * ref.RHO_F * ref.NU * sw * uz / (0.5 * dx) * dx * dx)))
    return np.array(out_t), np.array(out_f)
