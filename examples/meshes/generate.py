#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Regenerates the sample meshes of examples/meshes (committed; run by hand).

cube.off         unit cube [-0.5, 0.5]^3, 8 vertices, 6 quads
tetrahedron.off  regular tetrahedron, vertices (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1)
square.off       flat unit square in z = 0 (degenerate: coplanar)
sphere.obj       icosphere of radius 1, 3 subdivisions: 642 vertices, 1280
                 triangles; every vertex exactly on the sphere (to 17 digits)
points.obj       point cloud: 8 cube corners plus its centre, no faces
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def fmt(x):
    return repr(float(x))


def write_off(name, verts, faces, comment):
    with open(os.path.join(HERE, name), "w") as f:
        f.write("OFF\n# %s\n%d %d 0\n" % (comment, len(verts), len(faces)))
        for v in verts:
            f.write(" ".join(fmt(c) for c in v) + "\n")
        for face in faces:
            f.write("%d %s\n" % (len(face), " ".join(str(i) for i in face)))


def icosphere(levels):
    t = (1 + 5 ** 0.5) / 2
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
             (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9),
             (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2),
             (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
             (8, 6, 7), (9, 8, 1)]

    def unit(v):
        n = math.sqrt(sum(c * c for c in v))
        return tuple(c / n for c in v)

    verts = [unit(v) for v in verts]
    for _ in range(levels):
        cache = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                va, vb = verts[a], verts[b]
                verts.append(unit(tuple((x + y) / 2 for x, y in zip(va, vb))))
                cache[key] = len(verts) - 1
            return cache[key]

        new = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            new += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new
    return verts, faces


def main():
    h = 0.5
    cube = [(x, y, z) for x in (-h, h) for y in (-h, h) for z in (-h, h)]
    # index = 4*ix + 2*iy + iz; quads listed counter-clockwise seen from outside
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    write_off("cube.off", cube, quads, "unit cube [-0.5, 0.5]^3")
    tet = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
    write_off("tetrahedron.off", tet, [(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)],
              "regular tetrahedron")
    sq = [(-h, -h, 0), (h, -h, 0), (h, h, 0), (-h, h, 0)]
    write_off("square.off", sq, [(0, 1, 2, 3)], "flat unit square in z = 0")
    verts, faces = icosphere(3)
    with open(os.path.join(HERE, "sphere.obj"), "w") as f:
        f.write("# icosphere, radius 1, 3 subdivisions (examples/meshes/generate.py)\n")
        f.write("o sphere\n")
        for v in verts:
            f.write("v %s\n" % " ".join(fmt(c) for c in v))
        for a, b, c in faces:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))
    with open(os.path.join(HERE, "points.obj"), "w") as f:
        f.write("# point cloud: cube corners and centre, no faces\n")
        for v in cube + [(0, 0, 0)]:
            f.write("v %s\n" % " ".join(fmt(c) for c in v))


if __name__ == "__main__":
    main()
