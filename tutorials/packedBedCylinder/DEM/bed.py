#!/usr/bin/python3
"""bed.py: the particle positions of the packedBedCylinder bed, written as LIGGGHTS commands
(DEM/bed.include). Spheres of d = 2 mm on concentric rings of radius (j + 1/2) 2.2 mm, j = 0..4,
each ring with round(2 pi r / 2.2 mm) particles evenly spaced, rings turned by half a spacing from
layer to layer; 30 layers 2.2 mm apart from z = 12.1 mm. Every ring stands for an annulus 2.2 mm
wide, so the solid fraction is the same from the axis to the 11 mm wall (the outer ring's spheres
reach 10.9 mm): a bed without the wall channel of a square lattice cut by a circle, so that Ergun
at the bed's mean voidage is the reference everywhere across the column.
Usage: bed.py > DEM/bed.include
"""
import math
spacing, layers, z0 = 2.2e-3, 30, 12.1e-3
n = 0
for k in range(layers):
    z = z0 + k * spacing
    for j in range(5):
        r = (j + 0.5) * spacing
        m = round(2 * math.pi * r / spacing)
        for i in range(m):
            phi = 2 * math.pi * (i + 0.5 * (k % 2)) / m
            print(f"create_atoms 1 single {r * math.cos(phi):.9f} {r * math.sin(phi):.9f} {z:.9f} units box")
            n += 1
print(f"# {n} particles")
