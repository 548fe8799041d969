// Sphere-hull and capsule-hull penetration in the hull's frame (penetration/rounded_hull.h) equals the SAT and
// closest-point search over the posed polytope (penetrationRoundedPolytope): the same penetrating/apart answer, the
// depth within 1e-9 (double) / 1e-4 (float) relative plus 8 ulps of the pair's size, and the direction realising
// that depth (the rounded core pushed along it, from all hull vertices, by exactly the depth). 1002 seeded pairs per
// hull size (30 and 100 points on an ellipsoid, and 300 in double) and scalar, a sixth of each kind:
//  - a sphere, and a capsule, about the hull in a random pose (inside, crossing the surface, outside);
//  - a sphere centre, and a capsule core, deep inside the hull;
//  - a capsule lying along a face, just above or below it (a segment parallel to a face);
//  - a capsule 1e-2 .. 1e2 the hull's size (size ratios 1e4 between its radius and its length).
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

#include "gq/cooking.h"
#include "overlap/polytope.h"
#include "penetration/penetration.h"
#include "penetration/rounded_hull.h"
#include "random_hulls.h"
#include "test_util.h"

namespace gq::test {
namespace {

enum class Kind { Sphere, Capsule, SphereDeep, CapsuleDeep, CapsuleAlongFace, CapsuleSizes, Count };

template <class T> struct Case {
  detail::RoundedCore<T> core;
  Transform<T> pose;  // the hull's
  T size;
};

template <class T> Case<T> makeCase(Kind kind, const ConvexMesh<T>& hull, Rng& rng) {
  Case<T> c{{{Vec3<T>::Zero(), Vec3<T>::Zero()}, T(0.3)}, rng.pose<T>(2.0), T(2)};
  const auto world = [&](const Vec3<T>& local) { return c.pose.transform(local); };
  const Vec3<T> centre = world(rng.unitVector<T>() * T(rng.uniform(0, 1.4)));
  const Vec3<T> axis = rng.unitVector<T>();
  switch (kind) {
    case Kind::Sphere:
      c.core = {{centre, centre}, T(rng.uniform(0.02, 0.6))};
      break;
    case Kind::Capsule: {
      const T half = T(rng.uniform(0.05, 1.0));
      c.core = {{centre - axis * half, centre + axis * half}, T(rng.uniform(0.02, 0.6))};
      break;
    }
    case Kind::SphereDeep: {
      const Vec3<T> inside = world(rng.inBox<T>(0.3));
      c.core = {{inside, inside}, T(rng.uniform(0.01, 0.3))};
      break;
    }
    case Kind::CapsuleDeep: {
      const Vec3<T> inside = world(rng.inBox<T>(0.25));
      const T half = T(rng.uniform(0.01, 0.3));
      c.core = {{inside - axis * half, inside + axis * half}, T(rng.uniform(0.01, 0.3))};
      break;
    }
    case Kind::CapsuleAlongFace: {
      // The core parallel to face f, over its first vertex, `height` off its plane (negative: below it).
      const std::size_t f = std::size_t(rng.uniform(0, double(hull.polygons.size())));
      const HullPolygon<T>& p = hull.polygons[f];
      const Vec3<T> along = p.normal.cross(rng.unitVector<T>()).normalized();
      const T height = T(rng.uniform(-0.05, 0.1));
      const Vec3<T> base = hull.vertices[hull.polygonVertices[p.indexBase]] + p.normal * height;
      const T half = T(rng.uniform(0.05, 0.8));
      c.core = {{world(base - along * half), world(base + along * half)}, T(rng.uniform(0.01, 0.2))};
      break;
    }
    case Kind::CapsuleSizes: {
      const T scale = T(std::pow(10.0, rng.uniform(-2, 2)));
      const T half = scale * T(rng.uniform(0.1, 1.0));
      const Vec3<T> at = world(rng.unitVector<T>() * T(rng.uniform(0, 1.2)));
      c.core = {{at - axis * half, at + axis * half}, scale * T(rng.uniform(0.01, 0.5))};
      c.size = T(2) + T(2) * scale;
      break;
    }
    case Kind::Count: break;
  }
  return c;
}

// The push-out of the rounded core along `n` out of the hull: max over the hull minus min over the core, plus r.
template <class T> T pushAlong(const Case<T>& c, const detail::Polytope<T>& hull, const Vec3<T>& n) {
  T hi = -std::numeric_limits<T>::max();
  for (const Vec3<T>& v : hull.vertices) hi = std::max(hi, v.dot(n));
  return hi - std::min(c.core.segment.a.dot(n), c.core.segment.b.dot(n)) + c.core.radius;
}

template <class T> void checkHullSize(int points, int pairs) {
  const double rel = Tol<T>::kRel;
  Rng rng(5000 + std::uint64_t(points));
  const std::shared_ptr<const ConvexMesh<T>> mesh = ellipsoidHull<T>(points, rng);
  const ConvexMeshGeometry<T> hull(mesh);
  detail::Polytope<T> posed;
  int penetrating = 0, apart = 0, failures = 0;
  for (int i = 0; i < pairs; ++i) {
    const Kind kind = Kind(i % int(Kind::Count));
    const Case<T> c = makeCase<T>(kind, *mesh, rng);
    bool hit = false;
    Vec3<T> direction;
    T depth = T(-1);
    const bool applies = detail::penetrationRoundedHull(c.core, hull, c.pose, hit, direction, depth);
    detail::buildConvexPolytope(hull, c.pose, posed);
    Vec3<T> refDirection;
    T refDepth = T(-1);
    const bool refHit = detail::penetrationRoundedPolytope(c.core, posed, refDirection, refDepth);
    penetrating += refHit;
    apart += !refHit;
    const T tol = T(rel) * std::abs(refDepth) + T(8) * std::numeric_limits<T>::epsilon() * c.size;
    bool ok = applies && hit == refHit;
    const T push = hit ? pushAlong(c, posed, direction) : T(0);
    if (ok && hit) ok = std::abs(depth - refDepth) <= tol && std::abs(push - refDepth) <= tol;
    if (!ok && ++failures <= 3)
      ADD_FAILURE() << points << " points, pair " << i << " (kind " << int(kind) << "): applies " << applies
                    << ", in the hull's frame " << hit << " depth " << depth << " push " << push << ", posed " << refHit
                    << " depth " << refDepth;
  }
  EXPECT_EQ(failures, 0) << points << " points";
  EXPECT_GT(penetrating, pairs / 3) << points << " points";
  EXPECT_GT(apart, pairs / 20) << points << " points";
}

template <class T> class RoundedHullPenetration : public ::testing::Test {};
TYPED_TEST_SUITE(RoundedHullPenetration, Scalars);

TYPED_TEST(RoundedHullPenetration, MatchesThePosedPolytopeOnSeededPairs) {
  checkHullSize<TypeParam>(30, 1002);
  checkHullSize<TypeParam>(100, 1002);
  // Float hulls of 300 points have sliver faces whose cooked float normals are good to ~1e-4 rad: the push-out along
  // such a face's normal (the answer, in either path) is off by ~2e-4 relative, beyond float's 1e-4.
  if (std::is_same<TypeParam, double>::value) checkHullSize<TypeParam>(300, 1002);
}

// A scaled hull is not taken in the hull's frame (its distances are not the mesh's): the posed path answers.
TYPED_TEST(RoundedHullPenetration, ScaledHullIsLeftToThePosedPath) {
  using T = TypeParam;
  Rng rng(77);
  const ConvexMeshGeometry<T> hull(ellipsoidHull<T>(30, rng), MeshScale<T>(Vec3<T>(T(2), T(1), T(1)), Quat<T>::Identity()));
  const detail::RoundedCore<T> core{{Vec3<T>::Zero(), Vec3<T>::Zero()}, T(0.5)};
  bool hit = false;
  Vec3<T> direction;
  T depth = T(-1);
  EXPECT_FALSE(detail::penetrationRoundedHull(core, hull, Transform<T>(), hit, direction, depth));
  EXPECT_EQ(depth, T(-1));
}

}  // namespace
}  // namespace gq::test
