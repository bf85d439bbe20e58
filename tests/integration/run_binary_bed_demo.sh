#!/bin/bash
# The binary liquid-fluidized bed (tutorials/binaryBedKhan) in its demo mode, one method: the run
# ends, postprocess.py and validation/khan/compare.py write their files, and
#   - the solid volume is conserved (the solver's last Coupling line: particles kept, rel. err);
#   - both species are in the alpha_p profiles, each with its whole volume;
#   - the big species lies below the small one (mean heights);
#   - the frictional pressure drop is within 5 % of the bed's buoyant weight (the tolerance of the
#     liquidFluidizedBed test; the issue's 3 % is for the long runs);
#   - no WARNING: no layer leaves the tube, no missed contacts;
#   - the pressure drop's balance (weight - walls' support + the fluid's wall shear) closes within 2 %;
#   - summary.csv has the agreed header and a row per species;
#   - bad input is reported by name and time: the run's data again with n = 1.5 (the small
#     species' kernel within its host cell) and with small particles moved into the top cell layer;
#     a run stopped before its window's end (its last dumps removed) is refused with the time;
#   - -continue continues with the run's own case files and refuses, naming the file, with a changed one
#     (also the one -alphaRelax changes); -alphaRelax writes one entry with its value, and a
#     non-positive or malformed time is refused before a run is made.
#   run_binary_bed_demo.sh [-method M] [-U U]          (default bigParticle, 0.015)
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$top/etc/bashrc" || exit 1
. "$here/result.sh"
method=bigParticle; U=0.015
while [ $# -gt 0 ]; do
    case "$1" in
        -method) method="$2"; shift 2 ;;
        -U) U="$2"; shift 2 ;;
        *) echo "usage: $0 [-method M] [-U U]" >&2; exit 2 ;;
    esac
done
case_dir="$top/tutorials/binaryBedKhan"
# the test's own run (a user's runs/<method>_U<U>_demo stays), and one test at a time: a second
# invocation (another tests/Alltest) waits here instead of deleting this one's run under it
name="alltest_${method}_U${U}_demo"
run="$case_dir/runs/$name"
exec 9> /tmp/coarsedem-binarybed-test.lock
flock 9
log="/tmp/coarsedem-binarybed-$name.log"
tag="binary bed demo $name"
start=$(date +%s)
if ! "$case_dir/Allrun" -mode demo -method "$method" -U "$U" -name "$name" > "$log" 2>&1; then
    result fail "$tag: Allrun failed (see $log)"; tail -5 "$log"; finish
fi
result ok "$tag: Allrun ran to the end and post-processed ($(( $(date +%s) - start )) s, $log)"

checks=$(/usr/bin/python3 - "$run" <<'PYEOF'
import csv, math, os, re, sys
run = sys.argv[1]
tag = "binary bed demo " + os.path.basename(run)
status = 0
def check(ok, what):
    global status
    print(("PASS" if ok else "FAIL") + ": %s: %s" % (tag, what))
    status |= not ok
res = os.path.join(run, "results")
layers = {r["species"]: r for r in csv.DictReader(open(os.path.join(res, "layers.csv")))}
bed = next(csv.DictReader(open(os.path.join(res, "bed.csv"))))
log = open(os.path.join(run, "log.coarseDemFoam")).read()
m = re.findall(r"^End: Coupling: particles (\d+), solid volume particles ([0-9.eE+-]+) .*?rel\. err ([0-9.eE+-]+)\)", log, re.M)
n_start = sum(int(l["N"]) for l in layers.values())
check(bool(m) and int(m[-1][0]) == n_start and float(m[-1][2]) <= 1e-12,
      "solid volume conserved: %s particles (%d at the start), rel. err %s on the last Coupling line"
      % (m[-1][0] if m else "?", n_start, m[-1][2] if m else "?"))
prof = list(csv.DictReader(open(os.path.join(res, "profiles.csv"))))
A, dz = 1e-4, 1e-3
for sp in ("big", "small"):
    vol = sum(float(p["alpha_" + sp]) for p in prof) * A * dz * 1e9
    want = float(layers[sp]["V_s_mm3"])
    check(vol > 0 and abs(vol - want) <= 1e-3 * want,
          "species %s in the alpha_p profiles: %.2f mm3 binned (its particles: %.2f mm3)" % (sp, vol, want))
hb, hs = float(layers["big"]["mean_height_mm"]), float(layers["small"]["mean_height_mm"])
check(hb < hs, "big below small: mean heights %.2f mm (1 mm) and %.2f mm (0.3 mm)" % (hb, hs))
dp, w = float(bed["dp_pa"]), float(bed["dp_weight_pa"])
check(abs(dp - w) <= 0.05 * w, "frictional pressure drop %.2f +- %.2f Pa within 5 %% of the buoyant weight %.2f Pa "
      "(%+.2f %%)" % (dp, float(bed["dp_sem_pa"]), w, 100 * (dp - w) / w))
ws = float(bed.get("wall_force_share", "nan"))
check(ws < 0.03, "the walls carry under 3 %% of the bed's buoyant weight (%.2f +- %.2f %%: post/wallForce.txt)"
      % (100 * ws, 100 * float(bed.get("wall_force_share_sem", "nan"))))
# the bed's balance: the frictional pressure drop = the weight less the walls' support plus the fluid's
# shear on the side walls (postprocess.py; the demo's window holds one written time)
shear, writes, residual = (float(bed.get("fluid_wall_shear_share", "nan")), int(bed.get("fluid_wall_shear_writes", "0")),
                           float(bed.get("dp_balance_residual", "nan")))
check(writes >= 1 and 0 < shear < 0.05 and abs(residual) < 0.02,
      "the pressure drop's balance closes within 2 %% of the weight: dp %+.2f %%, walls %.2f %%, fluid wall shear %.2f %% "
      "(%d written times), residual %+.2f %%" % (100 * float(bed["dp_rel_err"]), 100 * ws, 100 * shear, writes, 100 * residual))
msgs = open(os.path.join(res, "messages.txt")).read().strip()
check(not msgs, "no WARNING (no layer leaves the tube, largest overlap %s %% d)%s"
      % (bed["max_overlap_pct_d"], "" if not msgs else ": " + msgs.splitlines()[0]))
summ = os.path.join(res, "compare", "summary.csv")
lines = open(summ).read().splitlines() if os.path.isfile(summ) else []
header = ("method,U,species,alpha_p_plateau,alpha_p_sem,alpha_p_reference,layer_top_mm,dp_pa,dp_reference_pa,"
          "mixing_width_mm,window_s,wall_s,coupling_share,wall_force_share,fluid_wall_shear_share")
check(len(lines) == 3 and lines[0] == header and all(len(l.split(",")) == 15 for l in lines[1:]),
      "compare.py's summary.csv: the agreed header and a row per species (%d lines)" % len(lines))
sys.exit(status)
PYEOF
)
echo "$checks"
npass=$((npass + $(grep -c '^PASS' <<< "$checks"))); nfail=$((nfail + $(grep -c '^FAIL' <<< "$checks")))
[ -n "$checks" ] || result fail "$tag: the checks of the run's results did not run"

# bad input, on a copy of the run's data: postprocess.py must name the species and the time
bad=$(mktemp -d /tmp/coarsedem-binarybed-bad.XXXXXX)
cp -r "$run/constant" "$run/post" "$run/postProcessing" "$bad/"
for d in "$run"/[0-9]*; do [ "$(basename "$d")" != 0 ] && cp -r "$d" "$bad/"; done
sed -i 's/expansionFactor 5;/expansionFactor 1.5;/' "$bad/constant/couplingProperties"
last=$(ls "$bad"/post/dump*.liggghts | sort | tail -1)
# the last dump: ten small particles (type 2) lifted into the top cell layer, z = 119.5 mm
awk 'BEGIN { n = 0 } /^ITEM: ATOMS/ { atoms = 1; print; next }
     atoms && $2 == 2 && n < 10 { $5 = 0.1195; n++ } { print }' "$last" > "$last.new" && mv "$last.new" "$last"
demdt=$(awk '/^timestep/ {print $2}' "$run/DEM/in.liggghts")   # the run's own DEM step
t_last=$(/usr/bin/python3 -c "import sys; print('%g' % (int(open(sys.argv[1]).readlines()[1]) * float(sys.argv[2])))" "$last" "$demdt")
/usr/bin/python3 "$case_dir/postprocess.py" "$bad" -method "$method" -U "$U" -mode demo -tstart 0.6 -tend 1.0 \
    -demdt "$demdt" > "$bad/log.post" 2>&1
if grep -q "WARNING .*species small (d = 0.30 mm.*smaller than the bigParticle kernel reach allows" "$bad/log.post" &&
   grep -q "present at t = 0 s" "$bad/log.post"; then
    result ok "$tag: a species too small for the kernel is named with the time (n = 1.5: $(grep -o 'expanded diameter 2 n R = [0-9.]* mm' "$bad/log.post" | head -1))"
else
    result fail "$tag: n = 1.5 did not name the small species as too small for the kernel (see $bad/log.post)"
fi
if grep -q "WARNING .*species small leaves the tube: 10 of its .* at t = $t_last s" "$bad/log.post"; then
    result ok "$tag: a layer leaving the tube is named with the time (species small, t = $t_last s)"
else
    result fail "$tag: the small particles in the top cell layer were not reported with the time $t_last s (see $bad/log.post)"
fi
# a run that stopped before its window's end (its dumps after 0.9 s gone) is refused, with the time
for f in "$bad"/post/dump*.liggghts; do
    step=$(basename "$f" .liggghts); step=$((10#${step#dump}))
    /usr/bin/python3 -c "import sys; sys.exit(0 if int(sys.argv[1]) * float(sys.argv[2]) > 0.9 + 1e-9 else 1)" "$step" "$demdt" && rm "$f"
done
if ! /usr/bin/python3 "$case_dir/postprocess.py" "$bad" -method "$method" -U "$U" -mode demo -tstart 0.6 -tend 1.0 \
        -demdt "$demdt" > "$bad/log.post.early" 2>&1 &&
   grep -q "FAIL: .*stopped at t = 0.9 s (its last particle dump), before its window's end 1 s" "$bad/log.post.early"; then
    result ok "$tag: a run stopped before its window's end is refused with the time (t = 0.9 s)"
else
    result fail "$tag: a run stopped at 0.9 s was not refused naming the time (see $bad/log.post.early)"
fi
rm -rf "$bad"

# -continue: with the run's own case files it continues (at its end already: the solver starts and
# stops, the post-processing again); with a changed file it refuses, naming it
if "$case_dir/Allrun" -mode demo -method "$method" -U "$U" -name "$name" -continue > "$log.continue" 2>&1 &&
   grep -q "continuing runs/$name" "$log.continue"; then
    result ok "$tag: -continue with the same case files continues"
else
    result fail "$tag: -continue with the same case files did not continue (see $log.continue)"
fi
# the first start's wall forces survive the continuation (LIGGGHTS starts its file anew)
if [ -f "$run/post/wallForce.part0.txt" ] && [ "$(grep -vc '^#' "$run/post/wallForce.part0.txt")" -gt 0 ]; then
    result ok "$tag: -continue keeps the first start's wall forces as post/wallForce.part0.txt ($(grep -vc '^#' "$run/post/wallForce.part0.txt") samples)"
else
    result fail "$tag: -continue lost the first start's wall forces (no samples in $run/post/wallForce.part0.txt)"
fi
cp "$run/DEM/in.liggghts" "$log.dem"
echo "# edited" >> "$run/DEM/in.liggghts"
if ! "$case_dir/Allrun" -mode demo -method "$method" -U "$U" -name "$name" -continue > "$log.refused" 2>&1 &&
   grep -q "DEM/in.liggghts" "$log.refused" && grep -q "cannot continue" "$log.refused"; then
    result ok "$tag: -continue with a changed case file refuses, naming DEM/in.liggghts"
else
    result fail "$tag: -continue with a changed case file did not refuse naming it (see $log.refused)"
fi
cp "$log.dem" "$run/DEM/in.liggghts"
# -alphaRelax writes alphaRelaxationTime into the case's couplingProperties: the same run continued
# with it refuses, naming that file; a non-positive time is refused before anything is made
if ! "$case_dir/Allrun" -mode demo -method "$method" -U "$U" -name "$name" -alphaRelax 0.003 -continue > "$log.relax" 2>&1 &&
   grep -q "constant/couplingProperties" "$log.relax" && grep -q "cannot continue" "$log.relax"; then
    result ok "$tag: -alphaRelax 0.003 changes the case's couplingProperties (-continue refuses, naming it)"
else
    result fail "$tag: -continue -alphaRelax 0.003 did not refuse naming constant/couplingProperties (see $log.relax)"
fi
# the entry it writes: exactly one alphaRelaxationTime, the value given (the case made by Allrun
# -makeCase into a scratch directory)
mk=$(mktemp -d /tmp/coarsedem-khan-relax.XXXXXX)
"$case_dir/Allrun" -mode demo -method "$method" -U "$U" -alphaRelax 0.003 -makeCase "$mk" > /dev/null 2>&1
entries=$(grep -c "^alphaRelaxationTime " "$mk/constant/couplingProperties" 2>/dev/null)
value=$(sed -n 's/^alphaRelaxationTime  *\([^;]*\);.*/\1/p' "$mk/constant/couplingProperties" 2>/dev/null)
rm -rf "$mk"
if [ "$entries" = 1 ] && [ "$value" = 0.003 ]; then
    result ok "$tag: -alphaRelax 0.003 writes one entry alphaRelaxationTime 0.003"
else
    result fail "$tag: -alphaRelax 0.003 wrote ${entries:-no} alphaRelaxationTime entries, value '${value}'"
fi
for bad in 0 -1 ' 0.003' 0.00_3; do
    if ! "$case_dir/Allrun" -mode demo -method "$method" -name alltest_relax_refused -alphaRelax "$bad" > "$log.relaxbad" 2>&1 &&
       grep -q "alphaRelax must be a time" "$log.relaxbad" && [ ! -d "$case_dir/runs/alltest_relax_refused" ]; then
        result ok "$tag: -alphaRelax '$bad' is refused before a run is made"
    else
        result fail "$tag: -alphaRelax '$bad' was not refused (see $log.relaxbad)"
        rm -rf "$case_dir/runs/alltest_relax_refused"
    fi
done
finish
