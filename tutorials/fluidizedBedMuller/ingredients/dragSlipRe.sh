# dragSlipRe: the Di Felice drag with its Reynolds number from the interstitial slip velocity
# (Re = |u_r| d / nu, eq. A7 of Zhang et al. 2023 as printed) in place of Di Felice's (1994)
# superficial one (alpha |u_r| d / nu). Why: at the bed's voidage the printed form gives about a
# third less drag (src/openfoam/forceModels/DiFeliceDrag.C), so less lift of the particles where the
# gas streams. Applied by Allrun -ingredient dragSlipRe to a case directory ($1).
set -e
sed -i 's/^DiFeliceDragProps .*/DiFeliceDragProps   { reynoldsNumber slip; }/' "$1/constant/couplingProperties"
grep -q 'reynoldsNumber slip' "$1/constant/couplingProperties"
