"""solver_log.py -- a coupled run's cost from its solver log: the wall seconds of every start (a log
continued after a restart holds several), pauses of a stopped run taken off, and the stage timers
(src/openfoam/coupling/stageTimers.H). For coarseDemFoam's and DPMFoam's logs; used by the Mueller,
binary-bed and bench scripts."""
import os
import re


def log_segments(log):
    """Per start of the solver (a log continued after a restart holds several, each beginning with
    OpenFOAM's "Create time"): its last stage-timer line (the timers count from each start) and its
    wall seconds. The wall clock is read at every step: coarseDemFoam's "Progress: t = T s ...,
    wall W s", DPMFoam's "Time = T" then "ClockTime = W". A start that was stopped and continued
    from its last write is counted up to the time the continuation started from: the stretch after
    it was computed again (and is counted there). Its stage timers were last printed at that write,
    so they cover the same stretch.

    Pauses: a long run stopped by SIGSTOP (the machine needed for something else) shows as one step
    whose wall time is PAUSE_FACTOR times the segment's median step or more. The excess over the
    median is the pause: taken off the segment's clock (seg["paused"], seg["pauses"]), and the
    stage-timer intervals holding one are left out of the stage shares (seg["stages"] is then the
    sum of the clean intervals), since the stage that was running when the run was stopped would
    otherwise carry the whole pause."""
    segs, t, nprocs = [], None, 1
    for line in open(log, errors="replace"):
        m = re.match(r"nProcs\s*:\s*(\d+)", line)   # in OpenFOAM's banner, before "Create time"
        if m:
            nprocs = int(m.group(1))
        elif line.startswith("Create time"):
            segs.append({"stage_lines": [], "walls": [], "nprocs": nprocs})
            t, nprocs = None, 1
        elif not segs:
            continue
        elif line.startswith("Stage timers"):
            segs[-1]["stage_lines"].append((t, {m.group(1): float(m.group(2)) for m in re.finditer(r"(\w+) ([0-9.eE+-]+) \(", line)}))
        elif line.startswith("Time = "):
            t = float(line.split()[2])
        else:
            m = re.match(r"Progress: t = ([0-9.eE+-]+) s .* wall ([0-9.eE+-]+) s", line)
            if m:
                segs[-1]["walls"].append((float(m.group(1)), float(m.group(2)), "progress"))
                continue
            m = re.search(r"ClockTime = ([0-9.eE+-]+)", line)
            if m:
                segs[-1]["walls"].append((t if t is not None else float("inf"), float(m.group(1)), "clock"))
    # each segment counts up to the earliest time any later segment started from (a start that
    # failed before its first step has no wall entries and cuts nothing)
    restart = float("inf")
    for seg in reversed(segs):
        walls = seg["walls"] if restart == float("inf") else [w for w in seg["walls"] if w[0] < restart]
        seg["clock"] = max((w[1] for w in walls), default=0.0)
        seg["pauses"] = find_pauses(walls)
        seg["paused"] = sum(p for _, p in seg["pauses"])
        lines = [l for l in seg["stage_lines"] if l[0] is None or l[0] <= restart]
        seg["stages"] = clean_stages(lines, [t for t, _ in seg["pauses"]])
        if seg["walls"]:
            restart = min(restart, seg["walls"][0][0])
    return segs

PAUSE_FACTOR = 100   # a step this many times the typical step: the run was stopped, not slow


def find_pauses(walls):
    """(time, seconds) of each pause among a segment's wall samples (time, wall, kind). Steps of one
    kind only: coarseDemFoam's "Progress" walls (its closing ClockTime counts from an earlier
    start, and its last "step" would hold the start-up), else DPMFoam's ClockTime (whole seconds:
    the typical step is the median, or where most steps round to 0 s the mean of the steps
    without their largest tenth, which would hold the pauses)."""
    kind = "progress" if any(w[2] == "progress" for w in walls) else "clock"
    ws = [w for w in walls if w[2] == kind]
    steps = sorted(b[1] - a[1] for a, b in zip(ws, ws[1:]))
    if not steps:
        return []
    kept = steps[:max(1, len(steps) - len(steps) // 10)]
    typical = steps[len(steps) // 2] or sum(kept) / len(kept)
    return [(b[0], b[1] - a[1] - typical) for a, b in zip(ws, ws[1:])
            if typical > 0 and b[1] - a[1] >= PAUSE_FACTOR * typical]


def clean_stages(lines, pause_times):
    """Stage seconds of a segment: its last stage-timer line, or without pauses, the sum of the
    increments between consecutive lines (from zero at the start) whose interval holds no pause."""
    if not lines:
        return None
    if not pause_times:
        return lines[-1][1]
    total, prev_t, prev = {}, float("-inf"), {}
    for t, cum in lines:
        if not any(prev_t < p <= t for p in pause_times):
            for k, v in cum.items():
                total[k] = total.get(k, 0.0) + v - prev.get(k, 0.0)
        prev_t, prev = t, cum
    return total

# the solver's stage timers that are not the coupling's (src/openfoam/coupling/stageTimers.H)
NOT_COUPLING = ("DEM", "fluid", "fields")

def stage_times(segs):
    """Stage seconds summed over the segments (None without any stage-timer line)."""
    total = {}
    for seg in segs:
        for k, v in (seg["stages"] or {}).items():
            total[k] = total.get(k, 0.0) + v
    return total or None

def run_wall(run):
    """(wall seconds, core seconds, sorted MPI rank counts, log segments, pauses) of a run directory.
    The solver log has every start, also one cut by a kill, each with its ranks (OpenFOAM's nProcs),
    its pauses taken off and the stretch computed again after a restart counted once
    (log_segments); wall_seconds.txt (one line per (re)start that returned, "<wall seconds>
    [<MPI ranks>]") only where there is no log."""
    logs = [p for p in (os.path.join(run, "log.coarseDemFoam"), os.path.join(run, "log.DPMFoam")) if os.path.exists(p)]
    segs = log_segments(logs[0]) if logs else []
    if segs:
        wall = sum(seg["clock"] - seg["paused"] for seg in segs)
        core = sum((seg["clock"] - seg["paused"]) * seg["nprocs"] for seg in segs)
        return wall, core, sorted(set(seg["nprocs"] for seg in segs)), segs, [p for seg in segs for p in seg["pauses"]]
    wpath = os.path.join(run, "wall_seconds.txt")
    starts = [l.split() for l in open(wpath) if l.strip()] if os.path.exists(wpath) else []
    wall = sum(float(t[0]) for t in starts)
    core = sum(float(t[0]) * (int(t[1]) if len(t) > 1 else 1) for t in starts)
    return wall, core, sorted(set(int(t[1]) if len(t) > 1 else 1 for t in starts)) or [1], segs, []
