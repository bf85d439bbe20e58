# bench/solverLog.sh -- sourced by the benchmarks (coupled/run.sh, cases/run.sh): coarseDemFoam run in a
# case, and what its log says of the run's cost.
#   run_solver DIR NP [ARGS]   coarseDemFoam in DIR (already decomposed for NP > 1) into DIR/log.coarseDemFoam
#   timers LOG                 the last "Stage timers" line
#   stage LOG NAME             one stage timer's seconds (nan when absent)
#   coupling_seconds LOG       every stage but DEM, fluid and the output-only fields (stageTimers.H)
#   loop_wall LOG              the time loop's wall seconds (the last Progress line)
run_solver() {
    local d="$1" np="$2"; shift 2
    ( cd "$d" || exit 1
      if [ "$np" -gt 1 ]; then
          mpirun --allow-run-as-root --oversubscribe -np "$np" coarseDemFoam -parallel "$@" > log.coarseDemFoam 2>&1
      else
          coarseDemFoam "$@" > log.coarseDemFoam 2>&1
      fi )
}
timers() { grep "Stage timers" "$1" | tail -1; }
stage() {
    timers "$1" | /usr/bin/python3 -c "import re,sys; m = re.search(r'\b$2 ([0-9.eE+-]+)', sys.stdin.read()); print(m.group(1) if m else 'nan')"
}
coupling_seconds() {
    timers "$1" | /usr/bin/python3 -c "import re,sys; print('%.6g' % sum(float(v) for k, v in re.findall(r'(\w+) ([0-9.eE+-]+) \(', sys.stdin.read()) if k not in ('DEM', 'fluid', 'fields')))"
}
loop_wall() { grep "^Progress:" "$1" | tail -1 | sed -E 's/.* wall ([0-9.eE+-]+) s.*/\1/'; }
