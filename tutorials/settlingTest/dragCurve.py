#!/usr/bin/python3
"""dragCurve.py -- terminal velocities of single spheres, Re_t from 0.1 to 1000, for every drag law,
against the standard drag curve of a sphere (etc/python/standard_drag.py: Clift, Grace & Weber 1978, Table 5.2).

Each case is this tutorial's column and coupling (2 mm sphere, 2 mm cells, 20 x 20 mm cross-section,
bigParticle kernels, background fields over 5 radii, Model A with gradPForce), with the sphere's
density and the fluid's viscosity chosen for the Reynolds number; the case runs in
post/dragCurve/<law>_Re<target>/. The terminal velocity is the mean over the last 20 % of the
history; its drift, (last 10 % - previous 10 %) / u, is reported.

Columns: u_reference from the standard curve; u_law the law's own single-sphere terminal velocity
(alpha = 1, algebraic); rel_err = u_sim/u_reference - 1 (law and coupling together), law_err =
u_law/u_reference - 1 (the law alone), coupling_err = u_sim/u_law - 1 (the coupling alone).
Checks (PASS/FAIL lines):
  vs_standard_curve  |rel_err| <= tolerance, tolerance = 5 % in Cd as a velocity (eps/(2 - m), m =
                     -dln Cd/dln Re) + 1 % for the coupling (the settlingTest ODE check measures
                     0.4-0.6 % at Re_t 460); only where the law claims validity (in_range)
  vs_own_law         |coupling_err| <= 1.5 %: the run reproduces the law's own terminal velocity
  range_warning      outside its range the law printed its warning exactly once, inside none
The full matrix checks all three on every row (some fail, README.md says why); -quick checks on
each of its points only what holds for a correct law.

Usage: dragCurve.py [-quick] [-laws L1,L2] [-re 0.1,1000] [-o dir] [-analyse]
  -quick    the short form of tests/Alltest (about 2 minutes)
  -analyse  no runs: the table again from the runs in post/dragCurve
Writes <o>/dragCurve.csv and <o>/dragCurve.md (-quick: dragCurve-quick.*), <o> = results;
prints PASS/FAIL lines; exit 1 on any FAIL.
"""
import os, re, shutil, subprocess, sys, time

HERE = os.path.dirname(os.path.abspath(__file__))
# the project's Python library, etc/python
sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."), "etc", "python"))
import standard_drag as sd

D, RHO_F = 2e-3, 1000.0
WIDTH = 0.02
# Re_t target: (rho_p kg/m3, nu m2/s, domain height m, simulated time s)
CASES = {
    0.1:  (1900.0, 2e-4, 0.2, 1.0),
    1:    (1650.0, 5e-5, 0.2, 1.0),
    10:   (1400.0, 1e-5, 0.2, 1.0),
    100:  (1900.0, 3e-6, 0.2, 0.6),
    1000: (5500.0, 1e-6, 0.4, 0.6),
}
LAWS = ["DiFeliceDrag", "GidaspowDrag", "SchillerNaumannDrag", "KochHillDrag"]
ALL_CHECKS = ("vs_standard_curve", "vs_own_law", "range_warning")
# -quick: (law, Re_t target, checks); at Re_t 100 the coupling's own error is below 1 % (README.md)
QUICK = [("SchillerNaumannDrag", 100, ALL_CHECKS),
         ("GidaspowDrag", 100, ALL_CHECKS),
         ("DiFeliceDrag", 100, ("vs_own_law", "range_warning")),
         ("KochHillDrag", 100, ("range_warning",))]
LAW_TOL = 0.015
NUM_TOL = 0.01


def sub(path, pattern, repl):
    with open(path) as f:
        s = f.read()
    s2, n = re.subn(pattern, repl, s, flags=re.M)
    if n == 0:
        sys.exit(f"dragCurve.py: '{pattern}' not found in {path}")
    with open(path, "w") as f:
        f.write(s2)


def setup(run, law, rho_p, nu, height, t_end):
    if os.path.isdir(run):
        shutil.rmtree(run)
    os.makedirs(run)
    for d in ("constant", "system", "DEM"):
        shutil.copytree(os.path.join(HERE, d), os.path.join(run, d))
    shutil.copytree(os.path.join(HERE, "0.orig"), os.path.join(run, "0"))
    os.makedirs(os.path.join(run, "post"))
    for f in ("couplingProperties.orig",):
        p = os.path.join(run, "constant", f)
        if os.path.exists(p):
            os.remove(p)
    sub(os.path.join(run, "constant", "couplingProperties"), r"^forceModels .*$",
        f"forceModels         ( {law} gradPForce );")
    sub(os.path.join(run, "constant", "transportProperties"), r"^nu .*$", f"nu   [0 2 -1 0 0 0 0] {nu:g};")
    H_mm = round(height * 1000)
    sub(os.path.join(run, "system", "blockMeshDict"), r"\(0 0 200\) \(20 0 200\) \(20 20 200\) \(0 20 200\)",
        f"(0 0 {H_mm}) (20 0 {H_mm}) (20 20 {H_mm}) (0 20 {H_mm})")
    sub(os.path.join(run, "system", "blockMeshDict"), r"\(10 10 100\)", f"(10 10 {H_mm // 2})")
    sub(os.path.join(run, "system", "controlDict"), r"^endTime .*$", f"endTime         {t_end:g};")
    sub(os.path.join(run, "system", "controlDict"), r"^writeInterval .*$", f"writeInterval   {t_end:g};")
    dem = os.path.join(run, "DEM", "in.liggghts")
    sub(dem, r"0 0\.02 0 0\.02 0 0\.2 units box", f"0 0.02 0 0.02 0 {height:g} units box")
    sub(dem, r"0\.0101 0\.0099 0\.17 units box", f"0.0101 0.0099 {height - 0.03:g} units box")
    sub(dem, r"density 2500", f"density {rho_p:g}")
    sub(dem, r"^dump .*$", "")


def run_case(run):
    env = dict(os.environ)
    start = time.time()
    with open(os.path.join(run, "log.blockMesh"), "w") as log:
        if subprocess.call(["blockMesh"], cwd=run, stdout=log, stderr=subprocess.STDOUT):
            return None, 0.0
    with open(os.path.join(run, "log.coarseDemFoam"), "w") as log:
        rc = subprocess.call(["coarseDemFoam"], cwd=run, stdout=log, stderr=subprocess.STDOUT, env=env)
    return rc, time.time() - start


def analyse(run):
    rows = []
    with open(os.path.join(run, "post", "particle.txt")) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            t, z, vz = map(float, line.split()[:3])
            rows.append((t, z, -vz))
    free = [r for r in rows if r[1] > 10 * D]
    n = len(free)
    tail = free[int(0.8 * n):]
    u = sum(r[2] for r in tail) / len(tail)
    last = free[int(0.9 * n):]
    prev = free[int(0.8 * n):int(0.9 * n)]
    drift = (sum(r[2] for r in last) / len(last) - sum(r[2] for r in prev) / len(prev)) / u
    with open(os.path.join(run, "log.coarseDemFoam")) as f:
        log = f.read()
    warnings = len(re.findall(r"is outside the range of the law", log))
    clock = re.findall(r"ClockTime = ([0-9.eE+-]+) s", log)
    return u, drift, warnings, float(clock[-1]) if clock else float("nan")


def git_output(args):
    """git's output in this tree, or "" where git is not installed (a fresh Debian machine: the
    project needs no git) or this is not a clone."""
    try:
        return subprocess.run(["git", "-C", HERE] + args, capture_output=True, text=True).stdout.strip()
    except OSError:
        return ""


def main(argv):
    laws, res, quick, rerun, out = LAWS, sorted(CASES), False, True, os.path.join(HERE, "results")
    i = 0
    while i < len(argv):
        a = argv[i]
        if a == "-quick":
            quick = True; i += 1
        elif a == "-laws":
            laws = argv[i + 1].split(","); i += 2
        elif a == "-re":
            res = [float(x) if float(x) < 1 else int(float(x)) for x in argv[i + 1].split(",")]; i += 2
        elif a == "-analyse":
            rerun = False; i += 1
        elif a == "-o":
            out = os.path.abspath(argv[i + 1]); i += 2
        elif a in ("-h", "--help"):
            print(__doc__); return 0
        else:
            sys.exit(f"dragCurve.py: unknown option {a}")
    pairs = QUICK if quick else [(law, r, ALL_CHECKS) for law in laws for r in res]
    os.makedirs(out, exist_ok=True)
    commit = git_output(["log", "-1", "--format=%h"]) or "unknown"
    dirty = git_output(["status", "--porcelain", "--", "../../src", "."])
    results, fails, run_commits = [], 0, set()
    for law, target, checks in pairs:
        rho_p, nu, height, t_end = CASES[target]
        u_ref, re_ref = sd.terminal_velocity(sd.cd_clift, D, rho_p, RHO_F, nu)
        u_law, re_law = sd.terminal_velocity(sd.LAW_CD[law], D, rho_p, RHO_F, nu)
        tol = sd.velocity_tolerance(re_ref) + NUM_TOL
        range_text, in_range_f = sd.LAW_RANGE[law]
        name = f"{law}_Re{target:g}"
        run = os.path.join(HERE, "post", "dragCurve", name)
        rc = 0
        if rerun:
            setup(run, law, rho_p, nu, height, t_end)
            with open(os.path.join(run, "commit"), "w") as f:
                f.write(commit + (" (with uncommitted changes)" if dirty else "") + "\n")
            rc, _ = run_case(run)
        elif not os.path.exists(os.path.join(run, "post", "particle.txt")):
            continue
        if rc != 0:
            print(f"FAIL: dragCurve/{name}: coarseDemFoam exited with {rc} (see {run}/log.coarseDemFoam)")
            fails += 1
            continue
        u, drift, nwarn, wall = analyse(run)
        re_sim = u * D / nu
        in_range = in_range_f(re_sim)
        err = u / u_ref - 1
        err_law = u / u_law - 1
        law_err = u_law / u_ref - 1
        ok_ref = abs(err) <= tol
        ok_law = abs(err_law) <= LAW_TOL
        ok_warn = (nwarn == 0) if in_range else (nwarn == 1)
        verdict = ("PASS" if ok_ref else "FAIL") if in_range else "outside range"
        with open(os.path.join(run, "commit")) as f:
            run_commits.add(f.read().strip())
        results.append(dict(law=law, Re_t=re_sim, d=D, rho_p=rho_p, nu=nu, u_sim=u, u_reference=u_ref,
                            rel_err=err, tolerance=tol, in_range=in_range, u_law=u_law,
                            coupling_err=err_law, law_err=law_err, drift=drift, warnings=nwarn, wall_s=wall,
                            verdict=verdict, Re_ref=re_ref))
        print(f"dragCurve: {law:20s} Re_t {re_sim:8.3f}  u_sim {u:.5f}  u_ref {u_ref:.5f} ({100*err:+6.2f} %,"
              f" tol {100*tol:.2f} %)  u_law {u_law:.5f} (law {100*law_err:+6.2f} %, coupling"
              f" {100*err_law:+6.2f} %)  drift {100*drift:+.2f} %"
              f"  warnings {nwarn}  {wall:.0f} s")
        if in_range and "vs_standard_curve" in checks:
            print(("PASS: " if ok_ref else "FAIL: ") + f"dragCurve/{name}/vs_standard_curve"
                  f" ({100*err:+.2f} %, tolerance {100*tol:.2f} %)")
            fails += not ok_ref
        if "vs_own_law" in checks:
            print(("PASS: " if ok_law else "FAIL: ") + f"dragCurve/{name}/vs_own_law ({100*err_law:+.2f} %,"
                  f" tolerance {100*LAW_TOL:.1f} %)")
            fails += not ok_law
        if "range_warning" in checks:
            print(("PASS: " if ok_warn else "FAIL: ") + f"dragCurve/{name}/range_warning"
                  f" ({nwarn} printed, {'in' if in_range else 'outside'} {range_text})")
            fails += not ok_warn
    write(out, results, ", ".join(sorted(run_commits)), quick)
    return 1 if fails else 0


def write(out, results, commit, quick):
    name = "dragCurve-quick" if quick else "dragCurve"
    keys = ["law", "Re_t", "d", "rho_p", "nu", "u_sim", "u_reference", "rel_err", "tolerance", "in_range",
            "u_law", "law_err", "coupling_err", "drift", "warnings", "wall_s", "verdict"]
    with open(os.path.join(out, name + ".csv"), "w") as f:
        f.write(",".join(keys) + "\n")
        for r in results:
            f.write(",".join(f"{r[k]:.6g}" if isinstance(r[k], float) else str(r[k]) for k in keys) + "\n")
    with open(os.path.join(out, name + ".md"), "w") as f:
        f.write(f"Terminal velocity of one sphere (d = 2 mm, rho_f = 1000 kg/m3) against Clift, Grace & Weber"
                f" (1978) Table 5.2; runs at commit {commit}.\n\n")
        f.write("| law | Re_t | rho_p (kg/m3) | nu (m2/s) | u_sim (m/s) | u_ref (m/s) | error | tolerance |"
                " in range | verdict | law alone | coupling | drift | warnings | wall (s) |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in results:
            f.write(f"| {r['law']} | {r['Re_t']:.3g} | {r['rho_p']:g} | {r['nu']:g} | {r['u_sim']:.5f} |"
                    f" {r['u_reference']:.5f} | {100*r['rel_err']:+.2f} % | {100*r['tolerance']:.2f} % |"
                    f" {'yes' if r['in_range'] else 'no'} | {r['verdict']} | {100*r['law_err']:+.2f} % |"
                    f" {100*r['coupling_err']:+.2f} % |"
                    f" {100*r['drift']:+.2f} % | {r['warnings']} | {r['wall_s']:.0f} |\n")
    print(f"dragCurve: wrote {os.path.join(out, name + '.csv')} and .md")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
