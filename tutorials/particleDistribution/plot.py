#!/usr/bin/python3
"""Figures of the particleDistribution tutorial, comparable to Zhang et al. 2023 (Phys. Fluids 35,
113330) Figs. 6-9, from the CSV files written by build/particle_distribution.

    ./plot.py [RESULTS_DIR]      (default: results next to this script)

Writes into RESULTS_DIR:
    fig6_contours_M2.png       alpha_p in the mid-z layer, every method, dx/d = 1 (colour 0..0.63)
    fig7_profiles.png          alpha_p along y = 0 (z average), every method, meshes M1-M4
    fig8_histograms_M2.png     alpha_p histograms over the statistics cells, dx/d = 1
    fig9_bigParticle_n_M3.png  bigParticle with n = 2..5 along y = 0, dx/d = 0.67
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
RES = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "results")
ALPHA_MAX = 0.63  # random close packing, the colour/axis limit of Zhang et al.'s (2023) figures

# (file tag, label) in the order of the figures
METHODS = [
    ("centre", "centre (PCM)"),
    ("divided", "divided (DPVM)"),
    ("bigParticle", "bigParticle original"),
    ("bigParticle_n2", "bigParticle n=2"),
    ("bigParticle_n3", "bigParticle n=3"),
    ("bigParticle_n4", "bigParticle n=4"),
    ("bigParticle_n5", "bigParticle n=5"),
    ("twoGrid", "twoGrid (3R)"),
    ("gaussian", "gaussian b=3d"),
    ("exact", "exact"),
    ("diffusion", "diffusion b=6d (centre)"),
    ("dividedDiffusion", "diffusion b=6d (divided)"),
]
# The expansion kernels are not wall-mirrored (as in the seed), so with walls 4d apart in z they
# load the middle z layers more than the outer ones; the z average is the slab's value along y = 0.
PROFILE_COLUMN = "alpha_zavg"
MESHES = [(1, "M1 dx/d=2"), (2, "M2 dx/d=1"), (3, "M3 dx/d=0.67"), (4, "M4 dx/d=0.5")]


def path(name):
    return os.path.join(RES, name)


def read_profile(tag, mesh, column=None):
    """x/d and alpha_p along the row of cells nearest y = 0, averaged over the z layers (default) or
    in the mid-z layer (column="alpha_midz")."""
    p = path("profile_%s_M%d.csv" % (tag, mesh))
    if not os.path.exists(p):
        return None
    with open(p) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return (np.array([float(r["x_over_d"]) for r in rows]), np.array([float(r[column or PROFILE_COLUMN]) for r in rows]))


def grid_axes(n, ncol, w=3.4, h=3.0):
    nrow = (n + ncol - 1) // ncol
    fig, axes = plt.subplots(nrow, ncol, figsize=(w * ncol, h * nrow), squeeze=False)
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    return fig, axes.flat


def label_panel(ax, title, xlabel, ylabel):
    """The small-print title and axis labels of one panel of a grid figure."""
    ax.set_title(title, fontsize=9)
    ax.set_xlabel(xlabel, fontsize=8)
    ax.set_ylabel(ylabel, fontsize=8)
    ax.tick_params(labelsize=7)


def fig6():
    present = [(t, l) for t, l in METHODS if os.path.exists(path("field_%s_M2.csv" % t))]
    if not present:
        print("plot.py: no field_*_M2.csv, skipping fig6")
        return
    fig, axes = grid_axes(len(present), 4, 3.6, 3.2)
    im = None
    for ax, (tag, label) in zip(axes, present):
        a = np.loadtxt(path("field_%s_M2.csv" % tag), delimiter=",", comments="#")
        ny, nx = a.shape
        x = np.linspace(-80, 80, nx + 1)
        y = np.linspace(-80, 80, ny + 1)
        im = ax.pcolormesh(x, y, a, vmin=0, vmax=ALPHA_MAX, cmap="jet", shading="flat")
        ax.set_xlim(-40, 40)
        ax.set_ylim(-40, 40)
        ax.set_aspect("equal")
        label_panel(ax, label, "x/d", "y/d")
    fig.suptitle("alpha_p, mid-z layer, dx/d = 1 (M2); colour 0..0.63, window |x|,|y| <= 40d", fontsize=10)
    fig.tight_layout(rect=(0, 0, 0.93, 0.96))
    cax = fig.add_axes((0.94, 0.15, 0.015, 0.7))
    fig.colorbar(im, cax=cax, label="alpha_p", extend="max")
    fig.savefig(path("fig6_contours_M2.png"), dpi=110)
    plt.close(fig)


def fig7():
    fig, axes = grid_axes(len(METHODS), 3, 4.2, 3.0)
    for ax, (tag, label) in zip(axes, METHODS):
        for mesh, mlabel in MESHES:
            pr = read_profile(tag, mesh)
            if pr is not None:
                ax.plot(pr[0], pr[1], lw=0.9, label=mlabel)
        ax.axhline(0.3, color="k", lw=0.5, ls=":")
        ax.set_xlim(-40, 40)
        ax.set_ylim(0, ALPHA_MAX)
        label_panel(ax, label, "x/d", "alpha_p")
    axes[0].legend(fontsize=7, loc="upper right")
    fig.suptitle("alpha_p along y = 0 (row of cells nearest y = 0, averaged over z); axis clipped at 0.63 as in Zhang et al. (2023)", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    fig.savefig(path("fig7_profiles.png"), dpi=110)
    plt.close(fig)


def fig8():
    p = path("histogram_M2.csv")
    if not os.path.exists(p):
        print("plot.py: no histogram_M2.csv, skipping fig8")
        return
    data = {}
    with open(p) as f:
        rows = csv.DictReader(line for line in f if not line.startswith("#"))
        for r in rows:
            tag = r["method"] + ("_n" + r["n_expand"] if r["n_expand"] else "")
            data.setdefault(tag, []).append((float(r["bin_lo"]), float(r["bin_hi"]), float(r["density"])))
    present = [(t, l) for t, l in METHODS if t in data]
    fig, axes = grid_axes(len(present), 4, 3.4, 2.6)
    for ax, (tag, label) in zip(axes, present):
        lo, hi, dens = (np.array(v) for v in zip(*data[tag]))
        ax.bar(lo, dens, width=hi - lo, align="edge", color="tab:blue", edgecolor="none")
        ax.axvline(0.3, color="k", lw=0.5, ls=":")
        ax.set_xlim(0, 0.7)
        label_panel(ax, label, "alpha_p", "probability density")
    fig.suptitle("alpha_p histograms, dx/d = 1 (M2), cells with |x|,|y| <= 20d; bin 0.01", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    fig.savefig(path("fig8_histograms_M2.png"), dpi=110)
    plt.close(fig)


def fig9():
    fig, ax = plt.subplots(figsize=(7, 4))
    for tag, label in [("bigParticle", "original (n=0)")] + [("bigParticle_n%d" % n, "n=%d" % n) for n in (2, 3, 4, 5)]:
        pr = read_profile(tag, 3)
        if pr is not None:
            ax.plot(pr[0], pr[1], lw=0.9, label=label, alpha=0.5 if tag == "bigParticle" else 1.0)
    ax.axhline(0.3, color="k", lw=0.5, ls=":")
    ax.set_xlim(-40, 40)
    ax.set_ylim(0, ALPHA_MAX)
    ax.set_xlabel("x/d")
    ax.set_ylabel("alpha_p")
    ax.set_title("bigParticle, expansion factor n, along y = 0 (z average), dx/d = 0.67 (M3)", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path("fig9_bigParticle_n_M3.png"), dpi=110)
    plt.close(fig)


def main():
    if not os.path.isdir(RES):
        sys.exit("plot.py: no results directory %s (run ./Allrun first)" % RES)
    fig6()
    fig7()
    fig8()
    fig9()
    print("plot.py: figures written to %s" % RES)


if __name__ == "__main__":
    main()
