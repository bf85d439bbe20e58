# cfdStepHalf: the CFD step and coupling interval halved (9 DEM steps of 1e-5 s, 9e-5 s, in place
# of 18, 1.8e-4 s; 15 of 6e-6 s in the run of validation/muller/results/ingredients). Why: the drag
# on a particle is explicit in the gas state of the last coupling and the gas sees the particles of
# the last coupling; a lag that shortens the response of the dense regions to a passing bubble
# changes how much solid the wakes carry up. Applied by Allrun -ingredient cfdStepHalf to a case
# directory ($1).
set -e
sed -i 's/^couplingInterval .*/couplingInterval    9;                  \/\/ ingredient cfdStepHalf: CFD 9e-5 s/' "$1/constant/couplingProperties"
grep -q '^couplingInterval    9;' "$1/constant/couplingProperties"
