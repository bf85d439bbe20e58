#!/usr/bin/python3
"""stiffness.py -- does a softer contact stiffness, or a longer DEM step, change the binary bed? One run
against another that differs in that setting only; usage and method: etc/python/khan_stiffness.py.

    stiffness.py OUT SOFT_RUN STIFF_RUN       Young's modulus: the softer run first (OUT/stiffness.md)
    stiffness.py OUT COARSE_RUN FINE_RUN      the DEM step (same E): the longer step first (OUT/demStep.md)
"""
import os, sys

# the project's Python library, etc/python (COARSEDEM_DIR: this file may run from a copy of its folder)
sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."), "etc", "python"))
import khan_stiffness  # noqa: E402

if __name__ == "__main__":
    sys.exit(khan_stiffness.main(sys.argv[1:]))
