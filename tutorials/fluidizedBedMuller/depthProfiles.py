#!/usr/bin/python3
"""depthProfiles.py: the `depthProfiles` function object of the Mueller bed for a mesh of
nx x ny x nz cells (Allrun writes it to system/depthProfiles, which system/controlDict includes).

    depthProfiles.py <nx> <ny> > system/depthProfiles

At each height of the MR data (z = 15, 16.4, 20, 25, 31.2 and 35 mm, those of the `profiles`
sets), one line across the width through every column of cells across the 10 mm thickness
(x = (i + 1/2) 10 mm / nx), sampled at the cell centres across the 44 mm width with the cells'
own values (interpolationScheme cell): validation/muller/profiles.py averages them over the
depth, as the MR measurement does.
"""
import sys

nx, ny = int(sys.argv[1]), int(sys.argv[2])
depth, width = 0.010, 0.044
heights = ["15", "16.4", "20", "25", "31.2", "35"]
print("// written by depthProfiles.py %d %d (Allrun): do not edit" % (nx, ny))
print("depthProfiles")
print("{")
print("    type            sets;")
print('    libs            ("libsampling.so");')
print("    writeControl    adjustableRunTime;")
print("    writeInterval   0.01;")
print("    timeStart       0;")
print("    setFormat       csv;")
print("    interpolationScheme cell;")
print("    fields          ( alpha alphaPBinned alphaPUsBinned );")
print("    sets")
print("    (")
for h in heights:
    z = float(h) / 1000
    for i in range(nx):
        x = (i + 0.5) * depth / nx
        y0, y1 = 0.5 * width / ny, (ny - 0.5) * width / ny
        print(f"        z{h}d{i} {{ type uniform; axis y; start ({x:.9g} {y0:.9g} {z:.9g}); "
              f"end ({x:.9g} {y1:.9g} {z:.9g}); nPoints {ny}; }}")
print("    );")
print("}")
