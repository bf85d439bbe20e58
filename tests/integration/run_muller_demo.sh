#!/bin/bash
# The Mueller bed in its demo mode (README command 1): runs end to end (settled bed, coupled run,
# profiles, comparison with the MR data) and writes both profiles at every height, finite, with
# the solid volume conserved and the inflow equal to the superficial velocity of the experiment;
# the binned particle fields hold every particle's volume and the same momentum as the kernel fields.
#   run_muller_demo.sh [-model M] [-mesh 1|0.67] [-U 0.9|0.6]   (the tutorial's variants; default
#                                                                bigParticle, 1, 0.9)
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$top/etc/bashrc" || exit 1
. "$here/result.sh"   # result ok|fail, results_from, finish
model=bigParticle; mesh=1; U=0.9
while [ $# -gt 0 ]; do
    case "$1" in
        -model) model="$2"; shift 2 ;;
        -mesh) mesh="$2"; shift 2 ;;
        -U) U="$2"; shift 2 ;;
        *) echo "usage: $0 [-model M] [-mesh 1|0.67] [-U 0.9|0.6]" >&2; exit 2 ;;
    esac
done
case "$mesh" in 1) cells="8 36 100" ;; 0.67) cells="12 54 150" ;; *) echo "unknown mesh $mesh" >&2; exit 2 ;; esac
name="${model}_dx${mesh}_U${U}_demo"
case_dir="$top/tutorials/fluidizedBedMuller"
log="/tmp/coarsedem-muller-$name.log"
"$case_dir/Allrun" -mode demo -model "$model" -mesh "$mesh" -U "$U" > "$log" 2>&1 ||
    { result fail "Muller demo run $name (see $log)"; tail -5 "$log"; finish; }
results_from < <(/usr/bin/python3 - "$case_dir/runs/$name" "$U" $cells <<'PYEOF'
import math, os, re, struct, sys
run, U_in = sys.argv[1], float(sys.argv[2])
nx, ny, nz = map(int, sys.argv[3:6])
tag = f"Muller demo {os.path.basename(run)}"
status = 0
def profile(q, h):
    p = os.path.join(run, "results", f"profile_{q}_z{h}mm.csv")
    return [float(l.split(",")[1]) for l in open(p) if l[0].isdigit()] if os.path.exists(p) else []
# 44 points each; the gas fraction finite everywhere; a particle velocity may be undefined (nan: no
# solid at that point over the window) only where the gas fraction is above 0.5, near the surface
for h in ("15", "16.4", "20", "25", "31.2", "35"):
    gas = profile("voidfraction", h)
    for q in ("voidfraction", "vz", "vzbinned"):
        vals = profile(q, h)
        undefined = sum(1 for v in vals if v != v)
        ok = len(vals) == 44 and len(gas) == 44 and all(
            math.isfinite(v) or (v != v and q != "voidfraction" and g > 0.5) for v, g in zip(vals, gas))
        print(("PASS" if ok else "FAIL") + f": {tag} profile {q} z = {h} mm ({len(vals)} points, "
              f"{undefined} without solid)")
        status |= not ok
# depth-averaged profiles (every cell column across the thickness, particles binned by the cell of
# their centre): one point per cell across the width at every height. The binned gas fraction is at
# most 1 but may be below 0 over a window this short where the cells are smaller than the particles
# (a cell holding a centre holds the whole particle: 1.7 times its volume at dx/d = 0.67); its time
# average tends to the solid fraction as the window grows.
for h in ("15", "16.4", "20", "25", "31.2", "35"):
    gas = profile("voidfractiondepthbinned", h)
    for q in ("voidfractiondepthbinned", "vzdepthbinned", "voidfractiondepth"):
        vals = profile(q, h)
        ok = len(vals) == ny and len(gas) == ny and all(
            math.isfinite(v) or (v != v and q == "vzdepthbinned" and g > 0.5) for v, g in zip(vals, gas)) and \
            all(g <= 1 + 1e-12 for g in gas)
        print(("PASS" if ok else "FAIL") + f": {tag} profile {q} z = {h} mm ({len(vals)} points of {ny})")
        status |= not ok
log = open(os.path.join(run, "log.coarseDemFoam")).read()
m = re.findall(r"^End: Coupling: particles (\d+), .*?rel\. err ([0-9.eE+-]+)\)", log, re.M)
ok = bool(m) and int(m[-1][0]) == 9240 and float(m[-1][1]) <= 1e-12
print(("PASS" if ok else "FAIL") + f": {tag}: 9240 particles kept, solid volume rel. err {m[-1][1] if m else '?'}")
status |= not ok
# the particles as a lagrangian cloud at the last write time (writeParticleCloud, default on)
last_w = sorted((d for d in os.listdir(run) if re.fullmatch(r"[0-9.e-]+", d) and float(d) > 0), key=float)[-1]
cloud = os.path.join(run, last_w, "lagrangian", "particles")
def count(name):
    path = os.path.join(cloud, name)
    if not os.path.exists(path): return -1
    mm = re.search(rb"\n(\d+)\s*[({]", open(path, "rb").read())
    return int(mm.group(1)) if mm else -1
counts = {f: count(f) for f in ("positions", "d", "U", "f", "id")}
ok = all(c == 9240 for c in counts.values())
print(("PASS" if ok else "FAIL") + f": {tag}: particle cloud at t = {last_w} ({cloud}) holds 9240 entries in each of "
      + ", ".join(f"{k} ({v})" for k, v in counts.items()))
status |= not ok
png = os.path.join(run, "results", "bed.png")
ok = os.path.exists(png) and os.path.getsize(png) > 10000
print(("PASS" if ok else "FAIL") + f": {tag}: the picture of the bed {png} " + ("written" if ok else "missing"))
status |= not ok
# superficial inflow above the bed (top layer of cells): alpha * Uz = the inlet velocity
last = sorted((d for d in os.listdir(run) if re.fullmatch(r"[0-9.e-]+", d) and float(d) > 0), key=float)[-1]
def rd(path):
    b = open(path, "rb").read()
    mm = re.search(rb"internalField\s+nonuniform\s+List<(scalar|vector)>\s*(\d+)\s*\(", b)
    n = int(mm.group(2)); k = 3 if mm.group(1) == b"vector" else 1
    return struct.unpack("<%dd" % (n * k), b[mm.end():mm.end() + 8 * n * k])
U, a = rd(os.path.join(run, last, "U")), rd(os.path.join(run, last, "alpha"))
top = range((nz - 1) * nx * ny, nz * nx * ny)
us = sum(U[3 * i + 2] * a[i] for i in top) / len(top)
ok = abs(us - U_in) <= 0.01 * U_in / 0.9
print(("PASS" if ok else "FAIL") + f": {tag}: superficial gas velocity at the top {us:.4f} m/s (inlet {U_in})")
status |= not ok
# binned particle fields: every particle's volume in the cell of its centre (no loss), and the
# binned and the kernel-spread momentum density hold the same total sum V_p v_p
V = 0.010 * 0.044 * 0.120 / (nx * ny * nz)
vp = 9240 * math.pi / 6 * 1.2e-3 ** 3
ab = rd(os.path.join(run, last, "alphaPBinned"))
ub, uk = rd(os.path.join(run, last, "alphaPUsBinned")), rd(os.path.join(run, last, "alphaPUs"))
err_v = abs(sum(ab) * V - vp) / vp
mom_b = [sum(ub[3 * i + d] for i in range(len(ab))) * V for d in range(3)]
mom_k = [sum(uk[3 * i + d] for i in range(len(ab))) * V for d in range(3)]
scale = max(sum(abs(ub[3 * i + d]) for i in range(len(ab))) * V for d in range(3))
err_m = max(abs(b - k) for b, k in zip(mom_b, mom_k)) / scale
ok = err_v <= 1e-12 and err_m <= 1e-12
print(("PASS" if ok else "FAIL") + f": {tag}: binned particle fields hold the particle volume (rel. err {err_v:.2e}) "
      f"and the kernel fields' momentum (rel. diff {err_m:.2e})")
status |= not ok
# the comparison with the MR data of this inlet velocity: one row per data file of that velocity
data = os.path.join(os.environ["COARSEDEM_DIR"], "validation", "muller", "data")
want = sorted(f for f in os.listdir(data) if f.startswith(f"mueller_U{sys.argv[2]}_"))
errs = os.path.join(run, "results", "comparison", "errors.csv")
rows = open(errs).read().splitlines()[1:] if os.path.exists(errs) else []
ok = len(want) > 0 and len(rows) >= len(want)
print(("PASS" if ok else "FAIL") + f": {tag}: compared with {len(want)} MR data files of U = {sys.argv[2]} m/s "
      f"({len(rows)} rows in errors.csv)")
status |= not ok
sys.exit(status)
PYEOF
)
# the checker exits non-zero on a failed check (counted) or on an error (a traceback after its PASS lines)
wait $! || [ "$nfail" -gt 0 ] || result fail "Muller demo $name: the checker stopped with an error after $nread verdicts"
# -continue: with the case files the run started with it continues (here: at its end already, so it
# only re-makes the profiles), after a write cut short by a stop (made here: a later time with the
# velocity of the first rank only and a DEM restart without its .step) is moved aside (without that,
# at bbceefb, OpenFOAM stopped: "Start time is not the same for all processors"); with a file of the
# run changed it refuses, naming the file
tag="Muller demo $name"
run_dir="$case_dir/runs/$name"
fields="$run_dir/processor0"; [ -d "$fields" ] || fields="$run_dir"
last_t=$(cd "$fields" && ls -d [0-9]* | sort -g | tail -1)
mkdir -p "$fields/9.99" "$run_dir/9.99" && cp "$fields/$last_t/U" "$fields/9.99/" && : > "$run_dir/9.99/dem.restart"
if "$case_dir/Allrun" -mode demo -model "$model" -mesh "$mesh" -U "$U" -continue > "$log.continue" 2>&1 &&
   grep -q "continuing runs/$name" "$log.continue" && grep -q "write time 9.99 .*cut short by a stop" "$log.continue" &&
   [ ! -e "$fields/9.99" ] && [ -f "$run_dir/incomplete/${fields#"$run_dir"}/9.99/U" ] && [ -d "$fields/$last_t" ] &&
   [ "$(find "$run_dir/incomplete" -mindepth 1 -maxdepth 2 -name '[0-9]*' | sed 's|.*/||' | sort -u)" = 9.99 ]; then
    result ok "$tag: -continue with the same case files continues from the last complete write ($last_t), a write cut short moved aside"
else
    result fail "$tag: -continue with the same case files did not continue from its last complete write (see $log.continue)"
fi
cp "$run_dir/constant/couplingProperties" "$log.cp"
echo "// edited" >> "$run_dir/constant/couplingProperties"
if ! "$case_dir/Allrun" -mode demo -model "$model" -mesh "$mesh" -U "$U" -continue > "$log.refused" 2>&1 &&
   grep -q "constant/couplingProperties" "$log.refused" && grep -q "cannot continue" "$log.refused"; then
    result ok "$tag: -continue with a changed case file refuses, naming constant/couplingProperties"
else
    result fail "$tag: -continue with a changed case file did not refuse naming it (see $log.refused)"
fi
cp "$log.cp" "$run_dir/constant/couplingProperties"
# -continue on other ranks than the run's: refused (the DEM restart and fields are per decomposition)
ran=$(awk 'NF >= 2 {n = $2} END {print n}' "$run_dir/wall_seconds.txt")
other=$((3 - ran))
if ! "$case_dir/Allrun" -mode demo -model "$model" -mesh "$mesh" -U "$U" -continue -np "$other" > "$log.ranks" 2>&1 &&
   grep -q "cannot continue on $other rank(s): it ran on $ran" "$log.ranks"; then
    result ok "$tag: -continue on $other rank(s) of a run made on $ran refuses, naming both"
else
    result fail "$tag: -continue on $other rank(s) of a run made on $ran did not refuse (see $log.ranks)"
fi
finish
