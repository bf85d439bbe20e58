#!/usr/bin/python3
"""Writes the DEM's surfaces of the particleJet tutorial as ASCII STL files (metres, x axial):

  pipe.stl            the pipe wall, radius 7.43 mm (inside the CFD mesh's faceted 7.5 mm wall),
                      x = -150 ... 0 mm (64 facets around, 10 along)
  inlet.stl           the insertion face, a disk of radius 0.9 R = 6.75 mm at x = -148 mm (the grains are made in the 2 mm behind it)
  station_<tag>.stl   counting planes: squares of side 6 D = 90 mm at the stations of Weaver &
                      Miskovic (2023) and Hardalupas et al. (1989): x/D = -5, 0.1, 5, 10, 19
  exit.stl            the plane x = 19.5 D where the particles are counted and deleted
Run once; the files are part of the tutorial (python3 DEM/surfaces.py from the tutorial)."""
import math
import os

D = 0.015
R = D / 2
HALF = 3 * D                      # the DEM box's half width
STATIONS = {"m5D": -5 * D, "0.1D": 0.1 * D, "5D": 5 * D, "10D": 10 * D, "19D": 19 * D}
EXIT_X = 19.5 * D
here = os.path.dirname(os.path.abspath(__file__))


def write(name, tris):
    with open(os.path.join(here, name), "w") as f:
        f.write("solid %s\n" % name[:-4])
        for a, b, c in tris:
            u = [b[i] - a[i] for i in range(3)]
            v = [c[i] - a[i] for i in range(3)]
            n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
            ln = math.sqrt(sum(x * x for x in n)) or 1.0
            f.write("  facet normal %.9g %.9g %.9g\n    outer loop\n" % tuple(x / ln for x in n))
            for p in (a, b, c):
                f.write("      vertex %.9g %.9g %.9g\n" % p)
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid %s\n" % name[:-4])


def ring(r, x, n):
    return [(x, r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n)) for k in range(n)]


def disk(r, x, n=32):
    pts = ring(r, x, n)
    return [((x, 0.0, 0.0), pts[k], pts[(k + 1) % n]) for k in range(n)]


def square(x, h):
    p = [(x, -h, -h), (x, h, -h), (x, h, h), (x, -h, h)]
    return [(p[0], p[1], p[2]), (p[0], p[2], p[3])]


def cylinder(r, x0, x1, n=64, m=10):
    tris = []
    for j in range(m):
        a = ring(r, x0 + (x1 - x0) * j / m, n)
        b = ring(r, x0 + (x1 - x0) * (j + 1) / m, n)
        for k in range(n):
            k1 = (k + 1) % n
            tris += [(a[k], a[k1], b[k1]), (a[k], b[k1], b[k])]
    return tris


# the wall the grains see lies on the CFD mesh's faceted pipe wall (24 flat faces around: their
# mid-points at R cos(pi/24) = 7.436 mm), so that a grain touching it has its centre in the mesh
write("pipe.stl", cylinder(R * math.cos(math.pi / 24) - 5e-6, -10 * D, 0.0))
write("inlet.stl", disk(0.9 * R, -10 * D + 0.002))
for tag, x in STATIONS.items():
    write("station_%s.stl" % tag, square(x, HALF))
write("exit.stl", square(EXIT_X, HALF))
