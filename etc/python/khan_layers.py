"""khan_layers.py -- one species' layer in the binary bed from its time-mean alpha_p(z) profile:
interior, plateau (+- batch-means sem), bottom and top (tutorials/binaryBedKhan/postprocess.py)."""
import math

import numpy as np

import khan_references as ref
from dem_series import NB

NZ = 120                 # the tube's cells along z (tutorials/binaryBedKhan's mesh)
DX = ref.HEIGHT / NZ     # their height


def crossing(z, a, start, level, step):
    """Walking from index start by step (+1 up, -1 down), the height where a falls below level
    (linear between cell centres); the distributor (0) or the tube's top when it never does."""
    i = start
    while 0 <= i + step < len(a):
        if a[i + step] < level:
            f = (a[i] - level) / (a[i] - a[i + step]) if a[i] != a[i + step] else 0.5
            return z[i] + f * (z[i + step] - z[i])
        i += step
    return 0.0 if step < 0 else ref.HEIGHT


def layer(z, prof, batch_profiles):
    """Interior, plateau (+- sem), bottom and top of one species from its time-mean profile."""
    cum = np.cumsum(prof) / max(prof.sum(), 1e-300)
    z05 = float(z[min(np.searchsorted(cum, 0.05), len(z) - 1)])
    z95 = float(z[min(np.searchsorted(cum, 0.95), len(z) - 1)])
    lo, hi = z05 + 0.2 * (z95 - z05), z95 - 0.2 * (z95 - z05)
    inner = (z >= lo - 1e-12) & (z <= hi + 1e-12)
    if not inner.any():                                   # a layer thinner than a cell: its densest cell
        inner = prof == prof.max()
    plateau = float(prof[inner].mean())
    per_batch = [float(b[inner].mean()) for b in batch_profiles]
    sem = float(np.std(per_batch, ddof=1) / math.sqrt(NB)) if len(per_batch) == NB else float("nan")
    idx = np.nonzero(inner)[0]
    # the edges are walked to from the interior's densest cell: an edge cell of the interior may lie
    # below half the plateau itself (a dense layer with a long dilute tail inside the other species,
    # whose 5-95 % span is then mostly tail), and a walk from it would extrapolate past the cell
    densest = int(idx[np.argmax(prof[idx])])
    top = crossing(z, prof, densest, 0.5 * plateau, +1)
    bottom = crossing(z, prof, densest, 0.5 * plateau, -1)
    return dict(plateau=plateau, sem=sem, inner=inner, interior_lo=float(z[idx[0]] - 0.5 * DX),
                interior_hi=float(z[idx[-1]] + 0.5 * DX), top=top, bottom=bottom)
