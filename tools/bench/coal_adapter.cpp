// SPDX-License-Identifier: MIT
// Coal 3.0.3 behind the C interface of coal_adapter.h: Coal's own shapes
// (Ellipsoid, Box, Convex<Triangle> with its vertex graph) and its GJK solver
// coal::details::GJK with the variants of Montaut et al. (RSS 2022): plain
// GJK, Nesterov acceleration (optionally with the normalization heuristic)
// and Polyak acceleration, stopped on the Frank-Wolfe duality gap, absolute
// tolerance, as the paper's benchmark does. Built only when
// tools/fetch-coal.sh has fetched Coal; linked against its libcoal.so.
#include "coal_adapter.h"

#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <vector>

#include "coal/config.hh"
#include "coal/narrowphase/gjk.h"
#include "coal/narrowphase/minkowski_difference.h"
#include "coal/shape/convex.h"
#include "coal/shape/geometric_shapes.h"

namespace {

using coal::Matrix3s;
using coal::Transform3s;
using coal::Vec3s;
using coal::details::GJK;
using coal::details::MinkowskiDiff;

Transform3s make_transform(const double r[9], const double t[3]) {
    Matrix3s R;
    R << r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8];
    return Transform3s(R, Vec3s(t[0], t[1], t[2]));
}

// Support calls are counted in one untimed run by wrapping the support
// function MinkowskiDiff::set() selected (the benchmark is single-threaded).
MinkowskiDiff::GetSupportFunction counted_inner = nullptr;
long counted_calls = 0;

void counting_support(const MinkowskiDiff &md, const Vec3s &dir, Vec3s &s0, Vec3s &s1,
                      coal::support_func_guess_t &hint, coal::details::ShapeSupportData data[2]) {
    ++counted_calls;
    counted_inner(md, dir, s0, s1, hint, data);
}

volatile double sink;

// Runs f, turning an exception from Coal into a message and `failed`.
template <class F, class R>
R guarded(F f, R failed) {
    try {
        return f();
    } catch (const std::exception &e) {
        std::fprintf(stderr, "agjk-bench: Coal threw: %s\n", e.what());
        return failed;
    }
}

}  // namespace

extern "C" int coal_adapter_available(void) { return 1; }

extern "C" const char *coal_adapter_version(void) { return COAL_VERSION; }

extern "C" void *coal_adapter_shape_new(const coal_shape_desc *d) {
    try {
        if (d->kind == COAL_SHAPE_ELLIPSOID)
            return new coal::Ellipsoid(d->size[0], d->size[1], d->size[2]);
        if (d->kind == COAL_SHAPE_BOX)  // Coal's Box takes full side lengths
            return new coal::Box(2 * d->size[0], 2 * d->size[1], 2 * d->size[2]);
        if (d->kind == COAL_SHAPE_CONVEX && d->vertex_count > 0 && d->triangle_count > 0) {
            auto points = std::make_shared<std::vector<Vec3s>>();
            auto tris = std::make_shared<std::vector<coal::Triangle>>();
            points->reserve((size_t)d->vertex_count);
            for (int i = 0; i < d->vertex_count; ++i)
                points->emplace_back(d->vertices[3 * i], d->vertices[3 * i + 1],
                                     d->vertices[3 * i + 2]);
            tris->reserve((size_t)d->triangle_count);
            for (int i = 0; i < d->triangle_count; ++i)
                tris->emplace_back((coal::Triangle::index_type)d->triangles[3 * i],
                                   (coal::Triangle::index_type)d->triangles[3 * i + 1],
                                   (coal::Triangle::index_type)d->triangles[3 * i + 2]);
            return new coal::Convex<coal::Triangle>(points, (unsigned)d->vertex_count, tris,
                                                    (unsigned)d->triangle_count);
        }
    } catch (const std::exception &e) {
        std::fprintf(stderr, "agjk-bench: Coal rejected a shape: %s\n", e.what());
    }
    return nullptr;
}

extern "C" void coal_adapter_shape_free(void *shape) {
    delete static_cast<coal::ShapeBase *>(shape);
}

namespace {

// One query: what stays the same between runs is built once, outside the
// timed region (as agjk's options are).
struct Query {
    const coal::ShapeBase *a, *b;
    Transform3s tf_a, tf_b;
    GJK gjk;
    MinkowskiDiff md;
    bool normalize;

    Query(const coal::ShapeBase *a_, const coal::ShapeBase *b_, const coal_query_desc *q)
        : a(a_), b(b_), tf_a(make_transform(q->rotation_a, q->translation_a)),
          tf_b(make_transform(q->rotation_b, q->translation_b)),
          gjk((size_t)q->max_iterations, q->tolerance),
          normalize(q->method == COAL_NESTEROV_NORMALIZED) {
        gjk.gjk_variant = q->method == COAL_GJK      ? coal::DefaultGJK
                          : q->method == COAL_POLYAK ? coal::PolyakAcceleration
                                                     : coal::NesterovAcceleration;
        gjk.convergence_criterion = coal::DualityGap;
        gjk.convergence_criterion_type = coal::Absolute;
        gjk.setDistanceEarlyBreak(q->boolean ? 0.0 : std::numeric_limits<double>::max());
    }

    // The timed region: the poses into A's frame and the support function
    // (MinkowskiDiff::set), x0 = c_A - c_B (B's origin sits at ot1 in A's
    // frame), GJK::evaluate.
    GJK::Status run() {
        md.set(a, b, tf_a, tf_b);
        md.normalize_support_direction = normalize;
        const Vec3s guess = -md.ot1;
        return gjk.evaluate(md, guess);
    }

    // The same, counting the support calls.
    long count_support_calls() {
        md.set(a, b, tf_a, tf_b);
        md.normalize_support_direction = normalize;
        counted_inner = md.getSupportFunc;
        counted_calls = 0;
        md.getSupportFunc = counting_support;
        gjk.evaluate(md, -md.ot1);
        return counted_calls;
    }
};

int verdict_of(GJK::Status status) {
    switch (status) {
    case GJK::NoCollision:
    case GJK::NoCollisionEarlyStopped: return 0;
    case GJK::Collision:
    case GJK::CollisionWithPenetrationInformation: return 1;
    default: return -1;
    }
}

}  // namespace

extern "C" void *coal_adapter_query_new(const void *shape_a, const void *shape_b,
                                        const coal_query_desc *q) {
    const coal::ShapeBase *a = static_cast<const coal::ShapeBase *>(shape_a);
    const coal::ShapeBase *b = static_cast<const coal::ShapeBase *>(shape_b);
    if (!a || !b || q->max_iterations < 1 || !(q->tolerance > 0)) return nullptr;
    return guarded([&]() -> void * { return new Query(a, b, q); }, static_cast<void *>(nullptr));
}

extern "C" int coal_adapter_query_run(void *query) {
    return guarded([&] { return verdict_of(static_cast<Query *>(query)->run()); }, -2);
}

extern "C" void coal_adapter_query_free(void *query) { delete static_cast<Query *>(query); }

extern "C" int coal_adapter_run(const void *shape_a, const void *shape_b,
                                const coal_query_desc *q, coal_answer *out) {
    Query *query = static_cast<Query *>(coal_adapter_query_new(shape_a, shape_b, q));
    if (!query) return -1;
    const int rc = guarded(
        [&] {
            const int reps = q->reps > 0 ? q->reps : 1;
            std::vector<double> times((size_t)reps);
            GJK::Status status = GJK::DidNotRun;
            for (int r = 0; r < reps; ++r) {
                const double t0 = q->now_ns();
                status = query->run();
                times[(size_t)r] = q->now_ns() - t0;
                sink = query->gjk.distance;
            }
            out->coal_status = (int)status;
            out->iterations = (int)query->gjk.getNumIterations();
            out->verdict = verdict_of(status);
            out->distance = out->verdict == 1 ? 0.0 : query->gjk.distance;
            out->time_ns = q->reps > 0 ? q->trimmed_mean(times.data(), reps) : 0.0;
            out->support_calls = (int)query->count_support_calls();
            return 0;
        },
        -1);
    delete query;
    return rc;
}

namespace {

using coal::details::EPA;

// One depth query: GJK and EPA objects built once (EPA's stores sized for
// epa_max_iterations), as a GJKSolver reused between queries holds them.
struct DepthQuery {
    const coal::ShapeBase *a, *b;
    Transform3s tf_a, tf_b;
    GJK gjk;
    EPA epa;
    MinkowskiDiff md;
    size_t gjk_max_iterations, epa_max_iterations;
    double gjk_tolerance, epa_tolerance;
    Vec3s w0, w1, normal;

    DepthQuery(const coal::ShapeBase *a_, const coal::ShapeBase *b_, const coal_depth_desc *q)
        : a(a_), b(b_), tf_a(make_transform(q->rotation_a, q->translation_a)),
          tf_b(make_transform(q->rotation_b, q->translation_b)),
          gjk((size_t)q->gjk_max_iterations, q->gjk_tolerance),
          epa((size_t)q->epa_max_iterations, q->epa_tolerance),
          gjk_max_iterations((size_t)q->gjk_max_iterations),
          epa_max_iterations((size_t)q->epa_max_iterations), gjk_tolerance(q->gjk_tolerance),
          epa_tolerance(q->epa_tolerance) {}

    // The timed region (see coal_adapter.h); true when EPA ran.
    bool run() {
        md.set(a, b, tf_a, tf_b);
        gjk.reset(gjk_max_iterations, gjk_tolerance);
        epa.status = EPA::DidNotRun;
        const Vec3s guess = -md.ot1;
        if (gjk.evaluate(md, guess) != GJK::Collision) return false;
        epa.reset(epa_max_iterations, epa_tolerance);
        epa.evaluate(gjk, -guess);
        epa.getWitnessPointsAndNormal(md, w0, w1, normal);
        return true;
    }

    void answer(coal_depth_answer *out) const {
        out->found = epa.status != EPA::DidNotRun;
        out->gjk_status = (int)gjk.status;
        out->epa_status = (int)epa.status;
        out->epa_valid = out->found && (epa.status & EPA::Valid) != 0;
        out->epa_iterations = out->found ? (int)epa.getNumIterations() : 0;
        out->depth = out->found ? epa.depth : 0.0;
        for (int i = 0; i < 3; ++i) out->normal[i] = out->found ? normal[i] : 0.0;
    }
};

}  // namespace

extern "C" void *coal_adapter_depth_query_new(const void *shape_a, const void *shape_b,
                                              const coal_depth_desc *q) {
    const coal::ShapeBase *a = static_cast<const coal::ShapeBase *>(shape_a);
    const coal::ShapeBase *b = static_cast<const coal::ShapeBase *>(shape_b);
    if (!a || !b || q->gjk_max_iterations < 1 || q->epa_max_iterations < 1 ||
        !(q->gjk_tolerance > 0) || !(q->epa_tolerance > 0))
        return nullptr;
    return guarded([&]() -> void * { return new DepthQuery(a, b, q); },
                   static_cast<void *>(nullptr));
}

extern "C" int coal_adapter_depth_query_run(void *query) {
    return guarded([&] { return static_cast<DepthQuery *>(query)->run() ? 1 : 0; }, -2);
}

extern "C" void coal_adapter_depth_query_answer(const void *query, coal_depth_answer *out) {
    static_cast<const DepthQuery *>(query)->answer(out);
}

extern "C" void coal_adapter_depth_query_free(void *query) {
    delete static_cast<DepthQuery *>(query);
}

extern "C" int coal_adapter_depth(const void *shape_a, const void *shape_b,
                                  const coal_depth_desc *q, coal_depth_answer *out) {
    DepthQuery *query =
        static_cast<DepthQuery *>(coal_adapter_depth_query_new(shape_a, shape_b, q));
    if (!query) return -1;
    const int rc = guarded(
        [&] {
            const int reps = q->reps > 0 ? q->reps : 1;
            std::vector<double> times((size_t)reps);
            for (int r = 0; r < reps; ++r) {
                const double t0 = q->now_ns();
                query->run();
                times[(size_t)r] = q->now_ns() - t0;
                sink = query->epa.depth;
            }
            query->answer(out);
            out->time_ns = q->reps > 0 ? q->trimmed_mean(times.data(), reps) : 0.0;
            return 0;
        },
        -1);
    delete query;
    return rc;
}
