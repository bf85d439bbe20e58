"""muller_plots.py -- the Mueller validation's profile figures (validation/muller/summary.py): each
case's last run against the MR data, at one height per data file or at every sampled height."""
import collections
import glob
import os
import re

from muller_compare import read_profile

# the MR data (validation/muller/data)
DATA_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "validation", "muller", "data")

# an instrument: the errors.csv quantities of the gas fraction and the particle v_z, the profile
# file stems of the MR data's quantities (voidfraction, vz), and its words in tables and figures
Instrument = collections.namedtuple("Instrument", "void_error vz_error stems words")
INSTRUMENTS = {
    "depthBinned": Instrument("void_fraction_depth_binned", "vz_particle_depth_binned_m_per_s",
                              {"voidfraction": "voidfractiondepthbinned", "vz": "vzdepthbinned"},
                              "depth-averaged, binned"),
    "midThickness": Instrument("void_fraction", "vz_particle_m_per_s",
                               {"voidfraction": "voidfraction", "vz": "vz"}, "mid-thickness"),
}
# per headline instrument: (the headline's, the other's) for the error columns
ERROR_INSTRUMENTS = {k: (INSTRUMENTS[k], INSTRUMENTS["midThickness" if k == "depthBinned" else "depthBinned"])
                     for k in INSTRUMENTS}
HEIGHTS_MM = ("15", "16.4", "20", "25", "31.2", "35")


def inlet_of(name):
    """The inlet velocity (m/s, as written) in a run's name (..._U0.9_...), or None."""
    m = re.search(r"_U([0-9.]+)_", name)
    return m.group(1) if m else None


def draw_profile(ax, path, label, **style):
    """A run's time-averaged profile (x in mm) with +-2 batch SEM as a band where the SEMs exist;
    False when the file is missing or empty."""
    if not os.path.exists(path):
        return False
    _, sx, sy, se = read_profile(path)
    if not sx:
        return False
    xs = [x * 1e3 for x in sx]
    line, = ax.plot(xs, sy, "-", label=label, **style)
    if all(e == e for e in se):
        ax.fill_between(xs, [y - 2 * e for y, e in zip(sy, se)], [y + 2 * e for y, e in zip(sy, se)],
                        color=line.get_color(), alpha=0.12, lw=0)
    return True


def plot_profiles(out, rows, plt, instrument, data_dir=DATA_DIR):
    """One panel per MR data file at an inlet velocity of the runs: each case's last run (a case:
    model, dx/d, U and mode, the run directory's name) against the data, its profile as copied to
    <out>, +-2 batch SEM as a band. Returns the number of panels."""
    latest = {r["name"]: r for r in rows}
    def inlet(name):
        u = inlet_of(name)
        return float(u) if u else None
    files = []
    for path in sorted(glob.glob(os.path.join(data_dir, "mueller_U*_*_z*mm_MR.csv"))):
        m = re.match(r"mueller_U([0-9.]+)_(\w+?)_z([0-9.]+)mm_MR\.csv", os.path.basename(path))
        if m and any(inlet(n) == float(m.group(1)) for n in latest):
            files.append((path, float(m.group(1)), m.group(2), m.group(3)))
    if not files:
        return 0
    fig, axes = plt.subplots(1, len(files), figsize=(5.5 * len(files), 4.2), squeeze=False)
    for ax, (path, U, q, h) in zip(axes[0], files):
        for name, r in latest.items():
            if inlet(name) != U:
                continue
            label = name.replace(f"_U{inlet_of(name)}", "")
            draw_profile(ax, os.path.join(out, r["run"], f"profile_{INSTRUMENTS[instrument].stems[q]}_z{h}mm.csv"),
                         f"{label} ({r['commit']})")
        _, dx, dy, _ = read_profile(path)
        ax.plot([x * 1e3 for x in dx], dy, "ko", ms=4, label="Müller et al. (MR)")
        ax.set_xlabel("distance from the left wall (mm)")
        ax.set_ylabel({"voidfraction": "time-averaged gas fraction",
                       "vz": "time-averaged particle v_z (m/s)"}.get(q, q))
        ax.set_title(f"U = {U:g} m/s, z = {h} mm")
        ax.legend(fontsize=7)
    fig.suptitle(f"Mueller bed: each case's last run against the MR data ({INSTRUMENTS[instrument].words}; bands: +-2 batch SEM)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "profiles_all_models.png"), dpi=110)
    plt.close(fig)
    return len(files)


def case_labels(names):
    """{run directory name: legend label}: the model and the parts of the name (mesh, inlet, mode,
    background) that differ between the cases drawn, e.g. "diffusion medium" and "diffusion full"."""
    parts = {n: n.split("_") for n in names}
    common = set.intersection(*(set(p[1:]) for p in parts.values())) if parts else set()
    return {n: " ".join([p[0]] + [x for x in p[1:] if x not in common]) for n, p in parts.items()}


def plot_all_heights(out, rows, plt, instrument, data_dir=DATA_DIR):
    """Two rows (gas fraction, particle v_z) by six heights: each case's last run, its profile with
    +-2 batch SEM, and the MR data where they exist at the runs' inlet velocity."""
    latest = {r["name"]: r for r in rows}
    labels = case_labels(latest)
    fig, axes = plt.subplots(2, len(HEIGHTS_MM), figsize=(3.2 * len(HEIGHTS_MM), 6.5), sharey="row")
    for i, q in enumerate(("voidfraction", "vz")):
        for ax, h in zip(axes[i], HEIGHTS_MM):
            inlets = set()
            for name, r in latest.items():
                sim = os.path.join(out, r["run"], f"profile_{INSTRUMENTS[instrument].stems[q]}_z{h}mm.csv")
                if draw_profile(ax, sim, labels[name], lw=1):
                    inlets.add(inlet_of(name))
            for U in sorted(u for u in inlets if u):
                data = os.path.join(data_dir, f"mueller_U{U}_{q}_z{h}mm_MR.csv")
                if os.path.exists(data):
                    _, dx, dy, _ = read_profile(data)
                    ax.plot([x * 1e3 for x in dx], dy, "ko", ms=3, label=f"MR, U = {U} m/s")
            ax.set_title(f"z = {h} mm", fontsize=9)
            ax.set_xlabel("x (mm)", fontsize=8)
        axes[i][0].set_ylabel("gas fraction" if q == "voidfraction" else "particle v_z (m/s)")
    axes[0][0].legend(fontsize=6)
    fig.suptitle(f"Mueller bed, every sampled height ({INSTRUMENTS[instrument].words}; bands: +-2 batch SEM)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "profiles_all_heights.png"), dpi=100)
    plt.close(fig)
