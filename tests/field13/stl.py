"""Field round 13: stand-in ASCII STL meshes for the LIGGGHTS decks (no import from the project).
usage: python stl.py plane Z HALF OUT.stl      a square at height Z, |x|,|y| <= HALF, normal +z
       python stl.py cylinder R Z0 Z1 N OUT.stl   the side of a z-cylinder of radius R, N facets round
       python stl.py xcylinder R YC ZC X0 X1 N OUT.stl   the side of an x-cylinder about (YC, ZC)
"""
import math, sys

def facet(out, a, b, c):
    ux, uy, uz = (b[i] - a[i] for i in range(3))
    vx, vy, vz = (c[i] - a[i] for i in range(3))
    n = (uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx)
    l = math.sqrt(sum(t * t for t in n)) or 1.0
    out.append("facet normal %g %g %g\n outer loop\n" % tuple(t / l for t in n))
    for p in (a, b, c):
        out.append("  vertex %.9g %.9g %.9g\n" % p)
    out.append(" endloop\nendfacet\n")

kind = sys.argv[1]
out = ["solid s\n"]
if kind == "plane":
    z, h, fn = float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
    facet(out, (-h, -h, z), (h, -h, z), (h, h, z))
    facet(out, (-h, -h, z), (h, h, z), (-h, h, z))
elif kind == "xcylinder":
    r, yc, zc, x0, x1, n, fn = (float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5]),
                                float(sys.argv[6]), int(sys.argv[7]), sys.argv[8])
    for k in range(n):
        a0, a1 = 2 * math.pi * k / n, 2 * math.pi * (k + 1) / n
        p0 = (yc + r * math.cos(a0), zc + r * math.sin(a0)); p1 = (yc + r * math.cos(a1), zc + r * math.sin(a1))
        facet(out, (x0, p0[0], p0[1]), (x0, p1[0], p1[1]), (x1, p1[0], p1[1]))
        facet(out, (x0, p0[0], p0[1]), (x1, p1[0], p1[1]), (x1, p0[0], p0[1]))
else:
    r, z0, z1, n, fn = float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5]), sys.argv[6]
    for k in range(n):
        a0, a1 = 2 * math.pi * k / n, 2 * math.pi * (k + 1) / n
        p0 = (r * math.cos(a0), r * math.sin(a0)); p1 = (r * math.cos(a1), r * math.sin(a1))
        facet(out, (p0[0], p0[1], z0), (p1[0], p1[1], z0), (p1[0], p1[1], z1))
        facet(out, (p0[0], p0[1], z0), (p1[0], p1[1], z1), (p0[0], p0[1], z1))
out.append("endsolid s\n")
open(fn, "w").write("".join(out))
