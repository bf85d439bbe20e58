# pressureTolerance1e-4: the pressure solved to a normalised residual of 1e-4 in place of 1e-6 (p and
# pFinal in system/fvSolution, GAMG; with one PISO corrector only pFinal is solved). A cost ingredient
# of issue 44: the pressure solve is about 40 % of the Mueller demo's fluid stage; from the demo's state
# (bench/tolerance_study.sh -setting pressure -values "1e-6 1e-8 1e-5 1e-4" -name
# tolerance_pressure_loose at 9c46d4c, serial, beside two binary-bed runs) it took 4.80 GAMG cycles per
# solve against 10.42 (1e-8: 17.26), and the demo's profiles differed from 1e-6's as much as 1e-8's did
# (bench/results/tolerance_pressure_loose.csv). Why 1e-4 and not 1e-5 (7.16 cycles): issue 44's cost
# target needs about a tenth of the Mueller loop (bench/cases: 0.55 of the baseline), which 1e-5 does
# not give; a choice by cost, judged by physics below.
# Why it may leave the bed alone (written before the run): the fluid fraction is not transported by
# the gas but set by the particles at every coupling, so a step's continuity error does not accumulate
# into a state; it is a flux error of that step. The demo's mean local continuity error per step,
# |ddt(alpha) + div(alpha phi)| dt averaged over the cells, was 1.7e-6 at 1e-4 against 2.1e-8 at 1e-6,
# about a thousandth of the fluid fraction's change per step where the bed moves (a particle crosses a
# 1.2 mm cell in some 40 steps). The drag, which sets the bed, takes the gas velocity from that flux.
# The rule that decides (written before the run, committed 2026-12-07 22:34 UTC in dacbbcc, issue 44; oneCorrector's and
# noMomentumPredictor's): the run goes to 10 s on one rank with main's build at 9c46d4c (whose solver
# differs from a1d4e4c's, that of the noMomentumPredictor run, only by the stage spread line, 7804068),
# cut into the four 2 s windows 2-4 ... 8-10 s (validation/muller/windows.py RUN 2 10 4), and is judged
# by samePhysics.py -windows against the tutorial's current reference, the noMomentumPredictor run's
# four windows (validation/muller/results/medium/windows/bigParticle_dx1_U0.9_medium_noMomentumPredictor_w*).
# The tutorial takes 1e-4 only if (a) the test says NO CHANGE DETECTED, (b) at most two of the 14
# quantities alone sit at the smallest p four and four windows give (0.03), and (c) the means of the
# windows' pressure drop and expansion differ by no more than 1 % of the weight and 2 % of the
# expansion. So that settings adopted one after another cannot drift step by step, (a)-(c) must hold
# also against the two-corrector reference's four windows (bigParticle_dx1_U0.9_medium_w*).
# Otherwise the tutorial keeps 1e-6.
# Decided 2026-12-07 23:41 UTC by that rule (validation/muller/results/medium/README.md, "The pressure
# to 1e-4"): the run (3537 s of solver wall, 22:35-23:41 UTC, beside a binary-bed run) against the
# noMomentumPredictor windows NO CHANGE DETECTED, p = 0.657, no quantity alone below p = 0.23,
# pressure drop -1.61 % against -1.73 % of the weight, expansion 1.543 against 1.551; against the
# two-corrector reference p = 0.486, none below 0.23, -1.61 % against -1.59 %, 1.543 against 1.560.
# The tutorial solves p to 1e-4 since then, so this ingredient now writes the tutorial's own setting;
# it stays for the run named after it.
# Applied by Allrun -ingredient pressureTolerance1e-4 to a case directory ($1).
set -e
sed -i 's/^\( *p  *{ solver GAMG; smoother GaussSeidel; \)tolerance 1e-6;/\1tolerance 1e-4;/' "$1/system/fvSolution"
grep -q '^ *p  *{ solver GAMG; smoother GaussSeidel; tolerance 1e-4;' "$1/system/fvSolution"
