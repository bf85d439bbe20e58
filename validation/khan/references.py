#!/usr/bin/python3
"""references.py -- reference numbers of the binary liquid-fluidized bed (binaryBedKhan), computed;
the formulas and their sources are in the project's library, etc/python/khan_references.py.

    references.py [-csv FILE] [U ...]     prints them per species (default U = 0.010 0.015 0.020
                                          0.025 m/s); -csv also writes them to FILE
"""
import os, sys

# the project's Python library, etc/python (COARSEDEM_DIR: this file may run from a copy of its folder)
sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."), "etc", "python"))
import khan_references  # noqa: E402

if __name__ == "__main__":
    sys.exit(khan_references.main(sys.argv[1:]))
