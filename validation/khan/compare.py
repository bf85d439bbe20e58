#!/usr/bin/python3
"""compare.py -- binaryBedKhan runs against the references: summary.csv, table.md, alpha_p_profiles.png.

    compare.py OUT RUN [RUN ...]

RUN: a run directory of tutorials/binaryBedKhan (runs/<method>_U<U>_<mode>[_background][_np<N>][_E<E>][_relax<TAU>]/)
that postprocess.py has processed (its results/bed.csv, layers.csv, profiles.csv, messages.txt; the
case, the stage costs and the commit are bed.csv's columns, so a copy of results/ alone will do, as
validation/khan/results/runs/ keeps them). The
runs compared must share one averaging window and one Young's modulus (refused otherwise: their beds
differ; a long run post-processed at 6 s has the short mode's window); velocities, methods, background fields and ranks may differ. OUT gets:

- summary.csv, one row per run and species, with the columns
  method,U,species,alpha_p_plateau,alpha_p_sem,alpha_p_reference,layer_top_mm,dp_pa,dp_reference_pa,
  mixing_width_mm,window_s,wall_s,coupling_share,wall_force_share,fluid_wall_shear_share
  alpha_p_reference: Richardson-Zaki with the Garside-Al-Dibouni exponent (the paper's Fig. 16
  line; references.py); dp_pa, dp_reference_pa, mixing_width_mm: the whole bed's (the same on both
  rows of a run); coupling_share: on the solver's last "Stage timers" line, every stage but DEM,
  fluid and fields over the sum of all stages (a continued run: each start's last line, summed;
  postprocess.py); wall_force_share: the walls' share of the bed's buoyant weight in the window
  (their z forces on the particles, DEM/tubeWalls.liggghts; empty for a run made before the walls
  stored them); fluid_wall_shear_share: the fluid's shear force on the side walls over the buoyant
  weight, mean over the window's written times (postprocess.py; empty for a run post-processed before
  it, or with no written time in the window), which the frictional pressure drop carries besides the
  particles: dp A = weight - walls' support + fluid wall shear;
  wall_s: the run's wall seconds from its solver log (postprocess.py: pauses and stretches computed
  twice left out); window_s: from the window's first to its last dump;
  method: the run's method, "+background" with background fields (bed.csv's background column, or
  a name part "background" in a run post-processed before that column);
- table.md: the same with the drag-law equilibrium, the pressure-slope alpha_p and the mean heights;
- error_vs_runtime.png: each run's plateau error against Richardson-Zaki per species against its
  core-seconds (wall_s x ranks) and its coupling share;
- alpha_p_profiles.png: per velocity, each species' time-mean alpha_p(z) of every run (band: +- 2
  batch-means sem) and, below, the method's own alpha_p on the tube's axis at the end (the paper's
  Fig. 16), against the two references drawn over the height of the ideal layers (big on the
  distributor, small on top of it);
- the runs' WARNING lines, and CHECK lines against the acceptance targets of issue 19 (big-layer
  plateau within 0.03 of Richardson-Zaki, pressure drop within 3 % of the buoyant weight, big below
  small): MET or MISSED, not PASS/FAIL (a comparison, not a test); beside the big-layer check, the
  Richardson-Zaki line with the wall correction of the 10 mm tube (references.py 2b), which the
  simulation (no wall term in its drag) is not held to.
"""
import csv, os, sys

# the project's Python library, etc/python (COARSEDEM_DIR: this file may run from a copy of its folder)
sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."), "etc", "python"))
import khan_references as ref  # noqa: E402
from khan_runs import one_case, read_run  # noqa: E402

HEADER = ("method,U,species,alpha_p_plateau,alpha_p_sem,alpha_p_reference,layer_top_mm,dp_pa,dp_reference_pa,"
          "mixing_width_mm,window_s,wall_s,coupling_share,wall_force_share,fluid_wall_shear_share")


# Zhang et al. (2023) §V.C, the binary bed's costs in multiples of the fluid solve's CPU time: the
# DEM about 23; the solid quantities per method (their names: PCM, big particle, diffusion based,
# DPVM); the fluid-phase reconstruction (background fields) about 2.69
PAPER_COST = {"DEM": 23.0, "centre": 3.85, "bigParticle": 4.37, "diffusion": 4.82, "divided": 4.91, "background": 2.69}


def shear(b):
    """bed.csv's fluid_wall_shear_share, '' where the run has none (older post-processing, no fields)."""
    v = b.get("fluid_wall_shear_share", "") or ""
    return "" if v in ("", "nan") else v


def percent(v):
    """'%+.2f %%' of a share given as text, '-' when there is none."""
    return "-" if v in ("", "nan", None) else "%+.2f %%" % (100 * float(v))


def summary_rows(runs):
    out = []
    for r in runs:
        b = r["bed"]
        for sp in ref.SPECIES:
            l = r["layers"][sp]
            out.append(dict(method=r["method"], U="%.3f" % float(b["U"]), species=sp,
                            alpha_p_plateau=l["alpha_p_plateau"], alpha_p_sem=l["alpha_p_sem"],
                            alpha_p_reference="%.5f" % float(l["alpha_p_richardson_zaki"]),
                            layer_top_mm=l["top_mm"], dp_pa=b["dp_pa"], dp_reference_pa=b["dp_weight_pa"],
                            mixing_width_mm=b["mixing_width_mm"], window_s=b["window_s"], wall_s=b["wall_s"],
                            coupling_share="%.4f" % r["share"],
                            wall_force_share=b.get("wall_force_share", "") or "",
                            fluid_wall_shear_share=shear(b)))
    return out


def write_table(path, runs, case):
    with open(path, "w") as f:
        f.write("Averaging window %s s, Young's modulus %s Pa.\n\n" % case)
        f.write("| run | species | alpha_p plateau ± sem | R-Z | drag eq. | plateau - R-Z | from dp slope | layer (mm) "
                "| mean height (mm) | its drift (mm) | dp (Pa) ± sem | weight (Pa) | dp err | mixing (mm) | window (s) | wall (s) "
                "| coupling | DEM / fluid | coupling / fluid | walls | fluid shear | dp - weight + walls - shear |\n")
        f.write("|" + "---|" * 22 + "\n")
        for r in runs:
            b = r["bed"]
            for sp in ref.SPECIES:
                l = r["layers"][sp]
                f.write("| %s | %s | %.4f ± %.4f | %.4f | %.4f | %+.4f | %.4f | %.1f..%.1f | %.2f ± %.2f | %+.2f | %.2f ± %.2f "
                        "| %.2f | %+.1f %% | %.1f ± %.1f | %g | %.0f | %.1f %% | %.1f | %.2f | %s | %s | %s |\n" % (
                            r["name"], sp, float(l["alpha_p_plateau"]), float(l["alpha_p_sem"]),
                            float(l["alpha_p_richardson_zaki"]), float(l["alpha_p_drag_equilibrium"]),
                            float(l["alpha_p_plateau"]) - float(l["alpha_p_richardson_zaki"]),
                            float(l["alpha_p_from_dp"]), float(l["bottom_mm"]), float(l["top_mm"]),
                            float(l["mean_height_mm"]), float(l["mean_height_sem_mm"]),
                            float(l["mean_height_drift_mm"]), float(b["dp_pa"]),
                            float(b["dp_sem_pa"]), float(b["dp_weight_pa"]), 100 * float(b["dp_rel_err"]),
                            float(b["mixing_width_mm"]), float(b["mixing_width_sem_mm"]), float(b["window_s"]),
                            float(b["wall_s"]), 100 * r["share"], r["dem_per_fluid"], r["coupling_per_fluid"],
                            percent(b.get("wall_force_share")), percent(shear(b)),
                            percent(b.get("dp_balance_residual"))))
        f.write("\nalpha_p: particle volumes binned by the cell of their centre, cross-section mean, time mean over "
                "the window (sem: batch means); R-Z: Richardson-Zaki with the Garside-Al-Dibouni exponent; drag eq.: "
                "the homogeneous layer under the code's Di Felice drag (references.py).\n")
        f.write("\nwalls: their z force on the particles (support); fluid shear: the fluid's shear force on the side "
                "walls, as the solver's momentum equation puts it there; both in % of the buoyant weight. The frictional "
                "pressure drop carries the weight less the walls' support plus the fluid's wall shear: the last column "
                "is what that balance leaves (postprocess.py).\n")
        f.write("\nCosts from the solver's stage timers (pauses left out): DEM / fluid and coupling / fluid are in "
                "multiples of the fluid solve's time, as Zhang et al. (2023, §V.C) give theirs for this bed: DEM about "
                "%g; solid quantities %g (PCM = centre), %g (big particle), %g (diffusion based), %g (DPVM = divided); "
                "the fluid-phase reconstruction (background fields) %g more. Their solid-quantity cost and our coupling "
                "stages (locate, kernel, alphaP, ghosts, forces, push, sources, monitor) need not count the same work.\n"
                % tuple(PAPER_COST[k] for k in ("DEM", "centre", "bigParticle", "diffusion", "divided", "background")))
        warnings = [w for r in runs for w in r["warnings"]]
        if warnings:
            f.write("\n" + "\n".join("- " + w for w in warnings) + "\n")


def reference_lines(ax, U, vols, z_top):
    """The two references of each species at U, drawn over its ideal layer (big on the distributor,
    small on top of it; heights from the run's solid volumes and Richardson-Zaki)."""
    z0 = 0.0
    for sp in ref.SPECIES:
        d = ref.SPECIES[sp][0]
        for alpha, style, label in ((ref.alpha_richardson_zaki(U, d), "k:", "Richardson-Zaki (the paper's line)"),
                                    (ref.alpha_drag_equilibrium(U, d), "k-.", "Di Felice equilibrium")):
            if alpha == alpha:
                h = min(ref.layer_height(alpha, vols[sp]), z_top - z0)
                ax.plot([alpha, alpha], [1e3 * z0, 1e3 * (z0 + h)], style, lw=1, label=label if sp == "big" else None)
        a_rz = ref.alpha_richardson_zaki(U, d)
        z0 += ref.layer_height(a_rz, vols[sp]) if a_rz == a_rz else 0


def palette_of(plt, methods):
    """One colour per method (tab10, tab20 beyond ten)."""
    cmap = plt.get_cmap("tab10" if len(methods) <= 10 else "tab20")
    return lambda method: cmap(methods.index(method) % cmap.N)


def plot(path, runs, plt):
    """Top row: each species' time-mean profile per run and velocity; bottom row: the method's
    alpha_p on the axis at the end (the paper's Fig. 16), both against the references."""
    us = sorted({float(r["bed"]["U"]) for r in runs})
    fig, axes = plt.subplots(2, len(us), figsize=(4.6 * len(us), 9.5), squeeze=False)
    colour_of = palette_of(plt, sorted({r["method"] for r in runs}))
    for col, U in enumerate(us):
        mine = [r for r in runs if float(r["bed"]["U"]) == U]
        top = 0.0
        for r in mine:
            colour = colour_of(r["method"])
            z = [float(p["z_mm"]) for p in r["prof"]]
            for sp, style in zip(ref.SPECIES, ("-", "--")):
                a = [float(p["alpha_" + sp]) for p in r["prof"]]
                e = [2 * float(p["alpha_%s_sem" % sp]) for p in r["prof"]]
                axes[0][col].plot(a, z, style, color=colour, lw=1.2, label="%s, %s (%s)" % (r["method"], sp, r["bed"]["mode"]))
                axes[0][col].fill_betweenx(z, [x - y for x, y in zip(a, e)], [x + y for x, y in zip(a, e)],
                                           color=colour, alpha=0.2)
                top = max([top] + [zz for zz, aa in zip(z, a) if aa > 0.01])
            if r["axis"]:
                key = next(k for k in r["axis"][0] if k.startswith("alphaP_method"))
                axes[1][col].plot([float(p[key]) for p in r["axis"]], [float(p["z_mm"]) for p in r["axis"]], "-",
                                  color=colour, lw=1.2, label="%s, t = %s s" % (r["method"], key.split("_t")[-1]))
        vols = {sp: 1e-9 * float(mine[0]["layers"][sp]["V_s_mm3"]) for sp in ref.SPECIES}
        zmax = min(120.0, max(top, 1e3 * sum(ref.layer_height(ref.alpha_richardson_zaki(U, ref.SPECIES[sp][0]), vols[sp])
                                                for sp in ref.SPECIES)) + 10)
        for row, xlabel in ((0, "alpha_p per species (cross-section, time mean)"),
                            (1, "the method's alpha_p on the axis at the end")):
            ax = axes[row][col]
            reference_lines(ax, U, vols, ref.HEIGHT)
            ax.set_title("U = %.3f m/s" % U, fontsize=10)
            ax.set_xlabel(xlabel, fontsize=9)
            ax.set_ylabel("z (mm)")
            ax.set_xlim(0, 0.75)
            ax.set_ylim(0, zmax)
            ax.grid(alpha=0.3)
            ax.legend(fontsize=6)
    fig.suptitle("binaryBedKhan: solid 1 mm, dashed 0.3 mm", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_error_vs_runtime(path, runs, plt):
    """Each run's plateau error against Richardson-Zaki (big: filled, small: open) against its wall
    core-seconds (wall time x MPI ranks: runs on 1 and 2 ranks side by side; left) and its coupling
    share (right), as the Mueller validation's error_vs_runtime.png."""
    colour_of = palette_of(plt, sorted({r["method"] for r in runs}))
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
    for r in runs:
        for sp, face in (("big", None), ("small", "none")):
            l = r["layers"][sp]
            err = abs(float(l["alpha_p_plateau"]) - float(l["alpha_p_richardson_zaki"]))
            core = float(r["bed"]["wall_s"]) * int(r["bed"]["ranks"])
            for ax, x in ((axes[0], core), (axes[1], 100 * r["share"])):
                ax.plot([x], [err], "o", ms=7, color=colour_of(r["method"]),
                        mfc=face if face else colour_of(r["method"]),
                        label="%s, %s, U = %s" % (r["method"], sp, r["bed"]["U"]))
    for ax, xlabel in ((axes[0], "core-seconds (wall time x ranks)"), (axes[1], "coupling share of the stages (%)")):
        ax.set_xlabel(xlabel)
        ax.set_ylabel("|plateau alpha_p - Richardson-Zaki|")
        ax.axhline(0.03, color="k", lw=0.8, ls=":")
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
    axes[1].legend(fontsize=6)
    fig.suptitle("binaryBedKhan: error against run time (filled: 1 mm layer, open: 0.3 mm; dotted: issue 19's 0.03)",
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def checks(runs):
    for r in runs:
        b, big, small = r["bed"], r["layers"]["big"], r["layers"]["small"]
        d_big = float(big["alpha_p_plateau"]) - float(big["alpha_p_richardson_zaki"])
        U, d = float(b["U"]), ref.SPECIES["big"][0]
        print("CHECK %-6s %s: big-layer plateau %.4f within 0.03 of Richardson-Zaki %.4f (%+.4f; with the 10 mm "
              "tube's wall correction of u_t the line would be %.4f)" % (
            "MET" if abs(d_big) <= 0.03 else "MISSED", r["name"], float(big["alpha_p_plateau"]),
            float(big["alpha_p_richardson_zaki"]), d_big, ref.alpha_richardson_zaki_wall(U, d)))
        e = float(b["dp_rel_err"])
        print("CHECK %-6s %s: pressure drop %.2f Pa within 3 %% of the buoyant weight %.2f Pa (%+.2f %%)" % (
            "MET" if abs(e) <= 0.03 else "MISSED", r["name"], float(b["dp_pa"]), float(b["dp_weight_pa"]), 100 * e))
        hb, hs = float(big["mean_height_mm"]), float(small["mean_height_mm"])
        print("CHECK %-6s %s: big below small (mean heights %.2f and %.2f mm)" % (
            "MET" if hb < hs else "MISSED", r["name"], hb, hs))


def main(argv):
    if len(argv) < 2:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    out, runs = argv[0], [read_run(r) for r in argv[1:]]
    win, young = one_case(runs)
    os.makedirs(out, exist_ok=True)
    rows = summary_rows(runs)
    with open(os.path.join(out, "summary.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=HEADER.split(","), lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    write_table(os.path.join(out, "table.md"), runs, (win, young))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        plot(os.path.join(out, "alpha_p_profiles.png"), runs, plt)
        plot_error_vs_runtime(os.path.join(out, "error_vs_runtime.png"), runs, plt)
    except ImportError:
        print("compare.py: matplotlib not available, no plots")
    for r in runs:
        for w in r["warnings"]:
            print(w)
    checks(runs)
    print("compare.py: %d runs (window %s s, E = %s Pa), %d rows: %s" % (len(runs), win, young, len(rows), ", ".join(
        os.path.join(out, f) for f in ("summary.csv", "table.md", "alpha_p_profiles.png", "error_vs_runtime.png"))))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
