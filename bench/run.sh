#!/bin/bash
# Kernel micro-benchmark: builds the core and bench/build/kernel_bench, runs 1e3..1e6 particles,
# writes results/kernels.csv, results/ratios.md (the headline table) and results/run_info.txt.
#   ./run.sh                       all sizes (about 1.5 minutes on 2 shared cores)
#   ./run.sh -n 1000,10000         other sizes (passed to kernel_bench)
cd "${0%/*}" || exit 1
make -s || { echo "run.sh: build failed" >&2; exit 1; }
mkdir -p results
# the code's version before this run writes its own results (tracked files: they would read as -dirty)
code_version=$(../etc/codeVersion bench src/core)
started=$(date -u +%Y-%m-%dT%H:%M:%SZ)
start=$(date +%s%N)
./build/kernel_bench -o results/kernels.csv "$@" | tee results/log.kernel_bench
status=${PIPESTATUS[0]}
ms=$(( ($(date +%s%N) - start) / 1000000 ))
[ "$status" -eq 0 ] || { echo "run.sh: kernel_bench failed" >&2; exit "$status"; }

# Headline: ratios to the touch-only loop, one row per method, one column per particle count.
awk -F, '
NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
{
    n = $col["n_particles"]; m = $col["method"]
    if (!(n in seen_n)) { seen_n[n] = 1; ns[++nn] = n }
    if (!(m in seen_m)) { seen_m[m] = 1; ms[++nm] = m }
    b[m, n] = $col["build_over_touch"]; a[m, n] = $col["alpha_over_touch"]; f[m, n] = $col["first_build_over_touch"]
    t[m, n] = $col["n_timed"]; c[m, n] = $col["cells_per_kernel"]
}
function table(title, which,    i, j, line, x) {
    print "\n" title "\n"
    line = "| method | cells/kernel |"; for (j = 1; j <= nn; ++j) line = line sprintf(" N = %g |", ns[j]); print line
    line = "|---|---|"; for (j = 1; j <= nn; ++j) line = line "---|"; print line
    for (i = 1; i <= nm; ++i) {
        line = "| " ms[i] " | " c[ms[i], ns[nn]] " |"
        for (j = 1; j <= nn; ++j) {
            x = (which == "f") ? f[ms[i], ns[j]] : (which == "a") ? a[ms[i], ns[j]] : b[ms[i], ns[j]]
            line = line sprintf(" %.4g%s |", x, (t[ms[i], ns[j]] < ns[j]) ? "*" : "")
        }
        print line
    }
}
END {
    table("Kernel build (steady state: valid host hints) / touch-only", "b")
    table("First kernel build (no host hints, fresh buffers) / touch-only", "f")
    table("alpha_p spreading (cdc_alpha_p) / touch-only", "a")
    print "\n`*` timed on the first n_timed particles of the set (same mesh): see kernels.csv."
    print "cells/kernel: at the largest N."
}' results/kernels.csv > results/ratios.md
cat results/ratios.md

{
    echo "date: $started (start)"
    echo "commit: $code_version"
    echo "host: $(uname -m), $(nproc) cores, load average at the end $(cut -d' ' -f1-3 /proc/loadavg)"
    echo "command: bench/run.sh $*"
    echo "elapsed (kernel_bench): $((ms / 1000)).$(printf %03d $((ms % 1000))) s"
} > results/run_info.txt
cat results/run_info.txt
