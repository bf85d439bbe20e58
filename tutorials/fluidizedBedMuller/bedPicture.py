#!/usr/bin/python3
"""A picture of a Mueller-bed run at its last write time: the particles over the gas fraction, beside
the headline profile against the MR data.

    bedPicture.py <run dir> <U> [-o PNG]          (default <run>/results/bed.png)

Left: the gas fraction alpha averaged over the bed's depth (the 10 mm thickness, the x direction),
as an image over the width (y) and the height (z), with the particles of the run's lagrangian cloud
(<time>/lagrangian/particles/positions, written by writeParticleCloud) drawn over it, projected on
the same plane. Right: the time-averaged, depth-averaged gas fraction from particles binned by the
cell of their centre at z = 16.4 mm (results/, from profiles.py) with its batch-means error, against
the MR data of the same inlet velocity (validation/muller/data). Reads OpenFOAM's ascii and binary
formats. A parallel run is read at its reconstructed last write time (Allrun runs reconstructPar).
"""
import os, re, sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(here, "..", ".."), "etc",
                                "python"))  # the project's reader of written fields
from foam_fields import FieldFormatError, read_cloud_positions, read_internal_field  # noqa: E402
DATA = os.path.join(here, "..", "..", "validation", "muller", "data")


def last_time(run):
    times = [d for d in os.listdir(run) if re.fullmatch(r"[0-9.eE+-]+", d) and float(d) > 0
             and os.path.isdir(os.path.join(run, d, "lagrangian"))]
    if not times:
        sys.exit(f"bedPicture.py: {run} has no write time with a particle cloud (writeParticleCloud off?)")
    return max(times, key=float)


def main():
    args = sys.argv[1:]
    if len(args) < 2:
        sys.exit(__doc__)
    run, U = args[0], args[1]
    out = args[args.index("-o") + 1] if "-o" in args else os.path.join(run, "results", "bed.png")
    t = last_time(run)
    try:
        pos = read_cloud_positions(os.path.join(run, t, "lagrangian", "particles", "positions"))
        alpha = read_internal_field(os.path.join(run, t, "alpha"))
    except FieldFormatError as e:
        sys.exit(f"bedPicture.py: {e}")
    block = open(os.path.join(run, "system", "blockMeshDict")).read()
    nx, ny, nz = map(int, re.search(r"hex\s*\([^)]*\)\s*\((\d+)\s+(\d+)\s+(\d+)\)", block).groups())
    if len(alpha) != nx * ny * nz:
        sys.exit(f"bedPicture.py: {run}/{t}/alpha has {len(alpha)} cells, the mesh {nx * ny * nz}")
    W, H = 44.0, 120.0  # mm (blockMeshDict)
    # depth average: blockMesh numbers cells x fastest, then y, then z
    img = [[sum(alpha[i + nx * (j + ny * k)] for i in range(nx)) / nx for j in range(ny)] for k in range(nz)]

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(9, 6), gridspec_kw={"width_ratios": [1, 1.4]})
    top = 70.0  # mm shown: the bed and its freeboard
    kt = int(top / H * nz)
    im = ax.imshow(img[:kt], origin="lower", extent=(0, W, 0, kt * H / nz), cmap="Blues_r", vmin=0.35, vmax=1.0,
                   aspect="equal")
    ys = [1e3 * p[1] for p in pos if 1e3 * p[2] <= top]
    zs = [1e3 * p[2] for p in pos if 1e3 * p[2] <= top]
    ax.scatter(ys, zs, s=0.5, c="tab:red", alpha=0.5, linewidths=0)
    ax.set_xlabel("y (mm)")
    ax.set_ylabel("z (mm)")
    ax.set_title(f"t = {float(t):.3g} s: {len(pos)} particles over the\ndepth-averaged gas fraction", fontsize=9)
    fig.colorbar(im, ax=ax, fraction=0.05, label="gas fraction")

    prof = os.path.join(run, "results", "profile_voidfractiondepthbinned_z16.4mm.csv")
    data = os.path.join(DATA, f"mueller_U{U}_voidfraction_z16.4mm_MR.csv")
    if os.path.exists(prof):
        rows = [l.strip().split(",") for l in open(prof) if l[0].isdigit()]
        x = [1e3 * float(r[0]) for r in rows]
        y = [float(r[1]) for r in rows]
        e = [float(r[2]) if r[2] != "nan" else 0.0 for r in rows]
        note = open(prof).readline().strip("# \n")
        bx.errorbar(x, y, yerr=e, fmt="o-", ms=3, label="simulation (binned, depth-averaged)")
        w = re.search(r"window \(([^\]]*)\] s", note)
        bx.set_title("z = 16.4 mm" + (f", averaged over ({w.group(1)}] s" if w else ""), fontsize=9)
    if os.path.exists(data):
        rows = [l.strip().split(",") for l in open(data) if l[0].isdigit()]
        bx.plot([1e3 * float(r[0]) for r in rows], [float(r[1]) for r in rows], "ks", ms=4, label="MR data (Mueller et al.)")
    bx.set_xlabel("y (mm)")
    bx.set_ylabel("time-averaged gas fraction")
    bx.set_xlim(0, W)
    bx.legend(fontsize=8)
    fig.tight_layout()
    os.makedirs(os.path.dirname(out) or ".", exist_ok=True)
    fig.savefig(out, dpi=110)
    print(f"bedPicture.py: {out} (t = {t} s, {len(pos)} particles)")


if __name__ == "__main__":
    main()
