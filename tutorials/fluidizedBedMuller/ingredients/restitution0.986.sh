# restitution0.986: the coefficient of restitution 0.986 (particle-particle and particle-wall) in
# place of Table II's 0.9. Why: the value of the public CFD-DEM cases of this bed (CFDEMcoupling-PFM's
# bubblingFluidizedBed, Khawaja's Case B; sediFoam's expMueller09, whose damping gives 0.986),
# likely from Mueller et al.'s own DEM (not confirmed: their paper is not at hand). Collisions that
# keep more energy let the dense regions flow more freely. Applied by Allrun -ingredient
# restitution0.986 to a case directory ($1).
set -e
sed -i 's/^\(fix             m3 all property\/global coefficientRestitution peratomtypepair 1\) 0.9$/\1 0.986/' "$1/DEM/materials.liggghts"
grep -q 'coefficientRestitution peratomtypepair 1 0.986$' "$1/DEM/materials.liggghts"
