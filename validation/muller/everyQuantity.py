#!/usr/bin/python3
"""everyQuantity.py -- every Mueller set-up on every MR profile and physics check, with the
recommendation rule; usage and method: etc/python/muller_every.py (the project's library)."""
import os, sys

# the project's Python library, etc/python (COARSEDEM_DIR: this file may run from a copy of its folder)
sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."), "etc", "python"))
import muller_every  # noqa: E402

if __name__ == "__main__":
    muller_every.main()
