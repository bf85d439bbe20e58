# cfdStepHalf: the CFD step and coupling interval halved (15 DEM steps, 9e-5 s, in place of 30,
# 1.8e-4 s). Why: the drag on a particle is explicit in the gas state of the last coupling and the
# gas sees the particles of the last coupling; a lag that shortens the response of the dense
# regions to a passing bubble changes how much solid the wakes carry up. Applied by Allrun
# -ingredient cfdStepHalf to a case directory ($1).
set -e
sed -i 's/^couplingInterval .*/couplingInterval    15;                 \/\/ ingredient cfdStepHalf: CFD 9e-5 s/' "$1/constant/couplingProperties"
grep -q '^couplingInterval    15;' "$1/constant/couplingProperties"
