#!/usr/bin/python3
"""references.py -- the reference numbers of liquidFluidizedBed (the drag laws' equilibrium voidage,
Richardson-Zaki, the bed's buoyant weight and heights), each formula with its source in the project's
library, etc/python/liquid_bed_references.py.

    references.py [U ...]      prints them (default U = 0.015 0.020 0.025 m/s) and writes
                               results/references.csv
"""
import os, sys

# the project's Python library, etc/python (COARSEDEM_DIR: this file may run from a copy of the tutorial)
sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."), "etc", "python"))
import liquid_bed_references  # noqa: E402

if __name__ == "__main__":
    liquid_bed_references.main(os.path.join(os.path.dirname(os.path.abspath(__file__)), "results", "references.csv"))
