#!/bin/bash
# validation/khan/collectWindow10.sh -- take finished long runs of tutorials/binaryBedKhan (window 3..13 s)
# into validation/khan/results/window10/runs/<run>/ (their build.txt, commit.txt and results/) and compare
# every run there (compare.py: window10/summary.csv, table.md, the figures). A run may sit in another
# tree (a copy made for the long runs): give its directory.
#
#   validation/khan/collectWindow10.sh RUN_DIR [RUN_DIR ...]
#   validation/khan/collectWindow10.sh -compare        only the comparison of what window10/runs holds
here="$(cd "$(dirname "$0")" && pwd)"
dest="$here/results/window10"
[ $# -gt 0 ] || { sed -n '2,8p' "$0"; exit 2; }
if [ "$1" != -compare ]; then
    for run in "$@"; do
        name=$(basename "$run")
        [ -d "$run/13" ] || [ -d "$run/processor0/13" ] ||
            { echo "collectWindow10.sh: $run has no write at 13 s (the long mode's end): not finished" >&2; exit 1; }
        [ -f "$run/results/layers.csv" ] ||
            { echo "collectWindow10.sh: $run has no results/layers.csv (run its Allrun ... -post first)" >&2; exit 1; }
        rm -rf "$dest/runs/$name"
        mkdir -p "$dest/runs/$name/results"
        cp "$run/build.txt" "$run/commit.txt" "$dest/runs/$name/"
        for f in axis_end.csv bed.csv layers.csv messages.txt profiles.csv series.csv; do
            [ -f "$run/results/$f" ] && cp "$run/results/$f" "$dest/runs/$name/results/"
        done
        echo "collectWindow10.sh: $name"
    done
fi
/usr/bin/python3 "$here/compare.py" "$dest" "$dest"/runs/*
