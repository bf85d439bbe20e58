#!/bin/bash
# Bad input to the benchmarks (issue 17): a method, rank count, size or option a benchmark cannot run
# stops it at once with exit status 2 and a message naming what was asked, before anything is
# measured or any result file is overwritten. Nothing here is timed. Prints "N passed, N failed".
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$here/result.sh"
work=$(mktemp -d /tmp/coarsedem-benchin.XXXXXX)
trap 'rm -rf "$work"' EXIT

# refused NAME 'expected message' command...: exit status 2 and the message on stderr
refused() {
    local name="$1" expect="$2"; shift 2
    "$@" > "$work/out" 2> "$work/err"
    local rc=$?
    if [ $rc -eq 2 ] && grep -qF -- "$expect" "$work/err"; then
        result ok "bench input '$name' refused (exit 2): $expect"
    else
        result fail "bench input '$name' (exit $rc) not refused with: $expect"
        sed 's/^/    /' "$work/err" | head -5
    fi
}

coupled="$top/bench/coupled/run.sh"
refused coupled-method "unknown method 'pcm'" "$coupled" -methods "centre pcm"
refused coupled-np "np 3: the Mueller case splits in 1 or 2 parts only" "$coupled" -np "1 3"
refused coupled-couplings "-couplings needs a positive number" "$coupled" -couplings 0
refused coupled-novalue "-np needs a value" "$coupled" -np
refused coupled-state "-state -0.4: needs a time in s after the start" "$coupled" -state -0.4
refused coupled-option "unknown option '-model'" "$coupled" -model centre
cases="$top/bench/cases/run.sh"
refused cases-case "unknown case 'ergun' (muller khan)" "$cases" -cases "muller ergun"
refused cases-np "np 3: 1 or 2 ranks" "$cases" -np "1 3"
refused cases-stretch "'-0.1' must be a time in s > 0" "$cases" -stretch -0.1
refused cases-novalue "-cases needs a value" "$cases" -cases
refused cases-option "unknown option '-method'" "$cases" -method divided
refused cases-pairs "-pairs '0' must be a whole number >= 1" "$cases" -pairs 0
# the cost table pairs the k-th baseline run with the k-th tutorial run and takes the median ratio
cat > "$work/runs.csv" <<'RUNS'
case,settings,np,simulated_s,wall_s,wall_per_simulated_s,dem_s,fluid_s,coupling_s,build
muller,baseline,2,0.1,40,400,4,4,2,x
muller,tutorial,2,0.1,24,240,2,2,1,x
muller,baseline,2,0.1,50,500,4,4,2,x
muller,tutorial,2,0.1,20,200,2,2,1,x
muller,baseline,2,0.1,40,400,4,4,2,x
muller,tutorial,2,0.1,18,180,2,2,1,x
RUNS
/usr/bin/python3 "$top/bench/cases/ratios.py" "$work/runs.csv" "$work/cases.csv" > /dev/null 2>&1
if [ "$(cut -d, -f6,13-15 "$work/cases.csv" | tail -1)" = "0.4500,3,0.4000,0.6000" ]; then
    result ok "bench/cases ratios.py: pairs in turn, median ratio 0.45 of 0.60, 0.40, 0.45"
else
    result fail "bench/cases ratios.py: expected ratio 0.4500 over 3 pairs (0.4000-0.6000), got: $(tail -1 "$work/cases.csv")"
fi
refused cases-baseline "is not a built tree" "$cases" -baselineTree "$work"
refused cases-method "unknown method 'dpvm' for muller" "$cases" -methods "centre dpvm"
refused cases-method-case "unknown method 'gaussian' for khan" "$cases" -cases khan -methods "centre gaussian"
refused cases-method-pcm "-methods needs centre" "$cases" -methods "divided bigParticle"
# the methods' table pairs the k-th run of a method with the k-th run of centre, round by round
cat > "$work/methods.csv" <<'RUNS'
case,method,np,simulated_s,wall_s,wall_per_simulated_s,dem_s,fluid_s,coupling_s,build
muller,centre,2,0.1,10,100,4,4,1,x
muller,bigParticle,2,0.1,13,130,4,4,4,x
muller,centre,2,0.1,20,200,4,4,1,x
muller,bigParticle,2,0.1,22,220,4,4,3,x
muller,centre,2,0.1,15,150,4,4,1,x
muller,bigParticle,2,0.1,18,180,4,4,3,x
RUNS
if /usr/bin/python3 "$top/bench/cases/ratios.py" -methods "$work/methods.csv" > "$work/methods.md" 2>&1 &&
   grep -qF "| muller | 2 | bigParticle | 3 | 180 | 1.20 (1.10-1.30) | 35 %/35 %/29 % | 30.0 | +13.3 % |" "$work/methods.md"; then
    result ok "bench/cases ratios.py -methods: rounds paired with centre's in order, median ratio 1.20 of 1.30, 1.10, 1.20 (1.10 if paired in reverse)"
else
    result fail "bench/cases ratios.py -methods: expected bigParticle 1.20 (1.10-1.30) and +13.3 %, got:"; sed 's/^/    /' "$work/methods.md"
fi
refused demstep-case "invalid choice: 'ergun'" /usr/bin/python3 "$top/bench/demStep/collision.py" ergun

make -s -C "$top/bench" > "$work/make.log" 2>&1 || { result fail "bench: kernel_bench does not build"; cat "$work/make.log"; finish; }
kb="$top/bench/build/kernel_bench"
echo "kept" > "$work/kernels.csv"
refused kernel-method "-m bigParticle: unknown method (known: centre divided bigParticle_n5" "$kb" -n 1000 -m bigParticle -o "$work/kernels.csv"
refused kernel-count "-n 1000,0: particle counts 1..1e8" "$kb" -n 1000,0 -o "$work/kernels.csv"
refused kernel-option "usage:" "$kb" -x
if [ "$(cat "$work/kernels.csv")" = kept ]; then
    result ok "kernel_bench refused before overwriting its CSV"
else
    result fail "kernel_bench overwrote its CSV on bad input"
fi
# the accepted spelling runs (one small size, one method): the refusals above are not of everything
if "$kb" -n 1000 -m centre -o "$work/kernels.csv" > "$work/out" 2>&1 && [ "$(wc -l < "$work/kernels.csv")" -eq 2 ]; then
    result ok "kernel_bench -n 1000 -m centre runs and writes one row"
else
    result fail "kernel_bench -n 1000 -m centre"; sed 's/^/    /' "$work/out" | tail -5
fi

# bench/kernelReuse: builds and prints a share of identical kernels for one speed, which falls with the speed
make -s -C "$top/bench/kernelReuse" > "$work/make.log" 2>&1 || { result fail "bench: kernel_reuse does not build"; cat "$work/make.log"; finish; }
if "$top/bench/kernelReuse/build/kernel_reuse" 0.05 0.3 > "$work/reuse.txt" 2>&1 &&
   awk -F'|' 'NR == 2 {a = $2 + 0} NR == 3 {b = $2 + 0} END {exit !(NR == 3 && a > b && b > 0 && a < 100)}' "$work/reuse.txt"; then
    result ok "kernel_reuse: fewer kernels identical at 0.3 than at 0.05 m/s ($(awk -F'|' 'NR > 1 {printf "%s", $2}' "$work/reuse.txt"))"
else
    result fail "kernel_reuse 0.05 0.3"; sed 's/^/    /' "$work/reuse.txt" | tail -5
fi

make -s -C "$top/bench/diffusion" > "$work/make.log" 2>&1 || { result fail "bench: diffusion_fields_bench does not build"; cat "$work/make.log"; finish; }
db="$top/bench/diffusion/build/diffusion_fields_bench"
refused diffusion-reps "-r needs 1 to 1000 repetitions" "$db" -r 0
refused diffusion-option "usage:" "$db" -x
# one repetition on both meshes: 4 rows, the fields smoothed together checked against one by one
if "$db" -r 1 -o "$work/fields.csv" > "$work/out" 2>&1 && [ "$(wc -l < "$work/fields.csv")" -eq 5 ]; then
    result ok "diffusion_fields_bench -r 1 runs and writes four rows"
else
    result fail "diffusion_fields_bench -r 1"; sed 's/^/    /' "$work/out" | tail -5
fi
finish
