# cfdStep1.5OneCorrector: the CFD step 1.5 times as long (27 DEM steps of 1e-5 s, 2.7e-4 s, in place of
# 18, 1.8e-4 s) and one PISO pressure corrector in place of two. Why: issue 44 (half the cost of a
# validation run) measured these two as the only fluid-side settings that cut the demo's time loop
# (0.74 and 0.90 of it, bench/README.md "CFD step and pressure correctors"), with no difference a 0.1 s
# demo can show; a 5 s window against the tutorial's decides whether the bed's time averages stay
# within their batch errors. Not a circulation ingredient: a cost one. Applied by Allrun -ingredient
# cfdStep1.5OneCorrector to a case directory ($1).
set -e
sed -i 's/^couplingInterval .*/couplingInterval    27;                 \/\/ ingredient cfdStep1.5OneCorrector: CFD 2.7e-4 s/' "$1/constant/couplingProperties"
sed -i 's/^\( *\)nCorrectors .*/\1nCorrectors      1;   \/\/ ingredient cfdStep1.5OneCorrector/' "$1/system/fvSolution"
grep -q '^couplingInterval    27;' "$1/constant/couplingProperties"
grep -q 'nCorrectors      1;' "$1/system/fvSolution"
