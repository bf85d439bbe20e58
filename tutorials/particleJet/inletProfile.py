#!/usr/bin/python3
"""Writes the inlet's 1/n power-law velocity profile into <case>/0/U (Weaver & Miskovic 2023,
Table 3): u = u_max (1 - r/R)^(1/n), u_max = U_mean (n + 1)(2n + 1) / (2 n^2), n = 7 (assumed).
The face centres and areas come from the mesh (constant/polyMesh, ascii). The values are then
scaled so that the inflow is U_mean times the inlet's area exactly on this mesh (the power law's
mean over the discrete faces misses it by a few per cent)."""
import re
import sys

case = sys.argv[1] if len(sys.argv) > 1 else "."
U_MEAN, R, N = 13.0, 0.0075, 7


def foam_list(path):
    """The body of the first top-level list of an ascii polyMesh file, as text."""
    text = open(path).read()
    m = re.search(r"\n(\d+)\s*\n\(", text)
    if not m:
        sys.exit("inletProfile.py: %s is not an ascii list (writeFormat ascii for blockMesh)" % path)
    return int(m.group(1)), text[m.end():]


n, body = foam_list(case + "/constant/polyMesh/points")
points = [tuple(map(float, p.split())) for p in re.findall(r"\(([^()]*)\)", body)[:n]]
n, body = foam_list(case + "/constant/polyMesh/faces")
boundary = open(case + "/constant/polyMesh/boundary").read()
m = re.search(r"\binlet\s*\{[^}]*?nFaces\s+(\d+);[^}]*?startFace\s+(\d+);", boundary, re.S)
if not m:
    sys.exit("inletProfile.py: no patch 'inlet' in %s/constant/polyMesh/boundary" % case)
nFaces, start = int(m.group(1)), int(m.group(2))
faces = [list(map(int, f.split())) for f in re.findall(r"\d+\(([^()]*)\)", body)[start:start + nFaces]]

centres, areas = [], []
for f in faces:
    p = [points[i] for i in f]
    centres.append(tuple(sum(q[k] for q in p) / len(p) for k in range(3)))
    a = [0.0, 0.0, 0.0]       # the area vector: half the sum of the edge cross products
    for i in range(len(p)):
        u, v = p[i], p[(i + 1) % len(p)]
        a[0] += u[1] * v[2] - u[2] * v[1]
        a[1] += u[2] * v[0] - u[0] * v[2]
        a[2] += u[0] * v[1] - u[1] * v[0]
    areas.append(0.5 * sum(x * x for x in a) ** 0.5)

umax = U_MEAN * (N + 1) * (2 * N + 1) / (2.0 * N * N)
u = [umax * max(0.0, 1.0 - (y * y + z * z) ** 0.5 / R) ** (1.0 / N) for (_, y, z) in centres]
scale = U_MEAN * sum(areas) / sum(a * b for a, b in zip(u, areas))
u = [x * scale for x in u]
field = open(case + "/0/U").read()
vals = "\n".join("(%.6g 0 0)" % x for x in u)
new = re.sub(r"(inlet\s*\{\s*type\s+fixedValue;\s*value\s+)uniform\s*\([^)]*\)\s*;",
             lambda mm: mm.group(1) + "nonuniform List<vector> %d\n(\n%s\n);" % (len(u), vals), field, count=1)
if new == field:
    sys.exit("inletProfile.py: no 'inlet { type fixedValue; value uniform (...); }' in %s/0/U" % case)
open(case + "/0/U", "w").write(new)
print("inletProfile.py: %d inlet faces (%.4g m2), u_max %.3f m/s, power law scaled by %.4f to a mean of %.2f m/s"
      % (len(u), sum(areas), max(u), scale, U_MEAN))
