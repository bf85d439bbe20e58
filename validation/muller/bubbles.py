#!/usr/bin/python3
"""bubbles.py -- the bubbles of a Mueller-bed run against Darton et al.'s bubble size; usage and
method: etc/python/muller_bubbles.py (the project's library)."""
import os, sys

# the project's Python library, etc/python (COARSEDEM_DIR: this file may run from a copy of its folder)
sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."), "etc", "python"))
import muller_bubbles  # noqa: E402

if __name__ == "__main__":
    muller_bubbles.main()
