# gasSlip: the gas slips along every wall (slip in place of noSlip), in the case's 0/ and in the
# state's fields. Why: the bed is 10 mm deep on 8 cells; the gas's no-slip front and back walls
# slow the gas over a cell or two on each side, which shifts the drag, and so the particles' upflow,
# towards the mid-plane. Applied by Allrun -ingredient gasSlip to a case directory ($1).
set -e
for f in "$1"/[0-9]*/U; do   # 0/U and the state's time folder
    [ -f "$f" ] || continue
    LC_ALL=C sed -i 's/walls  { type noSlip; }/walls  { type slip; }/; /^    walls$/,/^    }$/ s/type            noSlip;/type            slip;/' "$f"
done
