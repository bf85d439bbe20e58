#!/usr/bin/env python3
"""check.py <case> [--expect N]: the coupling's particle inventory against the DEM's own counts.

Reads the last row of postProcessing/particleInventory/*/particleInventory.dat (the coupling: how many
particles entered through the feed, left through the drain, were lost; the mass balance) and the
last row of post/counts.txt (LIGGGHTS: particles in the DEM, and fix massflow/mesh's count of the
particles that crossed the drain plane and were deleted; their sum is what LIGGGHTS inserted, as
nothing else removes particles), and the particles in the DEM at every write time.
Prints one PASS/FAIL line per check; exit status 1 on a failure.
"""
import glob, os, sys

def last_row(path):
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith("#")]
    return rows[-1] if rows else None

def main():
    case = sys.argv[1] if len(sys.argv) > 1 else "."
    expect = int(sys.argv[sys.argv.index("--expect") + 1]) if "--expect" in sys.argv else 300
    tag = f"feedAndDrain {os.path.basename(os.path.abspath(case))}"
    files = sorted(glob.glob(os.path.join(case, "postProcessing", "particleInventory", "*", "particleInventory.dat")),
                   key=lambda p: float(p.split(os.sep)[-2]))
    if not files:
        print(f"FAIL: {tag}: no particleInventory.dat"); return 1
    head = [l for l in open(files[0]) if l.startswith("# time")][0].split()[1:]
    inv = dict(zip(head, map(float, last_row(files[-1]))))
    dem = last_row(os.path.join(case, "post", "counts.txt"))
    dem_particles, dem_drained = int(float(dem[1])), int(float(dem[2]))
    inserted = dem_particles + dem_drained
    checks = [
        (int(inv["in_feed"]) == inserted == expect,
         f"entered through the feed {int(inv['in_feed'])}, LIGGGHTS inserted {inserted} (in it + drained; expected {expect})"),
        (int(inv["in_elsewhere"]) == 0, f"entered elsewhere {int(inv['in_elsewhere'])}"),
        (int(inv["out_drain"]) == dem_drained, f"left through the drain {int(inv['out_drain'])}, "
                                               f"fix massflow/mesh counted {dem_drained}"),
        (int(inv["lost"]) == 0, f"lost {int(inv['lost'])}"),
        (int(inv["particles"]) == dem_particles == int(inv["in_feed"]) - int(inv["out_drain"]),
         f"particles now {int(inv['particles'])}, in the DEM {dem_particles}, entered - left "
         f"{int(inv['in_feed']) - int(inv['out_drain'])}"),
        (abs(inv["mass_balance_rel_err"]) <= 1e-12, f"mass balance rel. err {inv['mass_balance_rel_err']:.2e}"),
    ]
    # at every write time: the coupling's count is the DEM's (post/counts.txt, every 0.01 s)
    dem_at = {round(float(r.split()[0]), 6): int(float(r.split()[1]))
              for r in open(os.path.join(case, "post", "counts.txt")) if r.strip() and not r.startswith("#")}
    rows = [dict(zip(head, map(float, l.split()))) for f in files for l in open(f) if l.strip() and not l.startswith("#")]
    differ = [(r["time"], int(r["particles"]), dem_at.get(round(r["time"], 6))) for r in rows
              if dem_at.get(round(r["time"], 6)) != int(r["particles"])]
    checks.append((len(rows) > 0 and not differ,
                   f"particles at each of {len(rows)} write times as in the DEM" + (f": differ at {differ[:3]}" if differ else "")))
    status = 0
    for ok, what in checks:
        print(("PASS" if ok else "FAIL") + f": {tag}: {what}")
        status |= not ok
    return status

if __name__ == "__main__":
    sys.exit(main())
