#!/usr/bin/python3
"""Instantaneous profiles of a DPMFoam Mueller-bed run in the format of validation/muller/profiles.py.

    dpmProfiles.py <case dir> [--keep]

The coupled solver samples alpha, alphaP and alphaPUs along y at mid-thickness (x = 5 mm) every
0.01 s with a `sets` function object (cellPoint interpolation) into
postProcessing/profiles/<t>/z<h>_*.csv. DPMFoam has no particle-velocity field, so this script
makes the same files, with the same sampling, from what the case's function objects write at the
same times:
  - alpha (gas volume fraction): DPMFoam's own alpha.air, sampled during the run by the
    `gasProfiles` sets function object (same points, cellPoint): postProcessing/gasProfiles/<t>/.
    It is the field the solver uses: max(1 - theta, 1 - alphaMax), theta = volume of the
    particles whose centre is in the cell / cell volume.
  - alphaP and alphaPUs (particle volume fraction, particle volume flux density): every
    particle's position and velocity (`particleU` dataCloud function object,
    postProcessing/particleU/kinematicCloud_<time index>.dat, time = index x deltaT) are binned by
    centre into the cells of the run's mesh, exactly as DPMFoam's theta but not clipped:
        alphaP_c = sum_p V_p / V_c,   alphaPUs_c = sum_p V_p U_p / V_c,
    written as cell fields (zeroGradient at the walls) into a scratch case <case>/particleBins
    (the run's mesh), and sampled there by OpenFOAM's postProcess with the same sets and cellPoint
    interpolation as the coupled case. profiles.py then takes mean(alphaPUs_z) / mean(alphaP): the
    solid-volume-weighted vertical particle velocity.
  - alphaCheck = max(1 - alphaP_c, 1 - alphaMax) is sampled too: it must reproduce the solver's
    alpha.air; the largest difference is reported (a check of the binning and the cell order).
Writes postProcessing/profiles/<t>/z<h>_dpm.csv (y,alpha,alphaP,alphaPUs_0,alphaPUs_1,alphaPUs_2,
alphaCheck) and postProcessing/particleStats.csv (per sample: particle count, mean and 90th
percentile of the particle height, mean and rms vertical particle velocity, fraction of the solid
volume above alphaMax, which DPMFoam clips). Re-running redoes every sample (harmless); the particle
files are gzipped after use unless --keep.
"""
import glob, gzip, math, os, re, shutil, subprocess, sys
import numpy as np


def read_text(path):
    with open(path) as f:
        return re.sub(r"//.*", "", f.read())


def mesh_of(case):
    txt = read_text(os.path.join(case, "system", "blockMeshDict"))
    scale = float(re.search(r"\bscale\s+([0-9.eE+-]+)\s*;", txt).group(1))
    vtxt = re.search(r"vertices\s*\((.*?)\)\s*;", txt, re.S).group(1)
    v = np.array([[float(a) for a in t.split()] for t in re.findall(r"\(([^()]*)\)", vtxt)]) * scale
    n = [int(a) for a in re.search(r"hex\s*\([^)]*\)\s*\((\d+)\s+(\d+)\s+(\d+)\)", txt).groups()]
    return v.min(axis=0), v.max(axis=0), np.array(n)


def read_set(path):
    with open(path) as f:
        lines = [l.strip() for l in f if l.strip()]
    header = re.split(r"[,\s]+", lines[0].lstrip("#").strip())
    rows = np.array([[float(v) for v in re.split(r"[,\s]+", l)] for l in lines[1:] if not l.startswith("#")])
    return header, rows


def write_field(path, name, values):
    vec = values.ndim == 2
    with open(path, "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class %s; object %s; }\n"
                % ("volVectorField" if vec else "volScalarField", name))
        f.write("dimensions [0 %d %d 0 0 0 0];\n" % ((1, -1) if vec else (0, 0)))
        f.write("internalField nonuniform List<%s> %d\n(\n" % ("vector" if vec else "scalar", len(values)))
        if vec:
            f.write("\n".join("(%.9g %.9g %.9g)" % tuple(v) for v in values))
        else:
            f.write("\n".join("%.9g" % v for v in values))
        f.write('\n);\nboundaryField { ".*" { type zeroGradient; } }\n')


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    keep = "--keep" in args
    case = os.path.abspath([a for a in args if not a.startswith("--")][0])
    lo, hi, n = mesh_of(case)
    h = (hi - lo) / n
    vc = float(np.prod(h))
    ncell = int(np.prod(n))
    cd = read_text(os.path.join(case, "system", "controlDict"))
    dt = float(re.search(r"^\s*deltaT\s+([0-9.eE+-]+)\s*;", cd, re.M).group(1))
    sets = re.search(r"gasProfiles\s*\{.*?\bsets\s*\((.*?)\n\s*\);", cd, re.S).group(1)
    cp = read_text(os.path.join(case, "constant", "kinematicCloudProperties"))
    d = float(re.search(r"fixedValueDistribution\s*\{\s*value\s+([0-9.eE+-]+)", cp).group(1))
    amax = float(re.search(r"\balphaMax\s+([0-9.eE+-]+)\s*;", cp).group(1))
    vp = math.pi / 6 * d ** 3
    pp = os.path.join(case, "postProcessing")

    gas = {}
    for dd in glob.glob(os.path.join(pp, "gasProfiles", "*")):
        try:
            gas[float(os.path.basename(dd))] = os.path.basename(dd)
        except ValueError:
            pass
    files = {}
    for f in sorted(glob.glob(os.path.join(pp, "particleU", "kinematicCloud_*.dat*"))):
        idx = int(re.search(r"_(\d+)\.dat", os.path.basename(f)).group(1))
        if idx not in files or not f.endswith(".gz"):
            files[idx] = f

    # scratch case on the run's mesh
    bins = os.path.join(case, "particleBins")
    shutil.rmtree(bins, ignore_errors=True)
    os.makedirs(os.path.join(bins, "system"))
    os.makedirs(os.path.join(bins, "constant"))
    os.symlink(os.path.join(case, "constant", "polyMesh"), os.path.join(bins, "constant", "polyMesh"))
    for f in ("fvSchemes", "fvSolution"):
        shutil.copy(os.path.join(case, "system", f), os.path.join(bins, "system"))
    with open(os.path.join(bins, "system", "controlDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }\n"
                "application postProcess; startFrom startTime; startTime 0; stopAt endTime; endTime 1e9;\n"
                "deltaT 1; writeControl timeStep; writeInterval 1; writeFormat ascii; writePrecision 8;\n"
                "timeFormat general; timePrecision 8;\n"
                "functions\n{\n    particleProfiles\n    {\n        type sets; libs (\"libsampling.so\");\n"
                "        setFormat csv; interpolationScheme cellPoint;\n"
                "        fields ( alphaP alphaPUs alphaCheck );\n"
                "        sets\n        (" + sets + "\n        );\n    }\n}\n")

    stats, todo, unmatched = {}, {}, 0
    for idx in sorted(files):
        t = idx * dt
        match = [tg for tg in gas if abs(tg - t) < 0.5 * dt]
        if not match:
            unmatched += 1
            continue
        tname = gas[match[0]]
        opener = gzip.open if files[idx].endswith(".gz") else open
        with opener(files[idx], "rt") as f:
            data = np.loadtxt(f, comments="#", ndmin=2)
        x, u = data[:, 0:3], data[:, 3:6]
        c = np.clip(((x - lo) / h).astype(int), 0, n - 1)
        lin = c[:, 0] + n[0] * (c[:, 1] + n[1] * c[:, 2])          # blockMesh order: x fastest
        alphaP = np.bincount(lin, minlength=ncell) * vp / vc
        alphaPU = np.stack([np.bincount(lin, weights=u[:, k], minlength=ncell) * vp / vc for k in range(3)], 1)
        os.makedirs(os.path.join(bins, tname))
        write_field(os.path.join(bins, tname, "alphaP"), "alphaP", alphaP)
        write_field(os.path.join(bins, tname, "alphaPUs"), "alphaPUs", alphaPU)
        write_field(os.path.join(bins, tname, "alphaCheck"), "alphaCheck", np.maximum(1 - alphaP, 1 - amax))
        z = x[:, 2]
        clipped = np.sum(np.maximum(alphaP - amax, 0.0)) * vc / (len(z) * vp)
        stats[tname] = [match[0], len(z), z.mean(), np.percentile(z, 90), u[:, 2].mean(),
                        math.sqrt(np.mean(u[:, 2] ** 2)), clipped]
        todo[tname] = files[idx]
    if not todo:
        sys.exit(f"dpmProfiles.py: no particle samples with a gas sample under {pp}")

    with open(os.path.join(bins, "log.postProcess"), "w") as log:
        rc = subprocess.call(["postProcess", "-case", bins, "-fields", "(alphaP alphaPUs alphaCheck)"],
                             stdout=log, stderr=subprocess.STDOUT)
    if rc != 0:
        sys.exit(f"dpmProfiles.py: postProcess failed ({bins}/log.postProcess)")

    worst = 0.0
    for tname in sorted(todo, key=float):
        pdir = os.path.join(bins, "postProcessing", "particleProfiles", tname)
        outdir = os.path.join(pp, "profiles", tname)
        os.makedirs(outdir, exist_ok=True)
        for gpath in sorted(glob.glob(os.path.join(pp, "gasProfiles", tname, "z*_alpha.air.csv"))):
            setname = os.path.basename(gpath).split("_")[0]
            header, rows = read_set(gpath)
            cols = {"y": rows[:, header.index("y")], "alpha": rows[:, header.index("alpha.air")]}
            for ppath in glob.glob(os.path.join(pdir, setname + "_*.csv")):
                hh, rr = read_set(ppath)
                if not np.allclose(rr[:, hh.index("y")], cols["y"]):
                    sys.exit(f"dpmProfiles.py: sample points differ: {ppath} vs {gpath}")
                for j, name in enumerate(hh):
                    if name != "y":
                        cols[name] = rr[:, j]
            names = ["y", "alpha", "alphaP", "alphaPUs_0", "alphaPUs_1", "alphaPUs_2", "alphaCheck"]
            missing = [k for k in names if k not in cols]
            if missing:
                sys.exit(f"dpmProfiles.py: {tname} {setname}: no {missing} (see {bins}/log.postProcess)")
            worst = max(worst, float(np.max(np.abs(cols["alphaCheck"] - cols["alpha"]))))
            with open(os.path.join(outdir, f"{setname}_dpm.csv"), "w") as f:
                f.write(",".join(names) + "\n")
                for k in range(len(cols["y"])):
                    f.write(",".join(f"{cols[c][k]:.8g}" for c in names) + "\n")
        if not keep and not todo[tname].endswith(".gz"):
            with open(todo[tname], "rb") as fi, gzip.open(todo[tname] + ".gz", "wb") as fo:
                shutil.copyfileobj(fi, fo)
            os.remove(todo[tname])
        shutil.rmtree(os.path.join(bins, tname))

    with open(os.path.join(pp, "particleStats.csv"), "w") as f:
        f.write("# per sample: particle count, mean and 90th percentile particle height (m), mean and rms "
                "vertical particle velocity (m/s), fraction of the solid volume above alphaMax (clipped by DPMFoam)\n")
        f.write("t,n,z_mean,z_p90,uz_mean,uz_rms,clipped_solid_fraction\n")
        for tname in sorted(stats, key=float):
            s = stats[tname]
            f.write(f"{s[0]:.6g},{s[1]},{s[2]:.6g},{s[3]:.6g},{s[4]:.6g},{s[5]:.6g},{s[6]:.6g}\n")
    print(f"dpmProfiles.py: {len(todo)} samples written to {os.path.join(pp, 'profiles')}"
          + (f", {unmatched} particle files without a gas sample skipped" if unmatched else "")
          + f"; binned gas fraction vs the solver's alpha.air: max difference {worst:.2g}", flush=True)
    s = stats[max(stats, key=float)]
    print(f"dpmProfiles.py: last sample t = {s[0]:.6g} s: {s[1]} particles, mean height {s[2] * 1e3:.2f} mm, "
          f"90 % below {s[3] * 1e3:.2f} mm, mean v_z {s[4]:.3g} m/s, rms v_z {s[5]:.3g} m/s, "
          f"solid volume above alphaMax {100 * s[6]:.2g} %", flush=True)


main()
