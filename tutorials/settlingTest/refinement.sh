#!/bin/bash
# refinement.sh: the coarse sphere (d = 2 mm in 1 mm cells, d/dx = 2) with background fields, each run
# in its own copy of this tutorial under /tmp: the CFD step 1e-3 s (couplingInterval 200, the
# tutorial's) and 2.5e-4 s (50), the latter also with alphaRelaxationTime 1e-3 s; 0.3 s of fall, the
# DEM history every 50 DEM steps (so that one-step dips at the faces are sampled). Writes
# results/refinement.csv: terminal velocity against the ODE and the largest deviation from the mean
# velocity over the second half of the fall (compare.py -coarse), per run.
#   bash refinement.sh [METHOD ...]     default: divided centre
cd "$(dirname "$0")" || exit 1
here=$(pwd)
. "${COARSEDEM_DIR:-$(cd ../.. && pwd)}/etc/RunFunctions" || exit 1
methods=${*:-divided centre}
out="$here/results/refinement.csv"
{
    echo "# command: tutorials/settlingTest/refinement.sh $methods"
    echo "# commit: $(git -C "${COARSEDEM_DIR:-$here}" rev-parse --short HEAD 2>/dev/null) ($(date -u +%Y-%m-%d))"
    echo "method,couplingInterval,cfd_step_s,alphaRelaxationTime_s,u_sim,u_ode,rel_err,late_max_dev"
} > "$out"
for m in $methods; do
    for spec in "200 0" "50 0" "50 1e-3"; do
        set -- $spec
        d=$(mktemp -d "/tmp/coarsedem-refine-$m-ci$1.XXXXXX")
        cp -r "$here/." "$d" && cd "$d" && ./Allclean > /dev/null 2>&1
        cp -r 0.orig 0 && mkdir -p post results
        sed -i "s/^voidFractionModel .*/voidFractionModel   $m;/; s/^backgroundFields .*/backgroundFields    on;/; s/^couplingInterval .*/couplingInterval    $1;/" constant/couplingProperties
        [ "$2" != 0 ] && echo "alphaRelaxationTime $2;" >> constant/couplingProperties
        sed -i 's/^endTime .*/endTime         0.3;/' system/controlDict
        sed -i 's/fix             hist all print 200/fix             hist all print 50/' DEM/in.liggghts
        sed -i '/^blocks/s/(10 10 100)/(20 20 200)/' system/blockMeshDict
        blockMesh > log.blockMesh 2>&1 && coarseDemFoam > log.coarseDemFoam 2>&1 ||
            { echo "refinement.sh: $m couplingInterval $1 failed ($d/log.coarseDemFoam)" >&2; cd "$here"; continue; }
        /usr/bin/python3 compare.py . 0 A -coarse > log.compare 2>&1
        /usr/bin/python3 - "$m" "$1" "$2" results/summary.csv >> "$out" <<'PYEOF'
import csv, sys
m, ci, relax, path = sys.argv[1:5]
rows = {r["quantity"]: r for r in csv.DictReader(open(path))}
t = rows["terminal_velocity_m_per_s"]
u, ref = float(t["measured"]), float(t["reference"])
print("%s,%s,%g,%s,%.6g,%.6g,%.4e,%s" % (m, ci, 5e-6 * int(ci), relax, u, ref, (u - ref) / ref,
                                       rows["late_velocity_max_deviation_over_vt"]["measured"]))
PYEOF
        cd "$here" && rm -rf "$d"
    done
done
cat "$out"
