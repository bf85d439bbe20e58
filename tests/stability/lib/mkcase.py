#!/usr/bin/python3
"""mkcase.py -- make a case directory of the stability suite from a template.

    mkcase.py <template dir> <case dir> [KEY=value ...]

Copies the template, replaces every @KEY@ with its value (defaults below, overridden by the
arguments, plus derived keys), writes DEM/particles.in (LIGGGHTS create_atoms lines) and stops with
an error if a @KEY@ is left. Lengths: *_MM in millimetres, *_M in metres.

Particle layouts (LAYOUT):
  bed     PER_ROW x PER_ROW particles per layer (PER_ROW odd), LAYERS layers: in x and y the first and
          last particle touch the side walls (centre at r), the middle one sits on the plane
          x = width/2 + CENTRE_OFFSET x r (straddling the processor boundary of the np = 2 runs; with
          the default 0 its centre is exactly on the boundary plane); the others are spread
          evenly between; layers start touching the bottom wall, LAYER_GAP_MM apart (surface to surface);
          each particle's z is jittered by up to JITTER x d (seeded, reproducible).
  single  one particle at (X_MM, Y_MM, Z_MM).
  list    POSITIONS_MM = "x y z; x y z; ..."
"""
import os, random, re, shutil, sys

DEFAULTS = {
    "END_TIME": "0.05",
    "WRITE_INTERVAL": "0.025",
    "ADJUST_TIME_STEP": "no",
    "MAX_CO": "0.5",
    "WIDTH_MM": "10",
    "HEIGHT_MM": "40",
    "D_MM": "2",
    "D_OVER_DX": "1",
    "COUPLING_INTERVAL": "20",
    "IMPLICIT_DRAG": "true",
    "VOID_FRACTION_MODEL": "bigParticle",
    "EXPANSION_FACTOR": "5",
    "ALPHA_MIN": "0.3",
    "BACKGROUND_FIELDS": "off",
    "REACTION_KERNEL": "voidFraction",
    "DEM_MAX_IMPACT_VELOCITY": "1",
    "RHO_F": "1000",
    "NU_F": "1e-06",
    "RHO_P": "2500",
    "INLET_VELOCITY": "0.05",
    "YOUNGS_MODULUS": "1e7",
    "DEM_TIMESTEP": "5e-6",
    "DUMP_EVERY": "1000",
    "VELOCITY_COMMANDS": "",
    "EXTRA_COUPLING": "",
    "LAYOUT": "bed",
    "PER_ROW": "5",
    "LAYERS": "3",
    "LAYER_GAP_MM": "0.3",
    "JITTER": "0.02",
    "SEED": "1",
    "CENTRE_OFFSET": "0",
    "HYDROSTATIC_INIT": "true",
}


def fmt(x):
    return "%.12g" % x


def particles(v):
    d = float(v["D_MM"]) * 1e-3
    r = d / 2
    W = float(v["WIDTH_MM"]) * 1e-3
    out = []
    if v["LAYOUT"] == "single":
        out.append((float(v["X_MM"]) * 1e-3, float(v["Y_MM"]) * 1e-3, float(v["Z_MM"]) * 1e-3))
    elif v["LAYOUT"] == "list":
        for item in v["POSITIONS_MM"].split(";"):
            if item.strip():
                out.append(tuple(float(c) * 1e-3 for c in item.split()))
    elif v["LAYOUT"] == "bed":
        n = int(v["PER_ROW"])
        if n < 3 or n % 2 == 0:
            sys.exit("mkcase.py: PER_ROW must be odd and >= 3")
        # first/last touch the walls, middle on W/2, others evenly between
        xs = [r + (W - 2 * r) * i / (n - 1) for i in range(n)]
        xs[n // 2] = W / 2 + float(v["CENTRE_OFFSET"]) * r
        if xs[1] - xs[0] < d * (1 - 1e-9):
            sys.exit("mkcase.py: %d particles of %g mm do not fit in a row of %g mm" % (n, d * 1e3, W * 1e3))
        rng = random.Random(int(v["SEED"]))
        jit = float(v["JITTER"]) * d
        gap = float(v["LAYER_GAP_MM"]) * 1e-3
        for k in range(int(v["LAYERS"])):
            z0 = r + k * (d + gap + 2 * jit)
            for y in xs:
                for x in xs:
                    z = z0 + (jit * rng.random() if k > 0 else 0.0)
                    out.append((x, y, z))
    else:
        sys.exit("mkcase.py: unknown LAYOUT %s" % v["LAYOUT"])
    return out


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    tmpl, case = sys.argv[1], sys.argv[2]
    v = dict(DEFAULTS)
    for a in sys.argv[3:]:
        k, _, val = a.partition("=")
        v[k] = val
    d_mm = float(v["D_MM"])
    dx = d_mm / float(v["D_OVER_DX"])
    W, H = float(v["WIDTH_MM"]), float(v["HEIGHT_MM"])
    v.setdefault("NXY", str(int(round(W / dx))))
    v.setdefault("NZ", str(int(round(H / dx))))
    v["WIDTH_M"] = fmt(W * 1e-3)
    v["HEIGHT_M"] = fmt(H * 1e-3)
    v["DIAMETER_M"] = fmt(d_mm * 1e-3)
    v.setdefault("GAUSSIAN_BANDWIDTH", fmt(max(1.5 * dx, d_mm) * 1e-3))
    v.setdefault("SKIN", fmt(0.25 * d_mm * 1e-3))
    v["VELOCITY_COMMANDS"] = v["VELOCITY_COMMANDS"].replace(";", "\n")

    if os.path.exists(case):
        shutil.rmtree(case)
    shutil.copytree(tmpl, case)
    left = set()
    for root, _, files in os.walk(case):
        for f in files:
            p = os.path.join(root, f)
            s = open(p).read()
            s = re.sub(r"@([A-Z0-9_]+)@", lambda m: v.get(m.group(1), m.group(0)), s)
            left.update(re.findall(r"@([A-Z0-9_]+)@", s))
            open(p, "w").write(s)
    if left:
        sys.exit("mkcase.py: no value for " + ", ".join(sorted(left)))
    pts = particles(v)
    W_m, H_m = W * 1e-3, H * 1e-3
    with open(os.path.join(case, "DEM", "particles.in"), "w") as f:
        f.write("# %d particles (mkcase.py LAYOUT %s)\n" % (len(pts), v["LAYOUT"]))
        for x, y, z in pts:
            if not (0 <= x <= W_m and 0 <= y <= W_m and 0 <= z <= H_m):
                sys.exit("mkcase.py: particle (%g %g %g) outside the box" % (x, y, z))
            f.write("create_atoms 1 single %s %s %s units box\n" % (fmt(x), fmt(y), fmt(z)))
        if pts:
            f.write("set group all diameter %s density %s\n" % (v["DIAMETER_M"], v["RHO_P"]))
        # initial velocities belong to a fresh start only (a restart reads them from its file)
        f.write(v["VELOCITY_COMMANDS"] + "\n")
    os.makedirs(os.path.join(case, "post"), exist_ok=True)
    with open(os.path.join(case, "case.params"), "w") as f:
        for k in sorted(v):
            f.write("%s=%s\n" % (k, v[k]))
        f.write("N_PARTICLES=%d\n" % len(pts))


if __name__ == "__main__":
    main()
