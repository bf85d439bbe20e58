#!/usr/bin/python3
"""summary.py -- results/summary.csv, results/details.csv, the per-run time series and the plot of
liquidFluidizedBed from the runs of Allrun -all.

    summary.py TUTORIAL_DIR MODE [MODE ...]   several modes: each row from the first mode whose run
                                             exists (Allrun -summary: long, then full), written without
                                             a mode suffix; its window in the column window_s
    summary.py TUTORIAL_DIR -ingredients [-output NAME] RUN...  results/NAME.csv and .md (default
                                             ingredients): one row per named run (runs/RUN: an ingredient
                                             study, one input changed at a time; the small species' study
                                             is -output smallSpecies)
    summary.py TUTORIAL_DIR MODE -dragLaws   results/dragLaws.csv and dragLaws.md: bigParticle with
                                             each drag law (Allrun -dragLaws, and the matrix's Di Felice
                                             runs) against that law's own equilibrium voidage

Rows in the order method (centre divided bigParticle diffusion diffusionSources), modelType (A B), U (0.015 0.020
0.025); a missing run is reported and left out. Prints the checks against the targets (voidage
within 0.02 of the drag-law equilibrium, pressure drop within 2 % of the bed's weight, Model A and
B bed heights H_c within 2 %) as MET / MISSED lines (not PASS/FAIL: the matrix is not a test).
"""
import csv, os, shutil, sys

# the project's Python library, etc/python (COARSEDEM_DIR: this file may run from a copy of the tutorial)
sys.path.insert(0, os.path.join(os.environ.get("COARSEDEM_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."), "etc", "python"))
import liquid_bed_references as ref  # noqa: E402
from liquid_bed_references import PERSIST_FROZEN  # noqa: E402

METHODS = ("centre", "divided", "bigParticle", "diffusion", "diffusionSources")
MODELS = ("A", "B")
US = ("0.015", "0.020", "0.025")


def read_row(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return rows[0], list(rows[0].keys())


def eps_error(r):
    """eps_sim minus its drag-law equilibrium, for the tables and the targets."""
    return float(r["eps_sim"]) - float(r["eps_drag_equilibrium"])


def targets_met(r):
    """The issue's targets for one row: voidage within 0.01 of the drag-law equilibrium; the pressure drop
    and the walls' share together within 1 % of the buoyant weight, the walls under 2 %; the plateau
    within 0.01 of the bed-height voidage; particles that move (under half the contacts last 0.1 s).
    Rows without the wall and motion columns (the drag-law table): voidage 0.02, dp 2 %."""
    if "wall_force_share" not in r or r["wall_force_share"] == "":
        return "MET" if abs(eps_error(r)) <= 0.02 and abs(float(r["dp_rel_err"])) <= 0.02 else "MISSED"
    misses = []
    if abs(eps_error(r)) > 0.01:
        misses.append("voidage")
    if abs(float(r["dp_plus_walls_rel_err"])) > 0.01:
        misses.append("dp + walls")
    if float(r["wall_force_share"]) >= 0.02:
        misses.append("walls")
    if abs(float(r["eps_plateau"]) - float(r["eps_sim"])) > 0.01:
        misses.append("plateau")
    if not float(r["contact_persist_0.1s"]) < PERSIST_FROZEN:
        misses.append("frozen")
    return "MET" if not misses else "MISSED (%s)" % ", ".join(misses)


def window_s(d):
    """The averaging window of a run, from its details.csv row."""
    return "%g" % (float(d["tend"]) - float(d["tstart"]))


def mode_suffix(mode):
    return "" if mode == "full" else "_" + mode


def drag_laws(here, mode):
    """The drag-law table: the same MET/MISSED targets as the matrix, per law."""
    res = os.path.join(here, "results")
    suffix = mode_suffix(mode)
    out, header = [], None
    for law in ref.DRAG_LAWS:
        for mt in MODELS:
            for u in US:
                name = "bigParticle_%s_U%s_%s%s" % (mt, u, mode, "" if law == "DiFelice" else "_" + law)
                path = os.path.join(here, "runs", name, "results", "result.csv")
                if not os.path.isfile(path):
                    print("summary.py: run %s missing" % name)
                    continue
                r, header = read_row(path)
                r["drag"] = law
                out.append(r)
    if not out:
        print("summary.py: no drag-law runs of mode %s" % mode)
        return 1
    fields = ["drag"] + header
    with open(os.path.join(res, "dragLaws%s.csv" % suffix), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, lineterminator="\n")
        w.writeheader()
        w.writerows(out)
    with open(os.path.join(res, "dragLaws%s.md" % suffix), "w") as f:
        f.write("| drag law | model | U (m/s) | eps_sim ± sem | its drag eq. | eps - eq. | R-Z | dp_rel_err | wall (s) |\n")
        f.write("|" + "---|" * 9 + "\n")
        for r in out:
            f.write("| %s | %s | %s | %s ± %s | %s | %+.3f | %s | %+.1f %% | %.0f |\n" % (
                r["drag"], r["modelType"], r["U"], r["eps_sim"], r["eps_sem"], r["eps_drag_equilibrium"], eps_error(r),
                r["eps_richardson_zaki"], 100 * float(r["dp_rel_err"]), float(r["wall_s"])))
    for r in out:
        print("%-6s %s %s U %s: eps %s (its drag eq. %s, %+.4f; R-Z %s), dp %+.2f %%" % (
            targets_met(r), r["drag"], r["modelType"], r["U"], r["eps_sim"], r["eps_drag_equilibrium"],
            eps_error(r), r["eps_richardson_zaki"], 100 * float(r["dp_rel_err"])))
    return 0


# where the weight goes and how the particles move, from details.csv into summary.csv
SUMMARY_EXTRA = ("wall_force_share", "dp_plus_walls_rel_err", "eps_plateau", "v_rms_mm_s", "v_fluct_rms_mm_s",
                 "contact_persist_0.1s")


def ingredients(here, names, output="ingredients"):
    """One row per run of an ingredient study: what differs from the baseline is in the run's name."""
    res = os.path.join(here, "results")
    cols = ("run", "commit", "method", "modelType", "U", "window_s", "eps_sim", "eps_minus_equilibrium",
            "eps_plateau_minus_eps_sim", "wall_force_share", "dp_rel_err", "dp_plus_walls_rel_err",
            "fluid_share_bottom", "v_fluct_rms_mm_s", "coordination", "contact_persist_0.1s", "wall_s",
            "eps_drag_equilibrium", "flux_seen", "column_flux_min", "column_flux_max", "count_ratio_2p5mm")
    out = []
    for name in names:
        run = os.path.join(here, "runs", name)
        if not os.path.isfile(os.path.join(run, "results", "details.csv")):
            print("summary.py: run %s missing" % name)
            continue
        r, _ = read_row(os.path.join(run, "results", "result.csv"))
        d, _ = read_row(os.path.join(run, "results", "details.csv"))
        with open(os.path.join(run, "commit.txt")) as f:
            commit = f.read().split()[0]
        out.append({"run": name, "commit": commit, "method": r["method"], "modelType": r["modelType"], "U": r["U"],
                    "window_s": window_s(d), "eps_sim": r["eps_sim"],
                    "eps_minus_equilibrium": "%+.4f" % eps_error(r),
                    "eps_plateau_minus_eps_sim": "%+.4f" % (float(d["eps_plateau"]) - float(r["eps_sim"])),
                    "wall_force_share": d["wall_force_share"], "dp_rel_err": r["dp_rel_err"],
                    "dp_plus_walls_rel_err": d["dp_plus_walls_rel_err"], "fluid_share_bottom": d["fluid_share_bottom"],
                    "v_fluct_rms_mm_s": d["v_fluct_rms_mm_s"], "coordination": d["coordination"],
                    "contact_persist_0.1s": d["contact_persist_0.1s"], "wall_s": r["wall_s"],
                    "eps_drag_equilibrium": r["eps_drag_equilibrium"],
                    # the lateral flow (runs made before it was measured: blank)
                    "flux_seen": d.get("flux_seen", ""), "column_flux_min": d.get("column_flux_min", ""),
                    "column_flux_max": d.get("column_flux_max", ""), "count_ratio_2p5mm": d.get("count_ratio_2p5mm", "")})
    if not out:
        return 1
    with open(os.path.join(res, output + ".csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=cols, lineterminator="\n")
        w.writeheader()
        w.writerows(out)
    with open(os.path.join(res, output + ".md"), "w") as f:
        f.write("| run | eps - eq. | plateau - eps | walls carry | dp + walls | fluid, bottom layer | v_fluct (mm/s) "
                "| coordination | contacts kept 0.1 s | flux where the particles are | count variance / mean (2.5 mm) |\n|" + "---|" * 11 + "\n")
        for o in out:
            f.write("| %s | %s | %s | %.2f %% | %+.2f %% | %s | %s | %s | %s | %s | %s |\n" % (
                o["run"], o["eps_minus_equilibrium"], o["eps_plateau_minus_eps_sim"], 100 * float(o["wall_force_share"]),
                100 * float(o["dp_plus_walls_rel_err"]), o["fluid_share_bottom"], o["v_fluct_rms_mm_s"],
                o["coordination"], o["contact_persist_0.1s"], o["flux_seen"] or "-", o["count_ratio_2p5mm"] or "-"))
    return 0


def main():
    here = sys.argv[1]
    if sys.argv[2:3] == ["-ingredients"]:
        if sys.argv[3:4] == ["-output"]:
            if len(sys.argv) < 5:
                sys.exit("summary.py: -output needs a name")
            return ingredients(here, sys.argv[5:], sys.argv[4])
        return ingredients(here, sys.argv[3:])
    if sys.argv[3:] == ["-dragLaws"]:
        return drag_laws(here, sys.argv[2])
    modes = sys.argv[2:]
    mode = modes[0]
    res = os.path.join(here, "results")
    os.makedirs(os.path.join(res, "runs"), exist_ok=True)
    rows, details, missing = [], [], []
    header = dheader = None
    for m in METHODS:
        for mt in MODELS:
            for u in US:
                names = ["%s_%s_U%s_%s" % (m, mt, u, md) for md in modes]
                found = [n for n in names if os.path.isfile(os.path.join(here, "runs", n, "results", "result.csv"))]
                if not found:
                    missing.append(" or ".join(names))
                    continue
                name = found[0]
                run = os.path.join(here, "runs", name, "results")
                r, header = read_row(os.path.join(run, "result.csv"))
                d, dh = read_row(os.path.join(run, "details.csv"))
                # runs of later commits may hold more detail columns: the union, in the order first seen
                dheader = (dheader or []) + [k for k in dh if k not in (dheader or [])]
                for k in SUMMARY_EXTRA:
                    r[k] = d.get(k, "")
                r["window_s"] = window_s(d)
                rows.append(r)
                details.append(d)
                shutil.copy(os.path.join(run, "bedHeight.csv"), os.path.join(res, "runs", name + "_bedHeight.csv"))
                shutil.copy(os.path.join(run, "profile.csv"), os.path.join(res, "runs", name + "_profile.csv"))
                if os.path.isfile(os.path.join(run, "forceProfile.csv")):
                    shutil.copy(os.path.join(run, "forceProfile.csv"),
                                os.path.join(res, "runs", name + "_forceProfile.csv"))
    if not rows:
        print("summary.py: no runs of mode %s" % " or ".join(modes))
        return 1
    header = header + list(SUMMARY_EXTRA) + ["window_s"]
    suffix = "" if len(modes) > 1 else mode_suffix(mode)
    for fname, hdr, rr in (("summary%s.csv" % suffix, header, rows), ("details%s.csv" % suffix, dheader, details)):
        with open(os.path.join(res, fname), "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=hdr, restval="", lineterminator="\n")
            w.writeheader()
            w.writerows(rr)
    for name in missing:
        print("summary.py: run %s missing" % name)

    # a markdown table for the README: the summary row and the details that explain it
    dk = {(d["method"], d["modelType"], d["U"]): d for d in details}
    with open(os.path.join(res, "table%s.md" % suffix), "w") as f:
        f.write("| method | model | U (m/s) | window (s) | eps_sim ± sem | drag eq. | eps - eq. | eps_plateau | H_c (mm) "
                "| dp_sim (Pa) ± sem | dp_rel_err | walls carry | dp + walls | fluid carries, bottom layer | v_fluct (mm/s) "
                "| contacts kept 0.1 s | max overlap (% d) | wall (s) |\n")
        f.write("|" + "---|" * 18 + "\n")
        for r in rows:
            d = dk[(r["method"], r["modelType"], r["U"])]
            f.write("| %s | %s | %s | %s | %s ± %s | %s | %+.3f | %s | %.2f | %.2f ± %.2f | %+.1f %% | %.2f %% | %+.1f %% | %.3f "
                    "| %.1f | %.2f | %.2f | %.0f |\n" % (
                r["method"], r["modelType"], r["U"], r["window_s"], r["eps_sim"], r["eps_sem"], r["eps_drag_equilibrium"],
                eps_error(r), d["eps_plateau"], float(d["H_c_mm"]), float(r["dp_sim"]), float(d["dp_sem"]),
                100 * float(r["dp_rel_err"]), 100 * float(d["wall_force_share"]), 100 * float(d["dp_plus_walls_rel_err"]),
                float(d["fluid_share_bottom"]), float(d["v_fluct_rms_mm_s"]), float(d["contact_persist_0.1s"]),
                float(d["max_overlap_pct_d"]), float(r["wall_s"])))

    # targets
    hc = {(d["method"], d["modelType"], d["U"]): float(d["H_c_mm"]) for d in details}
    for r in rows:
        print("%s %s %s U %s: eps %s (drag eq. %s, %+.4f; plateau %s), dp %s Pa (%+.2f %%), walls %.2f %%, "
              "dp + walls %+.2f %%, contacts kept 0.1 s %s" % (
            targets_met(r), r["method"], r["modelType"], r["U"], r["eps_sim"], r["eps_drag_equilibrium"],
            eps_error(r), r["eps_plateau"], r["dp_sim"], 100 * float(r["dp_rel_err"]),
            100 * float(r["wall_force_share"]), 100 * float(r["dp_plus_walls_rel_err"]), r["contact_persist_0.1s"]))
    for m in METHODS:
        for u in US:
            k = "%.3f" % float(u)
            a, b = hc.get((m, "A", k)), hc.get((m, "B", k))
            if a and b:
                rel = (b - a) / a
                print("%-6s %s U %s: H_c Model A %.2f mm, Model B %.2f mm (%+.2f %%)" % (
                    "MET" if abs(rel) <= 0.02 else "MISSED", m, k, a, b, 100 * rel))

    # eps against U per method, both models, with the two reference lines
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("summary.py: matplotlib not available, no plot")
        return 0
    uu = [0.013 + 0.0005 * i for i in range(27)]
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    ax.plot(uu, [ref.eps_drag_equilibrium(u) for u in uu], "k-", label="Di Felice drag equilibrium")
    ax.plot(uu, [ref.eps_richardson_zaki(u) for u in uu], "k--", label="Richardson-Zaki (Garside-Al-Dibouni n)")
    marks = {"centre": "o", "divided": "s", "bigParticle": "^", "diffusion": "D", "diffusionSources": "v"}
    for i, m in enumerate(METHODS):
        for mt, off, fill in (("A", -0.00045, "full"), ("B", 0.00045, "none")):
            pts = [(float(r["U"]) + off + 0.0002 * (i - 2), float(r["eps_sim"]), float(r["eps_sem"]))
                   for r in rows if r["method"] == m and r["modelType"] == mt]
            if pts:
                ax.errorbar([p[0] for p in pts], [p[1] for p in pts], yerr=[p[2] for p in pts],
                            marker=marks[m], ls="none", color="C%d" % i, fillstyle=fill,
                            label="%s, Model %s" % (m, mt))
    ax.set_xlabel("superficial velocity U (m/s)")
    ax.set_ylabel("bed voidage (central part of the bed)")
    ax.set_title("liquidFluidizedBed: 1146 x 1 mm, 2000 kg/m3 in water")
    ax.legend(fontsize=7, ncol=2)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(res, "eps_vs_U%s.png" % suffix), dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main())
