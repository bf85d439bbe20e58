#!/usr/bin/python3
"""Where the gas streams through a fluidized bed, from one written time of a coarseDemFoam run.

    gasBypass.py CASE TIME [-dense ALPHA]

Reads CASE/TIME/{Co, alpha, U, alphaPBinned} (ascii or binary): the cell Courant number (OpenFOAM's
CourantNo function object with the run's CFD step as deltaT), the gas fraction, the gas velocity and
the particle fraction binned by particle centre (binnedParticleFields on). Prints, for the dense
cells (gas fraction below ALPHA, default 0.6), how many hold no particle centre and their mean
upward gas velocity against the others', and where the cells above Courant 1 (and 0.8) are.
The question it answers: does the gas meet drag in the cells where the particles are? With alpha_p
smoothed and the drag left in the cells of the particle centres, it does not in the dense cells
that hold none, and streams through them (validation/muller/results/medium/README.md).

The Courant number is not written by the run; in a copy of the case (system, constant and the time):
    sed -i 's/^deltaT .*/deltaT <CFD step>;/' system/controlDict
    postProcess -func CourantNo -time TIME
"""
import os
import sys

import numpy as np

TOP = os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(TOP, "etc", "python"))
from foam_fields import FieldFormatError, read_internal_field  # noqa: E402


def main():
    args = sys.argv[1:]
    dense_below = 0.6
    if "-dense" in args:
        i = args.index("-dense")
        dense_below = float(args[i + 1])
        args = args[:i] + args[i + 2:]
    if len(args) != 2:
        sys.exit(__doc__)
    case, time = args
    try:
        # the gas fraction gives the number of cells (a uniform alpha would not: refused)
        field = {"alpha": read_internal_field(os.path.join(case, time, "alpha"))}
        for f in ("Co", "U", "alphaPBinned"):
            field[f] = read_internal_field(os.path.join(case, time, f), len(field["alpha"]))
    except FieldFormatError as e:
        sys.exit(f"gasBypass.py: {e}")
    co, alpha, uz, binned = field["Co"], field["alpha"], field["U"][:, 2], field["alphaPBinned"]
    dense = alpha < dense_below
    bare = binned == 0
    print(f"{case} at t = {time}: {len(alpha)} cells, Courant number max {co.max():.3f}")
    print(f"dense cells (gas fraction < {dense_below}): {dense.sum()}, {(dense & bare).sum()} without a particle "
          f"centre ({100 * (dense & bare).sum() / max(dense.sum(), 1):.1f} %)")
    if (dense & bare).any() and (dense & ~bare).any():
        print(f"dense cells without / with a particle centre: mean upward gas velocity {uz[dense & bare].mean():.2f} / "
              f"{uz[dense & ~bare].mean():.2f} m/s, mean gas fraction {alpha[dense & bare].mean():.3f} / "
              f"{alpha[dense & ~bare].mean():.3f}")
        # a looser packing lets more gas through whatever the drag (Ergun: permeability ~ e^3/(1-e)^2):
        # the two compared at the same gas fraction
        edges = np.arange(0.30, dense_below + 1e-9, 0.05)
        for lo, hi in zip(edges[:-1], edges[1:]):
            inbin = dense & (alpha >= lo) & (alpha < hi)
            if (inbin & bare).any() and (inbin & ~bare).any():
                print(f"  gas fraction {lo:.2f}-{hi:.2f}: {(inbin & bare).sum()} / {(inbin & ~bare).sum()} cells, "
                      f"upward gas velocity {uz[inbin & bare].mean():.2f} / {uz[inbin & ~bare].mean():.2f} m/s")
    for limit in (1.0, 0.8):
        above = co > limit
        if not above.any():
            print(f"cells above Courant {limit:g}: none")
            continue
        print(f"cells above Courant {limit:g}: {above.sum()}, {(above & dense).sum()} dense, "
              f"{(above & bare).sum()} without a particle centre; gas fraction {alpha[above].min():.2f}-"
              f"{alpha[above].max():.2f}, upward gas velocity {uz[above].min():.2f}-{uz[above].max():.2f} m/s")


if __name__ == "__main__":
    main()
