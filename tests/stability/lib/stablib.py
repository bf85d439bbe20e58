"""stablib.py -- reading what a coarseDemFoam run left behind, for the stability suite.

    coupling_lines(case)      the "Coupling: ..." balance lines of log.coarseDemFoam as dicts
    exchange_lines(case)      the "Exchange in time: ..." lines (particles' vs fluid's impulse) as dicts
    write_times(case)         written times (serial or processor0), sorted
    read_scalar_field(case, time, name)   internal field values (all processors concatenated)
    read_vector_field(case, time, name)   list of (x, y, z)
    dumps(case)               LIGGGHTS dumps in post/: {step: {id: (x, y, z, vx, vy, vz, r)}}
    params(case)              case.params written by mkcase.py
    check_run(case, ...)      the common checks of a solver-level scene: (ok, summary, details)
"""
import glob, math, os, re, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "etc", "python"))
import foam_fields  # noqa: E402  the project's reader of written fields
import settling_ode  # noqa: E402  the drag ODE of a single sphere


def ode(p, times):
    """The ODE's velocities at the times, terminal velocity and response time for a scene's particle
    (mkcase parameters D_MM, RHO_P, RHO_F, NU_F)."""
    return settling_ode.settling(float(p["D_MM"]) * 1e-3, float(p["RHO_P"]), float(p["RHO_F"]),
                                 float(p["NU_F"]), times)


def progress(case):
    """(CFD steps, each step's largest Courant number) of a case's solver log."""
    steps, co = 0, []
    with open(os.path.join(case, "log.coarseDemFoam"), errors="replace") as f:
        for line in f:
            if line.startswith("Time = "):
                steps += 1
            m = re.match(r"Courant Number mean: (\S+) max: (\S+)", line)
            if m:
                co.append(float(m.group(2)))
    return steps, co

NUM = r"([-+]?(?:\d+\.?\d*(?:[eE][-+]?\d+)?|nan|inf|-nan|-inf))"
COUPLING = re.compile(
    r"Coupling: particles (\d+), solid volume particles " + NUM + r" cells " + NUM +
    r" \(rel\. err " + NUM + r"\), momentum imbalance " + NUM + r" N of " + NUM +
    r" N, limiter moved " + NUM + r" m3 in (\d+) cells")

EXCHANGE = re.compile(
    r"Exchange in time: (\d+) couplings compared, \|particles' \+ fluid's impulse\| of a coupling step last " +
    NUM + r" max " + NUM + r" x exchange; since the start net \(" + NUM + r" " + NUM + r" " + NUM +
    r"\) N s of " + NUM + r" N s")


def fnum(s):
    return float(s)


def _matches(case, pattern, log):
    """(match groups, line) of every line of the log that matches pattern"""
    with open(os.path.join(case, log), errors="replace") as f:
        return [(m.groups(), line) for line in f for m in [pattern.search(line)] if m]


def coupling_lines(case, log="log.coarseDemFoam"):
    return [dict(n=int(g[0]), vp=fnum(g[1]), vc=fnum(g[2]), rel=fnum(g[3]), M=fnum(g[4]), F=fnum(g[5]),
                 moved=fnum(g[6]), ncells=int(g[7]), end=line.startswith("End:"))
            for g, line in _matches(case, COUPLING, log)]


def exchange_lines(case, log="log.coarseDemFoam"):
    return [dict(n=int(g[0]), last=fnum(g[1]), max=fnum(g[2]), net=(fnum(g[3]), fnum(g[4]), fnum(g[5])),
                 gross=fnum(g[6]))
            for g, _ in _matches(case, EXCHANGE, log)]


def params(case):
    p = {}
    fn = os.path.join(case, "case.params")
    if os.path.exists(fn):
        for line in open(fn):
            k, _, v = line.rstrip("\n").partition("=")
            p[k] = v
    return p


def _time_dirs(d):
    out = []
    for e in os.listdir(d):
        try:
            t = float(e)
        except ValueError:
            continue
        if os.path.isdir(os.path.join(d, e)):
            out.append((t, e))
    return sorted(out)


def write_times(case):
    base = os.path.join(case, "processor0") if os.path.isdir(os.path.join(case, "processor0")) else case
    return _time_dirs(base)


def _read_internal(path, ncomp):
    """The internalField of one file (etc/python/foam_fields.py: ascii or binary) as a list, of floats
    or of (x, y, z); a uniform field as its one value (the suite compares written fields cell by cell
    and reads no mesh: a uniform field counts as one entry, per processor)."""
    v = foam_fields.read_internal_field(path, n_cells=1)  # n_cells is used by a uniform field only
    return [tuple(x) for x in v.tolist()] if ncomp == 3 else v.tolist()


def _field_paths(case, time, name):
    procs = sorted(glob.glob(os.path.join(case, "processor*")), key=lambda p: int(p.rsplit("processor", 1)[1]))
    if procs:
        return [os.path.join(p, time, name) for p in procs]
    return [os.path.join(case, time, name)]


def read_scalar_field(case, time, name):
    vals = []
    for p in _field_paths(case, time, name):
        vals.extend(_read_internal(p, 1))
    return vals


def read_vector_field(case, time, name):
    vals = []
    for p in _field_paths(case, time, name):
        vals.extend(_read_internal(p, 3))
    return vals


def dumps(case):
    """post/dump<step>.liggghts (dump custom id x y z vx vy vz radius) -> {step: {id: tuple}}"""
    out = {}
    for fn in glob.glob(os.path.join(case, "post", "dump*.liggghts")):
        with open(fn) as f:
            lines = f.read().splitlines()
        step = int(lines[lines.index("ITEM: TIMESTEP") + 1])
        k = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
        cols = lines[k].split()[2:]
        rows = {}
        for l in lines[k + 1:]:
            t = l.split()
            if len(t) != len(cols):
                continue
            rec = dict(zip(cols, t))
            rows[int(rec["id"])] = tuple(float(rec[c]) for c in ("x", "y", "z", "vx", "vy", "vz", "radius"))
        out[step] = rows
    return dict(sorted(out.items()))


def wall_time(case):
    try:
        return float(open(os.path.join(case, "wall_time")).read())
    except (OSError, ValueError):
        return float("nan")


def exit_status(case):
    try:
        return int(open(os.path.join(case, "exit_status")).read())
    except (OSError, ValueError):
        return -1


def log_has_nan(case, log="log.coarseDemFoam"):
    with open(os.path.join(case, log), errors="replace") as f:
        for line in f:
            if re.search(r"(?<![A-Za-z])-?nan(?![A-Za-z])", line, re.I):
                return line.strip()
    return None


# the solver's warnings for explicit coupling beyond its stable range (coarseDemCoupling.C)
PARTICLE_SIDE_WARNING = "explicit particle-side coupling beyond its range"
FLUID_SIDE_WARNING = "explicit fluid drag beyond its range"


def dvdt_unknown(case, log="log.coarseDemFoam"):
    """(at the first coupling, since) of the last "dv/dt unknown" report, or None without one."""
    last = None
    with open(os.path.join(case, log), errors="replace") as f:
        for line in f:
            m = re.search(r"dv/dt unknown for (\d+) particles at the first coupling, (\d+) since", line)
            if m:
                last = (int(m.group(1)), int(m.group(2)))
    return last


def log_has(case, text, log="log.coarseDemFoam"):
    with open(os.path.join(case, log), errors="replace") as f:
        return any(text in line for line in f)


def check_warning(case, text, expected, label):
    """(ok, description): whether the log has the warning `text` as `expected` (True/False)."""
    found = log_has(case, text)
    desc = "%s %s" % (label, "warned" if found else "no warning")
    return found == expected, desc + ("" if found == expected else " (expected %s)" %
                                      ("a warning" if expected else "none"))


def log_tail(case, n=6, log="log.coarseDemFoam"):
    try:
        with open(os.path.join(case, log), errors="replace") as f:
            lines = [l.rstrip() for l in f if l.strip()]
        return " | ".join(lines[-n:])
    except OSError:
        return "(no log)"


def failure_reason(case, log="log.coarseDemFoam"):
    """The message of a failed run: the FOAM FATAL ERROR text, a floating point exception, or the tail."""
    try:
        lines = [l.rstrip() for l in open(os.path.join(case, log), errors="replace")]
    except OSError:
        return "(no log)"
    for i, l in enumerate(lines):
        if "FOAM FATAL" in l:
            msg = [re.sub(r"^\[\d+\] ?", "", x).strip() for x in lines[i + 1:i + 4]]
            return "FATAL ERROR: " + " ".join(x for x in msg if x)[:300]
    if any("sigFpe" in l for l in lines):
        return "floating point exception (SIGFPE)"
    return log_tail(case, 4)


def check_run(case, alpha_min, expect_particles=None, rel_tol=1e-12, mom_tol=1e-10):
    """The common checks: exit 0, balance lines present (at each write and at the end), particle count
    constant (and as created), solid volume rel. err <= rel_tol, momentum imbalance <= mom_tol x force
    scale, no NaN in the log, alpha at the last write within [alpha_min, 1] and finite.
    Returns (ok, summary string, dict of measured values)."""
    m = {"wall": wall_time(case), "rc": exit_status(case)}
    problems = []
    if m["rc"] != 0:
        dem_err = None
        try:
            for line in open(os.path.join(case, "log.liggghts"), errors="replace"):
                if line.startswith("ERROR"):
                    dem_err = line.strip()
        except OSError:
            pass
        problems.append("solver exit status %d: %s" % (m["rc"], dem_err or failure_reason(case)))
    cl = coupling_lines(case)
    m["n_lines"] = len(cl)
    if not cl:
        problems.append("no Coupling balance lines in the log")
    else:
        counts = sorted(set(c["n"] for c in cl))
        m["particles"] = counts
        if len(counts) != 1:
            problems.append("particle count changed: %s" % counts)
        if expect_particles is not None and counts[0] != expect_particles:
            problems.append("%d particles, %d created" % (counts[0], expect_particles))
        m["rel"] = max(c["rel"] for c in cl)
        m["mom"] = max((c["M"] / c["F"]) if c["F"] > 0 else (0.0 if c["M"] == 0 else float("inf")) for c in cl)
        m["moved"] = max(c["moved"] for c in cl)
        m["limited"] = max(c["ncells"] for c in cl)
        if not (m["rel"] <= rel_tol):
            problems.append("solid volume rel. err %.2e > %.0e" % (m["rel"], rel_tol))
        if not (m["mom"] <= mom_tol):
            problems.append("momentum imbalance %.2e x force > %.0e" % (m["mom"], mom_tol))
        if not any(c["end"] for c in cl):
            problems.append("no End: balance line")
    nan = log_has_nan(case)
    if nan:
        problems.append("NaN in the log: " + nan[:100])
    times = write_times(case)
    m["last_time"] = times[-1][1] if times else None
    if times and times[-1][0] > 0:
        try:
            a = read_scalar_field(case, times[-1][1], "alpha")
            m["alpha_min"], m["alpha_max"] = min(a), max(a)
            if any(not math.isfinite(x) for x in a):
                problems.append("non-finite alpha")
            elif not (m["alpha_min"] >= alpha_min - 1e-12 and m["alpha_max"] <= 1 + 1e-12):
                problems.append("alpha [%.6g, %.6g] outside [%g, 1]" % (m["alpha_min"], m["alpha_max"], alpha_min))
        except (OSError, ValueError) as e:
            problems.append("alpha at t = %s unreadable: %s" % (times[-1][1], e))
    else:
        problems.append("no written time after 0")
    parts = []
    if "particles" in m:
        parts.append("particles %s" % ("/".join(str(c) for c in m["particles"])))
        parts.append("solid volume rel.err max %.1e" % m["rel"])
        parts.append("momentum imbalance max %.1e x force" % m["mom"])
        parts.append("limiter moved max %.2e m3 (%d cells)" % (m["moved"], m["limited"]))
    if "alpha_min" in m:
        parts.append("alpha_f [%.4f, %.4f] at t=%s" % (m["alpha_min"], m["alpha_max"], m["last_time"]))
    parts.append("%.0f s" % m["wall"])
    summary = ", ".join(parts)
    if problems:
        summary += "; " + "; ".join(problems)
    return (not problems), summary, m
