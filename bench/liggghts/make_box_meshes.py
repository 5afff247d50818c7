#!/usr/bin/python3
"""Writes the STL meshes of grainlab's split shear box (lab/shear_box.h) for
the LIGGGHTS deck beads_direct_shear.in: each side slab of the lower and upper
halves as a closed box (12 triangles, outward normals), and the cap as a
square plate larger than the box.

  make_box_meshes.py OUT_DIR L W H GAP TOP      (metres)

L, W: inner length (x, shear) and width; H: specimen height (the halves meet
at H/2); GAP: opening between the halves at the shear; TOP: top of the upper
half's slabs. Slabs are 2.5 mm thick (kShearBoxSlab). The upper half is built
with its gap closed (resting on the lower half) and raised by GAP before the
shear, as grainlab does; the deck moves it.
"""
import os
import sys

T = 2.5e-3  # slab thickness, m


def box_triangles(x0, x1, y0, y1, z0, z1):
    c = [(x, y, z) for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]
    # corner index = 4*ix + 2*iy + iz; faces as quads with outward winding
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    tris = []
    for a, b, cc, d in quads:
        tris += [(c[a], c[b], c[cc]), (c[a], c[cc], c[d])]
    return tris


def write_stl(path, tris):
    with open(path, "w") as f:
        f.write("solid grainlab\n")
        for t in tris:
            (ax, ay, az), (bx, by, bz), (cx, cy, cz) = t
            ux, uy, uz = bx - ax, by - ay, bz - az
            vx, vy, vz = cx - ax, cy - ay, cz - az
            n = (uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx)
            f.write(" facet normal %.9g %.9g %.9g\n  outer loop\n" % n)
            for p in t:
                f.write("   vertex %.9g %.9g %.9g\n" % p)
            f.write("  endloop\n endfacet\n")
        f.write("endsolid grainlab\n")


def slabs(L, W, z0, z1):
    return (box_triangles(-T, 0, -T, W + T, z0, z1) + box_triangles(L, L + T, -T, W + T, z0, z1) +
            box_triangles(0, L, -T, 0, z0, z1) + box_triangles(0, L, W, W + T, z0, z1))


def main():
    if len(sys.argv) != 7:
        sys.exit(__doc__)
    out = sys.argv[1]
    L, W, H, gap, top = (float(a) for a in sys.argv[2:])
    os.makedirs(out, exist_ok=True)
    split = H / 2 - gap / 2
    write_stl(os.path.join(out, "lower.stl"), slabs(L, W, -T, split))
    write_stl(os.path.join(out, "upper.stl"), slabs(L, W, split, top))
    # The cap: a plate 3 slab widths beyond the box on every side, its face at z = 0 (the deck moves it).
    m = 3 * T
    write_stl(os.path.join(out, "cap.stl"), [((-m, -m, 0), (L + m, -m, 0), (L + m, W + m, 0)),
                                             ((-m, -m, 0), (L + m, W + m, 0), (-m, W + m, 0))])


main()
