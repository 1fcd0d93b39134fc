/* SPDX-License-Identifier: MIT */
/* Penetration depth by the Expanding Polytope Algorithm (G. van den Bergen,
 * "Proximity queries and penetration depth computation on 3D game objects",
 * GDC 2001; "Collision Detection in Interactive 3D Environments", 2003).
 *
 * A polytope P with vertices in D = A - B is grown from the simplex GJK ends
 * with: each iteration takes the face nearest to the origin, asks for the
 * support of D in its normal and, if that point lies beyond the face, adds it
 * (the faces it sees are removed, the horizon is joined to it).
 *
 * The depth is certified both ways:
 * - upper: for any unit n, depth = min_m h_D(m) <= h_D(n) = <n, S_D(n)>;
 * - lower: if the faces form a closed oriented surface (each edge shared by two
 *   faces with opposite orientation, kept so by construction) and the origin is
 *   strictly inside every face's plane, at offset >= L, the origin has a
 *   positive winding number and the ball of radius L around it meets no face,
 *   so the ball lies in conv(vertices), inside D up to the vertices' rounding:
 *   depth >= L. This needs neither exact convexity of P nor exact arithmetic,
 *   only a rounding allowance on each face's offset (see face_plane).
 *
 * No allocation: the polytope lives on the stack (AGJK_EPA_MAX_VERTICES
 * vertices, twice as many faces); every loop is bounded by it or by the
 * iteration cap. */
#include "epa.h"

#define MAX_VERTICES AGJK_EPA_MAX_VERTICES
#define MAX_FACES AGJK__EPA_MAX_FACES

/* A face's neighbours are coded 4 * face + edge: the face across edge i (from
 * v[i] to v[(i + 1) % 3]) and the index of the same edge in it. */
#define ADJ(face, edge) (4 * (face) + (edge))
#define ADJ_FACE(code) ((code) >> 2)
#define ADJ_EDGE(code) ((code) & 3)

typedef struct epa_face {
    agjk_vec3 n;  /* unit outward normal */
    double dist;  /* offset <n, p> of the face's plane */
    double err;   /* rounding allowance on dist */
    int v[3];     /* vertex indices, counter-clockwise seen from outside */
    int adj[3];   /* ADJ(face, edge) across edge i */
    int mark;     /* the insertion that found the face visible (stamps only grow) */
} epa_face;

typedef struct epa_state {
    agjk__minkowski *md;
    agjk__vertex v[MAX_VERTICES + 1]; /* v[nv]: where a support call writes the next one */
    double vmax[MAX_VERTICES];  /* max |w_i| of each vertex (face_plane's rounding) */
    int vmark[MAX_VERTICES];    /* insert's check that the horizon is simple */
    /* The support hints (md->hint_a, hint_b) that found each vertex: a
     * support call in a face's normal starts from those of the face's newest
     * vertex, near its answer (hill climbing on polytopes: 6% fewer EPA
     * instructions on the benchmark's hulls than from wherever the last call
     * ended; the face's vertex farthest along the normal did worse). */
    int hint_a[MAX_VERTICES], hint_b[MAX_VERTICES];
    int nv;
    epa_face f[MAX_FACES];
    /* dist - err of each face slot (the lower bound the face proves), +inf for
     * a free slot. */
    double key[MAX_FACES];
    agjk__epa_scan scan;    /* the faces the nearest-face search visits */
    int nf;                 /* face slots in use, alive or free */
    int free_faces[MAX_FACES];
    int nfree;
    int stamp;
    double upper;           /* min over evaluated unit n of <n, S_D(n)> + dot rounding */
    agjk_vec3 upper_n;
    double estimate;        /* <n, S_D(n)> for upper_n */
    double lower;           /* best certified lower bound (before vertex noise) */
    double tolerance;       /* the caller's (absolute mode) */
    double width_cap;       /* sqrt(tolerance), solver units, absolute mode (width_met) */
    agjk__vertex extra[4];  /* blow-up points to add once the tetrahedron stands */
    int nextra;
    int support_calls;
} epa_state;

/* The solver's error scale of a point of D (kept up to date by the support). */
double agjk__epa_noise(const agjk__minkowski *md) { return md->noise; }

double agjk__epa_floor(const agjk__minkowski *md) {
    /* Vertex noise on both bounds, and face offsets with their rounding
     * allowance (larger on thin triangles): 1024 eps of the problem's size. */
    return 256.0 * md->noise;
}

/* sqrt(tolerance) in solver units, as agjk__epa_target computes it (so that
 * it bounds the target in absolute mode). */
static double width_cap(double tolerance, double scale) { return sqrt(tolerance * scale * scale); }

/* Multiplies everything held in solver units by f (the support call lowered
 * md->scale, see agjk__minkowski_shrink; exact, a power of two). */
static void follow_rescale(epa_state *st) {
    double f = st->md->rescaled;
    st->md->rescaled = 1.0;
    for (int i = 0; i < st->nv; ++i) {
        st->v[i].w = v3_scale(st->v[i].w, f);
        st->v[i].a = v3_scale(st->v[i].a, f);
        st->v[i].b = v3_scale(st->v[i].b, f);
        st->vmax[i] *= f;
    }
    for (int i = 0; i < st->nextra; ++i) {
        st->extra[i].w = v3_scale(st->extra[i].w, f);
        st->extra[i].a = v3_scale(st->extra[i].a, f);
        st->extra[i].b = v3_scale(st->extra[i].b, f);
    }
    for (int i = 0; i < st->nf; ++i) {
        st->f[i].dist *= f;
        st->f[i].err *= f;
        st->key[i] *= f; /* free slots stay +inf */
    }
    st->scan.excluded *= f;
    st->upper *= f;
    if (st->width_cap < INFINITY) st->width_cap = width_cap(st->tolerance, st->md->scale);
    st->estimate *= f;
    st->lower *= f;
}

/* The point of D farthest along n (a unit vector to rounding: a face normal
 * or a blow-up direction), its value <n, s> in *h, and the upper bound it
 * proves. Inline in EPA's loop; support_rare (out of line) for the blow-up
 * and the final call, so that the support path is expanded once. */
static AGJK__ALWAYS_INLINE int support(epa_state *st, agjk_vec3 n, agjk__vertex *s,
                                       double *h_out) {
    /* argmin <-n, .> */
    agjk__minkowski_support(st->md, v3_neg(n), 0.0, s, AGJK__SUPPORT_DIRECT, NULL, 0.0, 0.0, NULL);
    ++st->support_calls;
    if (st->md->bad_support) return 0;
    if (st->md->rescaled != 1.0) follow_rescale(st);
    double h = v3_dot(n, s->w);
    /* Rounding of the dot product and |n| = 1 +- a few eps, with
     * |w| <= sqrt(3) max |w_i|. */
    double up = h + 24.0 * DBL_EPSILON * v3_maxabs(s->w);
    if (up < st->upper) {
        st->upper = up;
        st->estimate = h;
        st->upper_n = n;
    }
    *h_out = h;
    return 1;
}

static AGJK__NOINLINE int support_rare(epa_state *st, agjk_vec3 n, agjk__vertex *s,
                                       double *h_out) {
    return support(st, n, s, h_out);
}

/* Plane of the triangle p0, p0 + e1, p0 + e2 (e1, e2 its computed edges, of
 * squared lengths l1, l2; c = e1 x e2): unit normal (right hand), offset, and
 * a rounding allowance on the offset. The computed normal is off the true one
 * by an angle of a few eps |e1| |e2| / |e1 x e2| (cancellation in the cross
 * product of the rounded edges), which moves the offset by that times |p|;
 * r >= the max |p_i| of the three points bounds |p|. Returns 0 for a triangle
 * without a normal. */
static inline int plane_of(agjk_vec3 c, agjk_vec3 p0, double l1, double l2, double r,
                           agjk_vec3 *n, double *dist, double *err) {
    double len2 = v3_norm2(c);
    if (!(len2 > 0.0) || !isfinite(len2)) return 0;
    double inv = 1.0 / sqrt(len2);
    *n = v3_scale(c, inv);
    *dist = v3_dot(*n, p0);
    /* |p| <= sqrt(3) max |p_i|; 1 / sin(angle at p0) = |e1| |e2| / |c|
     * <= (|e1|^2 + |e2|^2) / (2 |c|). */
    double skew = (l1 + l2) * (0.5 * inv);
    *err = 32.0 * DBL_EPSILON * r * (skew + 1.0);
    return 1; /* finite: solver units keep coordinates below 2^101 */
}

/* The same from the edges: c = e1 x e2. */
static inline int face_plane(agjk_vec3 p0, agjk_vec3 e1, agjk_vec3 e2, double l1, double l2,
                             double r, agjk_vec3 *n, double *dist, double *err) {
    return plane_of(v3_cross(e1, e2), p0, l1, l2, r, n, dist, err);
}

/* max |w_i| over the vertices of a triangle. */
static double max3(double a, double b, double c) {
    double m = a > b ? a : b;
    return m > c ? m : c;
}

/* Writes face fi (vertices a b c, plane n dist err) and its key. */
static AGJK__ALWAYS_INLINE void set_face(epa_state *st, int fi, int a, int b, int c,
                                         agjk_vec3 n, double dist, double err) {
    epa_face *f = &st->f[fi];
    f->v[0] = a;
    f->v[1] = b;
    f->v[2] = c;
    f->n = n;
    f->dist = dist;
    f->err = err;
    st->key[fi] = dist - err;
    agjk__epa_scan_offer(&st->scan, fi, dist - err, st->upper);
}

/* A free slot holds no face. */
static int alive(const epa_state *st, int fi) { return st->key[fi] < INFINITY; }

/* Whether the point w lies beyond face f, by more than its rounding allowance. */
static int sees(const epa_face *f, agjk_vec3 w) {
    return v3_dot(f->n, w) - f->dist > f->err;
}

/* Distance of p from the affine hull of pts[0..k-1] (k = 1, 2, 3). */
static double off_hull(const agjk__vertex *pts, int k, agjk_vec3 p) {
    agjk_vec3 d = v3_sub(p, pts[0].w);
    if (k == 1) return v3_norm(d);
    if (k == 2) {
        agjk_vec3 u = v3_normalize(v3_sub(pts[1].w, pts[0].w));
        return v3_norm(v3_cross(d, u));
    }
    agjk_vec3 n = v3_normalize(v3_cross(v3_sub(pts[1].w, pts[0].w), v3_sub(pts[2].w, pts[0].w)));
    return fabs(v3_dot(n, d));
}

/* Whether off_hull(pts, k, p) > thr (thr > 0), compared in squares: no
 * square root or division for GJK's points, nearly always far apart. */
static int off_hull_beyond(const agjk__vertex *pts, int k, agjk_vec3 p, double thr) {
    agjk_vec3 d = v3_sub(p, pts[0].w);
    double t2 = thr * thr;
    if (k == 1) return v3_norm2(d) > t2;
    agjk_vec3 e = v3_sub(pts[1].w, pts[0].w);
    if (k == 2) return v3_norm2(v3_cross(d, e)) > t2 * v3_norm2(e);
    agjk_vec3 c = v3_cross(e, v3_sub(pts[2].w, pts[0].w));
    double h = v3_dot(c, d);
    return h * h > t2 * v3_norm2(c);
}

/* Directions orthogonal to the affine hull of pts[0..k-1], k = 1, 2, 3. */
static int hull_normals(const agjk__vertex *pts, int k, agjk_vec3 dirs[3]) {
    if (k == 1) {
        dirs[0] = v3(1.0, 0.0, 0.0);
        dirs[1] = v3(0.0, 1.0, 0.0);
        dirs[2] = v3(0.0, 0.0, 1.0);
        return 3;
    }
    if (k == 2) {
        agjk_vec3 u = v3_normalize(v3_sub(pts[1].w, pts[0].w));
        /* The axis least aligned with u gives a well-conditioned cross product. */
        agjk_vec3 e = v3(1.0, 0.0, 0.0);
        if (fabs(u.y) <= fabs(u.x) && fabs(u.y) <= fabs(u.z)) e = v3(0.0, 1.0, 0.0);
        else if (fabs(u.z) <= fabs(u.x) && fabs(u.z) <= fabs(u.y)) e = v3(0.0, 0.0, 1.0);
        dirs[0] = v3_normalize(v3_cross(u, e));
        dirs[1] = v3_cross(u, dirs[0]);
        return 2;
    }
    dirs[0] = v3_normalize(v3_cross(v3_sub(pts[1].w, pts[0].w), v3_sub(pts[2].w, pts[0].w)));
    return 1;
}

/* Builds the initial tetrahedron in st->v[0..3] from GJK's simplex, blowing a
 * point, segment or triangle up by support calls in directions orthogonal to
 * it (van den Bergen 2003, sec. 4.3.8). Points found on both sides are kept in
 * st->extra, to be added next. Returns 1 with a tetrahedron, 0 when D is flat
 * (no volume to rounding) or a support failed. */
static int blow_up(epa_state *st, const agjk__vertex *simplex, int count, int *flat) {
    double thr = agjk__epa_floor(st->md);
    st->nv = 0;
    *flat = 0;
    if (count < 1) return 0;
    for (int i = 0; i < count && st->nv < 4; ++i)
        if (st->nv == 0 || off_hull_beyond(st->v, st->nv, simplex[i].w, thr))
            st->v[st->nv++] = simplex[i];
    while (st->nv < 4) {
        agjk_vec3 dirs[3];
        int nd = hull_normals(st->v, st->nv, dirs), added = 0;
        for (int i = 0; i < nd && !added; ++i) {
            agjk__vertex plus, minus;
            double h, scale;
            if (!support_rare(st, dirs[i], &plus, &h)) return 0;
            scale = st->md->scale;
            if (!support_rare(st, v3_neg(dirs[i]), &minus, &h)) return 0;
            if (st->md->scale != scale) { /* the second call lowered the units: follow */
                double f = st->md->scale / scale; /* a power of two: exact */
                plus.w = v3_scale(plus.w, f);
                plus.a = v3_scale(plus.a, f);
                plus.b = v3_scale(plus.b, f);
            }
            thr = agjk__epa_floor(st->md); /* the support calls may have grown the size */
            double op = off_hull(st->v, st->nv, plus.w), om = off_hull(st->v, st->nv, minus.w);
            if (op <= thr && om <= thr) continue; /* flat in this direction */
            const agjk__vertex *best = op >= om ? &plus : &minus;
            const agjk__vertex *other = op >= om ? &minus : &plus;
            st->v[st->nv++] = *best;
            if ((op >= om ? om : op) > thr && st->nextra < 4) st->extra[st->nextra++] = *other;
            added = 1;
        }
        if (!added) {
            *flat = 1;
            return 0;
        }
    }
    return 1;
}

/* The faces of a tetrahedron v[0..3] with v[3] above the triangle v[0] v[1]
 * v[2]: face i holds the edges tetra_tri[i][e] -> tetra_tri[i][e + 1], outward;
 * tetra_adj[i][e] is the face holding the same edge reversed, and that edge's
 * index in it. */
static const int tetra_tri[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
static const int tetra_adj[4][3] = {{ADJ(3, 0), ADJ(2, 0), ADJ(1, 0)},
                                    {ADJ(0, 2), ADJ(2, 2), ADJ(3, 1)},
                                    {ADJ(0, 1), ADJ(3, 2), ADJ(1, 1)},
                                    {ADJ(0, 0), ADJ(1, 2), ADJ(2, 1)}};

/* Face i of the tetrahedron (tetra_tri, tetra_adj) from its plane's cross
 * product c, first vertex p0, squared edge lengths l1, l2 and max |w_i| r. */
static AGJK__ALWAYS_INLINE int start_face(epa_state *st, int i, agjk_vec3 c, agjk_vec3 p0,
                                          double l1, double l2, double r) {
    agjk_vec3 n;
    double d, err;
    if (!plane_of(c, p0, l1, l2, r, &n, &d, &err)) return 0;
    const int *t = tetra_tri[i];
    set_face(st, i, t[0], t[1], t[2], n, d, err);
    for (int e = 0; e < 3; ++e) st->f[i].adj[e] = tetra_adj[i][e];
    return 1;
}

/* The per-vertex and per-face state of the tetrahedron st->v[0..3] (written
 * out: -O2 keeps four-pass loops with their index arithmetic). */
static AGJK__ALWAYS_INLINE void tetrahedron_state(epa_state *st) {
    /* The last call's hints: valid, if not the best. */
    const int ha = st->md->hint_a, hb = st->md->hint_b;
    st->nv = 4;
    st->vmax[0] = v3_maxabs(st->v[0].w);
    st->vmax[1] = v3_maxabs(st->v[1].w);
    st->vmax[2] = v3_maxabs(st->v[2].w);
    st->vmax[3] = v3_maxabs(st->v[3].w);
    st->vmark[0] = st->vmark[1] = st->vmark[2] = st->vmark[3] = 0;
    st->hint_a[0] = st->hint_a[1] = st->hint_a[2] = st->hint_a[3] = ha;
    st->hint_b[0] = st->hint_b[1] = st->hint_b[2] = st->hint_b[3] = hb;
    st->f[0].mark = st->f[1].mark = st->f[2].mark = st->f[3].mark = 0;
    for (int i = 0; i < 4; ++i) agjk__epa_scan_fresh(&st->scan, i);
    st->nf = 4;
    st->nfree = 0;
}

/* Faces of the tetrahedron st->v[0..3], outward, with their adjacency. */
static int tetrahedron_faces(epa_state *st) {
    agjk_vec3 p0 = st->v[0].w;
    double det = v3_dot(v3_cross(v3_sub(st->v[1].w, p0), v3_sub(st->v[2].w, p0)),
                        v3_sub(st->v[3].w, p0));
    if (!(det != 0.0) || !isfinite(det)) return 0;
    if (det < 0.0) { /* make v3 lie above the triangle v0 v1 v2 */
        agjk__vertex t = st->v[1];
        st->v[1] = st->v[2];
        st->v[2] = t;
    }
    tetrahedron_state(st);
    for (int i = 0; i < 4; ++i) {
        const int *t = tetra_tri[i];
        agjk_vec3 q = st->v[t[0]].w;
        agjk_vec3 e1 = v3_sub(st->v[t[1]].w, q), e2 = v3_sub(st->v[t[2]].w, q);
        if (!start_face(st, i, v3_cross(e1, e2), q, v3_norm2(e1), v3_norm2(e2),
                        max3(st->vmax[t[0]], st->vmax[t[1]], st->vmax[t[2]])))
            return 0;
    }
    return 1;
}

/* GJK's tetrahedron (count 4: how an overlapping query usually ends), set up
 * as blow_up and tetrahedron_faces would, bit for bit, with what they share
 * computed once: the edges from the first point, their squared lengths, the
 * cross product whose determinant orients the tetrahedron, each vertex copied
 * once in its final order. blow_up keeps each point that lies off the hull of
 * those before it by more than its threshold; the same three tests here, on
 * the same operands (a cross product with its factors swapped is the exact
 * negation: equal squared norms). Returns 0 when any test or face fails; the
 * general path then starts over (and meets the same failure). */
static int tetrahedron_start(epa_state *st, const agjk__vertex *sx) {
    double thr = agjk__epa_floor(st->md), t2 = thr * thr;
    agjk_vec3 p0 = sx[0].w;
    agjk_vec3 e1 = v3_sub(sx[1].w, p0), e2 = v3_sub(sx[2].w, p0), e3 = v3_sub(sx[3].w, p0);
    double l1 = v3_norm2(e1), l2 = v3_norm2(e2), l3 = v3_norm2(e3);
    agjk_vec3 c12 = v3_cross(e1, e2);
    double c2 = v3_norm2(c12), det = v3_dot(c12, e3);
    if (!(l1 > t2) || !(c2 > t2 * l1) || !(det * det > t2 * c2) || !isfinite(det)) return 0;
    /* v[3] above the triangle v[0] v[1] v[2]: with det < 0 the second and
     * third points trade places (tetrahedron_faces' swap). */
    int swap = det < 0.0;
    const agjk__vertex *q1 = &sx[swap ? 2 : 1], *q2 = &sx[swap ? 1 : 2];
    st->v[0] = sx[0];
    st->v[1] = *q1;
    st->v[2] = *q2;
    st->v[3] = sx[3];
    tetrahedron_state(st);
    const agjk_vec3 w1 = q1->w, w2 = q2->w, w3 = sx[3].w;
    agjk_vec3 e01 = swap ? e2 : e1, e02 = swap ? e1 : e2;
    double l01 = swap ? l2 : l1, l02 = swap ? l1 : l2;
    double r0 = st->vmax[0], r1 = st->vmax[1], r2 = st->vmax[2], r3 = st->vmax[3];
    /* Each face's plane from the same edges as tetrahedron_faces (tetra_tri:
     * from its first vertex to the next two), in the same order (the
     * nearest-face search lists them so); |v0 - v2|^2 = |e02|^2 exactly. */
    agjk_vec3 e12 = v3_sub(w2, w1), e13 = v3_sub(w3, w1);
    agjk_vec3 e20 = v3_sub(p0, w2), e23 = v3_sub(w3, w2);
    if (start_face(st, 0, swap ? c12 : v3_cross(e02, e01), p0, l02, l01, max3(r0, r2, r1)) &&
        start_face(st, 1, v3_cross(e01, e3), p0, l01, l3, max3(r0, r1, r3)) &&
        start_face(st, 2, v3_cross(e12, e13), w1, v3_norm2(e12), v3_norm2(e13),
                   max3(r1, r2, r3)) &&
        start_face(st, 3, v3_cross(e20, e23), w2, l02, v3_norm2(e23), max3(r2, r0, r3)))
        return 1;
    agjk__epa_scan_init(&st->scan); /* the general path lists its faces afresh */
    return 0;
}

/* Adds s to the polytope, seen from face f0 (sees(f0, s)): removes the faces
 * that see s and joins s to the horizon, the boundary of the region they
 * cover. The region is walked depth first across edges, each face's edges
 * counter-clockwise starting after the one it was entered by, so that for a
 * region that is a disc the horizon edges come out in order around it, each
 * ending where the next starts (as in van den Bergen's and Bullet's EPA).
 * Checks everything first; returns 0 with the polytope unchanged when the
 * store is full or the result would not be a closed surface of proper
 * triangles (rounding can make the visible region pinched or not a disc). */
static int insert(epa_state *st, const agjk__vertex *s, int f0, int hint_a, int hint_b) {
    static const int next3[3] = {1, 2, 0};
    /* The walk's stack of edges to cross, each as ADJ(face beyond, its edge
     * index there): f0 pushes 3, every other face entered (once: marked) 2. */
    int walk[2 * MAX_FACES + 3];
    /* slot[1..nrem]: the faces removed, then slot[1..nh] those of the new
     * faces; slot[0] and slot[nh + 1] repeat the ends (the cycle closes). */
    int slot[MAX_FACES + 2];
    /* Horizon edge i runs from hu[i] to hu[i + 1] (kept face across: ho[i]);
     * a simple cycle visits each vertex at most once: MAX_VERTICES edges.
     * New face i is the triangle s u_i u_{i+1}, of plane hn, hd, he [i]. */
    int hu[MAX_VERTICES + 1], ho[MAX_VERTICES];
    agjk_vec3 hn[MAX_VERTICES];
    double hd[MAX_VERTICES], he[MAX_VERTICES];
    /* The edges from s to the first and to the latest horizon vertex, their
     * squared lengths and the max |w_i| of their ends: each face's plane is
     * computed when the walk reaches its second horizon vertex. */
    agjk_vec3 w_first = {0.0, 0.0, 0.0}, w_last = w_first;
    double l_first = 0.0, l_last = 0.0, r_first = 0.0, r_last = 0.0;
    int depth = 0, nrem = 0, nh = 0, end = -1;
    if (st->nv >= MAX_VERTICES) return 0;
    const agjk_vec3 w = s->w;
    const double wmax = v3_maxabs(w);
    const int stamp = ++st->stamp;
    st->f[f0].mark = stamp;
    slot[++nrem] = f0;
    /* Popped in the order pushed in reverse: edges 0, 1, 2 of f0, and for a
     * face entered by edge e, the edges e + 1 and e + 2, each with all that
     * lies beyond it before the next. */
    for (int e = 2; e >= 0; --e) walk[depth++] = st->f[f0].adj[e];
    while (depth > 0) {
        int code = walk[--depth];
        int gi = ADJ_FACE(code), ge = ADJ_EDGE(code);
        epa_face *g = &st->f[gi];
        if (g->mark == stamp) continue; /* an edge inside the region */
        if (sees(g, w)) {
            g->mark = stamp;
            slot[++nrem] = gi;
            walk[depth++] = g->adj[next3[next3[ge]]];
            walk[depth++] = g->adj[next3[ge]];
            continue;
        }
        /* A horizon edge, from g's v[ge + 1] to its v[ge] (g sees it the
         * other way round): in walk order it must start where the last
         * ended. A vertex met twice would pinch the cycle (distinct vertices
         * also bound nh by MAX_VERTICES). */
        int u = g->v[next3[ge]];
        if ((nh > 0 && u != end) || st->vmark[u] == stamp) return 0;
        st->vmark[u] = stamp;
        end = g->v[ge];
        agjk_vec3 wu = v3_sub(st->v[u].w, w);
        double lu = v3_norm2(wu), ru = st->vmax[u];
        if (nh == 0) {
            w_first = wu;
            l_first = lu;
            r_first = ru;
        } else if (!face_plane(w, w_last, wu, l_last, lu, max3(r_last, ru, wmax), &hn[nh - 1],
                               &hd[nh - 1], &he[nh - 1])) {
            return 0;
        }
        hu[nh] = u;
        ho[nh] = code;
        w_last = wu;
        l_last = lu;
        r_last = ru;
        ++nh;
    }
    /* The horizon must close, the store must hold the new faces, and the
     * last one, from the last horizon vertex back to the first, needs a
     * normal too. */
    if (nh < 3 || end != hu[0] || nh > nrem + st->nfree + (MAX_FACES - st->nf)) return 0;
    if (!face_plane(w, w_last, w_first, l_last, l_first, max3(r_last, r_first, wmax),
                    &hn[nh - 1], &hd[nh - 1], &he[nh - 1]))
        return 0;
    hu[nh] = hu[0];
    /* Commit: the new faces take the removed faces' slots first. */
    int si = st->nv++;
    if (s != &st->v[si]) st->v[si] = *s;
    st->vmax[si] = wmax;
    st->vmark[si] = 0;
    st->hint_a[si] = hint_a;
    st->hint_b[si] = hint_b;
    for (int i = nrem + 1; i <= nh; ++i) {
        if (st->nfree > 0) {
            slot[i] = st->free_faces[--st->nfree];
        } else { /* a fresh slot: marks only grow, so 0 is never current */
            slot[i] = st->nf++;
            agjk__epa_scan_fresh(&st->scan, slot[i]);
            st->f[slot[i]].mark = 0;
        }
    }
    for (int i = nh + 1; i <= nrem; ++i) {
        st->key[slot[i]] = INFINITY;
        st->free_faces[st->nfree++] = slot[i];
    }
    slot[0] = slot[nh];
    slot[nh + 1] = slot[1];
    for (int i = 0; i < nh; ++i) {
        /* face i: edge 0 on the horizon (twin in the kept face ho[i]), edge 1
         * shared with face i + 1 (its edge 2), edge 2 with face i - 1 */
        int fi = slot[i + 1];
        set_face(st, fi, hu[i], hu[i + 1], si, hn[i], hd[i], he[i]);
        epa_face *f = &st->f[fi];
        f->adj[0] = ho[i];
        f->adj[1] = ADJ(slot[i + 2], 2);
        f->adj[2] = ADJ(slot[i], 1);
        st->f[ADJ_FACE(ho[i])].adj[ADJ_EDGE(ho[i])] = ADJ(fi, 0);
    }
    return 1;
}

/* The face whose plane is nearest to the origin (after its rounding
 * allowance): EPA expands it. Also the certified lower bound the polytope
 * proves, min over faces of dist - err, or -inf if it proves none (some face
 * may not have the origin strictly inside). */
static int nearest_face(epa_state *st, double *proved) {
    double low;
    int best = agjk__epa_scan_nearest(&st->scan, st->key, st->nf, st->upper, &low);
    *proved = low > 0.0 && low < INFINITY ? low : -INFINITY;
    return best;
}

AGJK__NOINLINE double agjk__signed_allowance_rescaled(double big, double scale) {
    return 2.0 * DBL_EPSILON * big + 2.0 * 0x1p-1074 * scale;
}

AGJK__NOINLINE double agjk__signed_floor_rescaled(double floor, double scale) {
    return floor / scale + 0x1p-1072;
}

/* Whether [lower, upper] (depth, with vertex noise) meets the target, as
 * agjk_signed_distance will judge the signed interval it makes of it: the
 * margins subtracted and its own rounding allowances added (bounded above
 * here), against the final floor. So a polytope that stops here gives an
 * answer whose final interval meets the promise. */
static AGJK__ALWAYS_INLINE int width_met(const epa_state *st, const agjk__epa_input *in,
                                         double noise) {
    double lo = st->lower - 2.0 * noise, up = st->upper + 2.0 * noise;
    if (!(up < INFINITY) || !(lo > -INFINITY)) return 0;
    double margin = in->margin * st->md->scale;
    double floor = agjk__signed_floor(st->md, margin);
    /* In absolute mode the target is at most max(sqrt(tolerance) (solver
     * units), floor): most iterations are decided here. */
    if (!in->relative && up - lo > st->width_cap && up - lo > floor) return 0;
    double s_lo = -(up + margin), s_hi = -(lo + margin);
    double big = fabs(s_lo) > fabs(s_hi) ? fabs(s_lo) : fabs(s_hi);
    double allow = agjk__signed_allowance(margin, big, st->md->scale);
    return agjk__signed_width_met(in->relative, in->tolerance, st->md->scale, s_lo - allow,
                                  s_hi + allow, floor);
}

/* Barycentric coordinates (unnormalised, l[i] opposite vertex i) of the
 * origin's projection on face f's plane; returns how far outside the
 * triangle it falls (0 inside), relative to the triangle's size. */
static double foot_weights(const epa_state *st, const epa_face *f, double l[3]) {
    agjk_vec3 q = v3_scale(f->n, f->dist);
    /* (Written out: each vertex's offset from q computed once, no index
     * arithmetic.) */
    agjk_vec3 d0 = v3_sub(st->v[f->v[0]].w, q), d1 = v3_sub(st->v[f->v[1]].w, q),
              d2 = v3_sub(st->v[f->v[2]].w, q);
    l[0] = v3_dot(v3_cross(d1, d2), f->n);
    l[1] = v3_dot(v3_cross(d2, d0), f->n);
    l[2] = v3_dot(v3_cross(d0, d1), f->n);
    double sum = fabs(l[0]) + fabs(l[1]) + fabs(l[2]);
    double worst = l[0] < 0.0 ? l[0] : 0.0;
    if (l[1] < worst) worst = l[1];
    if (l[2] < worst) worst = l[2];
    return sum > 0.0 ? -worst / sum : INFINITY;
}

/* Deepest points of the cores: the origin's projection on the nearest face's
 * plane, in barycentric coordinates. A facet of D made of several coplanar
 * triangles (boxes) may have its nearest triangle, by rounding, not the one
 * holding the projection: among the faces no farther than the upper bound,
 * the one holding its projection best is taken (clamped onto it). */
static void face_witness(const epa_state *st, int best, agjk__epa_output *out) {
    double l[3];
    double outside = foot_weights(st, &st->f[best], l);
    for (int i = 0; i < st->nf && outside > 0.0; ++i) {
        const epa_face *f = &st->f[i];
        if (!alive(st, i) || i == best || f->dist > st->upper) continue;
        double m[3];
        double o = foot_weights(st, f, m);
        if (o < outside) {
            outside = o;
            best = i;
            l[0] = m[0];
            l[1] = m[1];
            l[2] = m[2];
        }
    }
    const epa_face *f = &st->f[best];
    for (int i = 0; i < 3; ++i)
        if (!(l[i] > 0.0)) l[i] = 0.0;
    double sum = l[0] + l[1] + l[2];
    if (!(sum > 0.0) || !isfinite(sum)) {
        l[0] = l[1] = l[2] = 1.0;
        sum = 3.0;
    }
    const agjk__vertex *p0 = &st->v[f->v[0]], *p1 = &st->v[f->v[1]], *p2 = &st->v[f->v[2]];
    double t0 = l[0] / sum, t1 = l[1] / sum, t2 = l[2] / sum;
    /* (From +0, as a sum: a zero keeps its sign.) */
    agjk_vec3 zero = v3(0.0, 0.0, 0.0);
    out->a = v3_add(v3_add(v3_add(zero, v3_scale(p0->a, t0)), v3_scale(p1->a, t1)),
                    v3_scale(p2->a, t2));
    out->b = v3_add(v3_add(v3_add(zero, v3_scale(p0->b, t0)), v3_scale(p1->b, t1)),
                    v3_scale(p2->b, t2));
    out->has_witness = 1;
}

void agjk__epa(agjk__minkowski *md, const agjk__epa_input *in, agjk__epa_output *out) {
    epa_state st;
    st.md = md;
    st.nv = 0;
    st.nf = 0;
    st.nfree = 0;
    agjk__epa_scan_init(&st.scan);
    st.stamp = 0;
    st.upper = INFINITY;
    st.estimate = INFINITY;
    st.upper_n = v3(0.0, 0.0, 0.0);
    st.lower = -in->core_distance_upper; /* GJK's bound: depth >= -distance */
    st.tolerance = in->tolerance;
    st.width_cap = in->relative ? INFINITY : width_cap(in->tolerance, md->scale);
    st.nextra = 0;
    st.support_calls = 0;
    out->has_witness = 0;
    out->iterations = 0;
    out->converged = 0;

    int flat = 0;
    /* width_met's verdict on the final bounds when the loop ended on one
     * (nothing changes them afterwards then), -1 when still to be asked. */
    int met = -1;
    int ok = (in->count == 4 && tetrahedron_start(&st, in->simplex)) ||
             (blow_up(&st, in->simplex, in->count, &flat) && tetrahedron_faces(&st));
    if (md->bad_support) {
        out->outcome = AGJK__EPA_BAD_SUPPORT;
    } else if (!ok) {
        out->outcome = flat ? AGJK__EPA_FLAT : AGJK__EPA_DEGENERATE;
    } else {
        for (int i = 0; i < st.nextra; ++i)
            for (int fi = 0; fi < st.nf; ++fi)
                if (alive(&st, fi) && sees(&st.f[fi], st.extra[i].w)) {
                    insert(&st, &st.extra[i], fi, md->hint_a, md->hint_b);
                    break;
                }
        out->outcome = AGJK__EPA_CAP;
        int best = -1;
        for (int k = 0;; ++k) {
            double proved;
            best = nearest_face(&st, &proved);
            if (best < 0) { /* no face: cannot happen with a polytope */
                out->outcome = AGJK__EPA_DEGENERATE;
                break;
            }
            if (proved > st.lower) st.lower = proved;
            if (width_met(&st, in, agjk__epa_noise(md))) {
                out->outcome = AGJK__EPA_CONVERGED;
                met = 1;
                break;
            }
            if (k >= in->max_iterations) break;
            const epa_face *f = &st.f[best];
            agjk__vertex *s = &st.v[st.nv]; /* (the spare slot: no copy when added) */
            double h;
            ++out->iterations;
            md->hint_a = st.hint_a[f->v[2]]; /* the face's newest vertex */
            md->hint_b = st.hint_b[f->v[2]];
            if (!support(&st, f->n, s, &h)) {
                out->outcome = AGJK__EPA_BAD_SUPPORT;
                break;
            }
            f = &st.f[best]; /* (dist may have been rescaled) */
            if (!(h - f->dist > f->err)) { /* sees(f, s->w) */
                /* The face lies on D's boundary to rounding: the bounds are as
                 * tight as this polytope can make them. */
                met = width_met(&st, in, agjk__epa_noise(md));
                out->outcome = met ? AGJK__EPA_CONVERGED : AGJK__EPA_NO_PROGRESS;
                break;
            }
            if (st.nv >= MAX_VERTICES) {
                out->outcome = AGJK__EPA_FULL;
                break;
            }
            if (!insert(&st, s, best, md->hint_a, md->hint_b)) {
                out->outcome = AGJK__EPA_DEGENERATE;
                break;
            }
        }
        if (best >= 0 && in->want_witness) face_witness(&st, best, out);
        if (!(st.upper < INFINITY) && best >= 0) {
            /* No support value yet (cap before the first call): take one. */
            double h;
            if (!support_rare(&st, st.f[best].n, &st.v[st.nv], &h))
                out->outcome = AGJK__EPA_BAD_SUPPORT;
            met = -1;
        }
    }
    /* Twice the solver's noise scale on each end: a support value and a face
     * offset combine points of both shapes, and a verdict at the edge of the
     * noise model (magnitudes 1e15 apart, found by fuzzing) must not flip. */
    double noise = 2.0 * agjk__epa_noise(md);
    out->upper = st.upper + noise;
    out->lower = st.lower - noise;
    if (out->upper < out->lower) {
        /* Two certificates that contradict each other can only do so by
         * rounding beyond the allowances (extreme magnitude ranges): keep
         * both ends, no verdict from a zero-width interval. */
        double t = out->upper;
        out->upper = out->lower;
        out->lower = t;
    }
    out->estimate = st.estimate;
    if (out->estimate > out->upper) out->estimate = out->upper;
    if (out->estimate < out->lower) out->estimate = out->lower;
    out->normal = st.upper_n;
    if (met < 0 && out->outcome != AGJK__EPA_BAD_SUPPORT)
        met = width_met(&st, in, agjk__epa_noise(md));
    out->converged = out->outcome != AGJK__EPA_BAD_SUPPORT && met;
    if (out->converged && out->outcome != AGJK__EPA_FLAT) out->outcome = AGJK__EPA_CONVERGED;
    out->support_calls = st.support_calls;
}
