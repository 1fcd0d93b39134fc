#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Independent reference for tests/cli: the exact distance between two convex
polyhedral meshes in given poses, by brute force over feature pairs.

For two disjoint convex polytopes the closest points lie on a vertex-face or an
edge-edge pair of their boundaries, so the minimum over all vertex-triangle
and segment-segment distances is the distance (Ericson, Real-Time Collision
Detection, 5.1.5 and 5.1.9, rewritten here). Plain Python floats, no agjk code.

  ref_distance.py case SEED COUNT MESH_A MESH_B
      prints COUNT lines "tx ty tz qw qx qy qz distance" for random poses of B
      (A at the identity); distance 0 means the hulls intersect
  ref_distance.py mesh LEVEL OUT.obj
      writes an icosphere of LEVEL subdivisions (radius 1)
"""
import math
import random
import sys


def read_mesh(path):
    verts, faces = [], []
    with open(path) as f:
        lines = [l.split("#")[0].split() for l in f]
    lines = [t for t in lines if t]
    if path.endswith(".off"):
        nv, nf = int(lines[1][0]), int(lines[1][1])
        verts = [tuple(map(float, t[:3])) for t in lines[2:2 + nv]]
        for t in lines[2 + nv:2 + nv + nf]:
            k = int(t[0])
            faces.append([int(x) for x in t[1:1 + k]])
    else:
        for t in lines:
            if t[0] == "v":
                verts.append(tuple(map(float, t[1:4])))
            elif t[0] == "f":
                faces.append([int(x.split("/")[0]) - 1 for x in t[1:]])
    tris = [(f[0], f[i], f[i + 1]) for f in faces for i in range(1, len(f) - 1)]
    edges = sorted({(min(a, b), max(a, b)) for t in tris for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0]))})
    return verts, tris, edges


def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def add(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def mul(a, s): return (a[0] * s, a[1] * s, a[2] * s)
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def closest_on_triangle(p, a, b, c):
    """Closest point to p on triangle abc (Voronoi regions of the vertices,
    edges and face, in that order)."""
    ab, ac, ap = sub(b, a), sub(c, a), sub(p, a)
    d1, d2 = dot(ab, ap), dot(ac, ap)
    if d1 <= 0 and d2 <= 0:
        return a
    bp = sub(p, b)
    d3, d4 = dot(ab, bp), dot(ac, bp)
    if d3 >= 0 and d4 <= d3:
        return b
    vc = d1 * d4 - d3 * d2
    if vc <= 0 and d1 >= 0 and d3 <= 0:
        return add(a, mul(ab, d1 / (d1 - d3)))
    cp = sub(p, c)
    d5, d6 = dot(ab, cp), dot(ac, cp)
    if d6 >= 0 and d5 <= d6:
        return c
    vb = d5 * d2 - d1 * d6
    if vb <= 0 and d2 >= 0 and d6 <= 0:
        return add(a, mul(ac, d2 / (d2 - d6)))
    va = d3 * d6 - d5 * d4
    if va <= 0 and (d4 - d3) >= 0 and (d5 - d6) >= 0:
        return add(b, mul(sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6))))
    denom = 1.0 / (va + vb + vc)
    return add(a, add(mul(ab, vb * denom), mul(ac, vc * denom)))


def segment_closest(p1, q1, p2, q2):
    """Closest points of segments p1q1 and p2q2."""
    d1, d2, r = sub(q1, p1), sub(q2, p2), sub(p1, p2)
    a, e, f = dot(d1, d1), dot(d2, d2), dot(d2, r)
    c, b = dot(d1, r), dot(d1, d2)
    denom = a * e - b * b
    s = min(max((b * f - c * e) / denom, 0.0), 1.0) if denom > 1e-300 else 0.0
    t = (b * s + f) / e
    if t < 0:
        t, s = 0.0, min(max(-c / a, 0.0), 1.0)
    elif t > 1:
        t, s = 1.0, min(max((b - c) / a, 0.0), 1.0)
    return add(p1, mul(d1, s)), add(p2, mul(d2, t))


def rotate(q, v):
    w, x, y, z = q
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
         [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
         [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]
    return tuple(sum(r[i][j] * v[j] for j in range(3)) for i in range(3))


def distance(ma, mb):
    """Distance between hull(ma) and hull(mb), or None if they intersect.

    The minimum over feature pairs is the distance only when the shapes are
    disjoint; for penetrating shapes it is some positive number. So the pair
    found must also pass the separation test: the plane through its points,
    normal to their difference, must have A on one side and B on the other
    (it does exactly when the shapes are disjoint)."""
    (va, ta, ea), (vb, tb, eb) = ma, mb
    best, pair = math.inf, None

    def consider(a, b):
        nonlocal best, pair
        d = math.dist(a, b)
        if d < best:
            best, pair = d, (a, b)
    for p in va:
        for t in tb:
            consider(p, closest_on_triangle(p, vb[t[0]], vb[t[1]], vb[t[2]]))
    for p in vb:
        for t in ta:
            consider(closest_on_triangle(p, va[t[0]], va[t[1]], va[t[2]]), p)
    for i, j in ea:
        for k, l in eb:
            consider(*segment_closest(va[i], va[j], vb[k], vb[l]))
    pa, pb = pair
    n = sub(pb, pa)
    slack = 1e-12 * max(1.0, max(abs(c) for v in va + vb for c in v))
    if best == 0 or max(dot(n, v) for v in va) > dot(n, pa) + slack * math.sqrt(dot(n, n)) \
            or min(dot(n, v) for v in vb) < dot(n, pb) - slack * math.sqrt(dot(n, n)):
        return None
    return best


def cases(seed, count, path_a, path_b):
    random.seed(seed)
    ma, mb = read_mesh(path_a), read_mesh(path_b)
    ra = max(math.sqrt(dot(v, v)) for v in ma[0])
    rb = max(math.sqrt(dot(v, v)) for v in mb[0])
    made = 0
    while made < count:
        q = [random.gauss(0, 1) for _ in range(4)]
        n = math.sqrt(sum(x * x for x in q))
        q = [x / n for x in q]
        u = [random.gauss(0, 1) for _ in range(3)]
        un = math.sqrt(sum(x * x for x in u))
        # From touching distance up to one radius apart, to get small gaps too.
        d = (ra + rb) * random.uniform(0.55, 1.3)
        t = tuple(d * x / un for x in u)
        vb = [add(rotate(q, v), t) for v in mb[0]]
        dist = distance(ma, (vb, mb[1], mb[2]))
        if dist is not None and dist < 1e-3:  # nearly touching: no clear verdict
            continue
        dist = 0.0 if dist is None else dist  # 0: certainly intersecting
        print(" ".join(repr(x) for x in list(t) + q + [dist]))
        made += 1


def icosphere(levels, path):
    t = (1 + 5 ** 0.5) / 2
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
             (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9),
             (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2),
             (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
             (8, 6, 7), (9, 8, 1)]
    unit = lambda v: mul(v, 1 / math.sqrt(dot(v, v)))
    verts = [unit(v) for v in verts]
    for _ in range(levels):
        cache, new = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                verts.append(unit(mul(add(verts[a], verts[b]), 0.5)))
                cache[key] = len(verts) - 1
            return cache[key]
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            new += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new
    with open(path, "w") as f:
        for v in verts:
            f.write("v %r %r %r\n" % v)
        for a, b, c in faces:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


if __name__ == "__main__":
    if sys.argv[1] == "case":
        cases(int(sys.argv[2]), int(sys.argv[3]), sys.argv[4], sys.argv[5])
    else:
        icosphere(int(sys.argv[2]), sys.argv[3])
