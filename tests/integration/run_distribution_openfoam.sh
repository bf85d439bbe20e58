#!/bin/bash
# The particle-distribution case (Zhang et al. 2023 §V.A, mesh M2: dx = d) through the OpenFOAM
# path: LIGGGHTS holds the 8251 particles of tutorials/particleDistribution, coarseDemFoam computes
# alpha_p with the same method, and the field it writes must equal the standalone core's to
# round-off (mid-z layer, every cell). Methods: bigParticle n = 5 and divided.
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$top/etc/bashrc" || exit 1
. "$here/result.sh"   # result ok|fail, results_from, finish
work=$(mktemp -d /tmp/coarsedem-dist.XXXXXX)
trap 'rm -rf "$work"' EXIT
pd="$top/tutorials/particleDistribution"
make -s -C "$pd" > "$work/make.log" 2>&1 || { result fail "distribution via OpenFOAM: build of the standalone program"; finish; }
"$pd/build/particle_distribution" -m 2 -o "$work/standalone" > "$work/standalone.log" 2>&1 ||
    { result fail "distribution via OpenFOAM: standalone run"; finish; }

for method in bigParticle divided; do
    c="$work/case_$method"
    mkdir -p "$c/system" "$c/constant" "$c/0" "$c/DEM"
    cp "$top/tutorials/settlingTest/system/fvSchemes" "$top/tutorials/settlingTest/system/fvSolution" "$c/system/"
    cp "$top/tutorials/settlingTest/constant/transportProperties" "$top/tutorials/settlingTest/constant/turbulenceProperties" "$c/constant/"
    printf 'FoamFile { version 2.0; format ascii; class uniformDimensionedVectorField; object g; }\ndimensions [0 1 -2 0 0 0 0];\nvalue (0 0 0);\n' > "$c/constant/g"
    cat > "$c/system/blockMeshDict" <<'EOD'
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
scale 0.001;   // 160 d x 160 d x 4 d, d = 1 mm, cells of 1 d (mesh M2)
vertices ( (-80 -80 0) (80 -80 0) (80 80 0) (-80 80 0) (-80 -80 4) (80 -80 4) (80 80 4) (-80 80 4) );
blocks ( hex (0 1 2 3 4 5 6 7) (160 160 4) simpleGrading (1 1 1) );
boundary ( walls { type wall; faces ( (0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7) ); } );
EOD
    cat > "$c/system/controlDict" <<'EOD'
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application coarseDemFoam; startFrom startTime; startTime 0; stopAt endTime; endTime 1e-5; deltaT 1e-5;
writeControl timeStep; writeInterval 1; writeFormat ascii; writePrecision 17; timeFormat general; timePrecision 8;
EOD
    printf 'FoamFile { version 2.0; format ascii; class volVectorField; object U; }\ndimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\nboundaryField { walls { type noSlip; } }\n' > "$c/0/U"
    printf 'FoamFile { version 2.0; format ascii; class volScalarField; object p; }\ndimensions [0 2 -2 0 0 0 0];\ninternalField uniform 0;\nboundaryField { walls { type fixedFluxPressure; value uniform 0; } }\n' > "$c/0/p"
    props='bigParticleProps { expansionFactor 5; wallMirror false; }'
    cat > "$c/constant/couplingProperties" <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object couplingProperties; }
modelType A; couplingInterval 1; demScript "DEM/in.liggghts"; implicitDrag true;
voidFractionModel $method; $props
smoothingModel off; alphaMin 0.01; backgroundFields off; forceModels ( );
demTimeStepForce yes;
EOD
    {
        echo "atom_style granular"; echo "atom_modify map array"; echo "boundary f f f"; echo "newton off"
        echo "communicate single vel yes"; echo "units si"
        echo "region domain block -0.08 0.08 -0.08 0.08 0 0.004 units box"; echo "create_box 1 domain"
        echo "neighbor 0.0002 bin"; echo "neigh_modify delay 0"
        echo "fix m1 all property/global youngsModulus peratomtype 1e7"
        echo "fix m2 all property/global poissonsRatio peratomtype 0.3"
        echo "fix m3 all property/global coefficientRestitution peratomtypepair 1 0.9"
        echo "fix m4 all property/global coefficientFriction peratomtypepair 1 0.1"
        echo "pair_style gran model hertz tangential history"; echo "pair_coeff * *"; echo "timestep 1e-5"
        awk -F, 'NR > 2 { printf "create_atoms 1 single %.12g %.12g %.12g units box\n", $1*1e-3, $2*1e-3, $3*1e-3 }' "$work/standalone/particles.csv"
        echo "set group all diameter 0.001 density 2500"
        echo "fix cfd all couple/coarse"
    } > "$c/DEM/in.liggghts"
    (cd "$c" && blockMesh > log.blockMesh 2>&1 && coarseDemFoam > log.coarseDemFoam 2>&1) ||
        { result fail "distribution via OpenFOAM ($method): solver failed"; tail -5 "$c/log.coarseDemFoam"; continue; }
    name=$([ "$method" = bigParticle ] && echo bigParticle_n5 || echo "$method")
    results_from < <(/usr/bin/python3 - "$c/1e-05/alphaP" "$work/standalone/field_${name}_M2.csv" "$method" <<'PYEOF'

import re, sys
t = open(sys.argv[1]).read()
m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(", t)
of = [float(v) for v in t[m.end():].split(")")[0].split()[:int(m.group(1))]]
rows = [l for l in open(sys.argv[2]) if not l.startswith("#")]
k = 2   # the standalone field file holds layer k = 2
worst = 0.0
for j, row in enumerate(rows):
    for i, v in enumerate(row.split(",")):
        worst = max(worst, abs(float(v) - of[i + 160 * j + 160 * 160 * k]))
ok = worst <= 1e-12
print(("PASS" if ok else "FAIL") + f": distribution via OpenFOAM ({sys.argv[3]}, M2): max |alpha_p(coarseDemFoam) - alpha_p(core)| = {worst:.2e} over {len(rows)*160} cells (limit 1e-12)")
sys.exit(0 if ok else 1)
PYEOF
)
    [ "$nread" -eq 1 ] || result fail "distribution via OpenFOAM ($method): the comparison printed no verdict"
done
finish
