# oneCorrector: one PISO pressure corrector per CFD step in place of two, the CFD step (1.8e-4 s, the
# paper's Courant limit) kept. A cost ingredient of issue 44, not a circulation one: the demo's time
# loop at 0.90 of the tutorial's (bench/README.md "CFD step and pressure correctors").
# Why it may leave the bed alone (written before the run): the step is unchanged, so no Courant number
# above 1; the momentum matrix is dominated by the implicit drag in every cell with particles (Ksl/rho
# against 1/dt there), so the neighbour terms that PISO's second corrector re-evaluates are small, and
# each step still ends with a flux that satisfies continuity to the pressure tolerance.
# The rule that decides (written before the run, 2026-12-07, issue 44): the run goes to 10 s on one
# rank with the binaries of the tutorial's reference run (e7bab9d, /work/m44), cut into the four 2 s
# windows 2-4 ... 8-10 s (validation/muller/windows.py), and is judged by samePhysics.py -windows
# against the reference's four (validation/muller/results/medium/windows/bigParticle_dx1_U0.9_medium_w*).
# The tutorial takes one corrector only if (a) the test says NO CHANGE DETECTED, (b) at most two of
# the 14 quantities alone sit at the smallest p four and four windows give (0.029: about 0.4 are
# expected there by chance; the CFD-step pair had five), and (c) the mean pressure drop and expansion
# of the windows differ by at most a quarter of the windows' spread. Otherwise it keeps two.
# Applied by Allrun -ingredient oneCorrector to a case directory ($1).
set -e
sed -i 's/^\( *\)nCorrectors .*/\1nCorrectors      1;   \/\/ ingredient oneCorrector/' "$1/system/fvSolution"
grep -q 'nCorrectors      1;' "$1/system/fvSolution"
