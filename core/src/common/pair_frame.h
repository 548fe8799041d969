#pragma once
// The frame the overlap and penetration kernels run in: the pose of the smaller shape (distance's kernels run at its
// position, rotations kept). Its features keep full precision, while the other shape's offset rounds by
// ~eps * |offset|, small against that larger shape's own size.
// (In pose0's frame a unit cube 1e30 away from a capsule of radius 1e30 collapsed to one point, and the kernels read
// its faces and edges from rounding noise: "penetrating" for shapes 4e29 apart, found by fuzz_pair_queries.)
#include <cmath>
#include <limits>

#include "common/unit_vector.h"
#include "gq/cooking.h"
#include "gq/custom.h"
#include "gq/geometry.h"

namespace gq::detail {

// Radius about the shape's origin that holds its features (range-safe: a box 2^-540 across has a radius, not 0).
// Infinite for planes, meshes and heightfields: they are never the smaller shape (their kernels work in the surface's
// own frame).
template <class T> T featureRadius(const Geometry<T>& g) {
  const auto radius = [](const Bounds3<T>& b) {
    return rangeSafeNorm(Vec3<T>(b.min.cwiseAbs().cwiseMax(b.max.cwiseAbs())));
  };
  if (const auto* s = g.template getIf<SphereGeometry<T>>()) return s->radius;
  if (const auto* c = g.template getIf<CapsuleGeometry<T>>()) return c->halfHeight + c->radius;
  if (const auto* b = g.template getIf<BoxGeometry<T>>()) return rangeSafeNorm(b->halfExtents);
  if (const auto* m = g.template getIf<ConvexMeshGeometry<T>>())
    return radius(m->mesh->localBounds) * m->scale.scale.cwiseAbs().maxCoeff();
  if (const auto* c = g.template getIf<CustomGeometry<T>>()) return radius(c->callbacks->localBounds());
  return std::numeric_limits<T>::infinity();
}

template <class T> struct PairFrame {
  Transform<T> world;         // the frame's pose
  Transform<T> pose0, pose1;  // the shapes' poses in it
};

// Shape 1 is strictly smaller (so equal shapes keep pose0's frame, as every pair did before).
template <class T> bool shape1IsSmaller(const Geometry<T>& g0, const Geometry<T>& g1) {
  return featureRadius(g1) < featureRadius(g0);
}

// A rotation that is not unit to rounding is normalised (validation accepts |q| within 1e-3 of 1, and the relative
// pose of non-unit quaternions is a scaled rotation: found by fuzz_pair_queries, a cube hull whose |q| was 1.0008
// grew by 0.17 % in the SAT kernels, penetration 3.06784 against the exact 3.06625). One unit to rounding is used as
// given, so touching contacts built from it stay touching.
template <class T> [[gnu::noinline]] Quat<T> normalizedRotation(const Quat<T>& q) { return q.normalized(); }
template <class T> [[gnu::always_inline]] inline Quat<T> unitRotation(const Quat<T>& q) {
  return std::abs(q.squaredNorm() - T(1)) <= T(16) * std::numeric_limits<T>::epsilon() ? q : normalizedRotation(q);
}

// The frame from the shapes' feature radii r0, r1 (featureRadius, stored by a prepared shape).
template <class T> PairFrame<T> pairFrame(T r0, const Transform<T>& p0, T r1, const Transform<T>& p1) {
  const Transform<T> u0(p0.p, unitRotation(p0.q)), u1(p1.p, unitRotation(p1.q));
  if (r1 < r0) return {u1, u0.relativeTo(u1), Transform<T>()};
  return {u0, Transform<T>(), u1.relativeTo(u0)};
}

template <class T>
PairFrame<T> pairFrame(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1) {
  return pairFrame(featureRadius(g0), p0, featureRadius(g1), p1);
}

// The smaller shape's position, for queries that translate both poses and keep their rotations.
template <class T> Vec3<T> pairOrigin(T r0, const Transform<T>& p0, T r1, const Transform<T>& p1) {
  return r1 < r0 ? p1.p : p0.p;
}

template <class T>
Vec3<T> pairOrigin(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1) {
  return pairOrigin(featureRadius(g0), p0, featureRadius(g1), p1);
}

}  // namespace gq::detail
