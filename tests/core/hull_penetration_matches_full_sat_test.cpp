// Hull-hull and box-hull penetration (the Gauss-map tree search of penetration/hull_pair_mtd.h, and the posed search
// of penetration/polytope_mtd.h for hulls scaled non-uniformly) equals the full SAT over every face normal and every
// crossing edge pair (satMinimumOverlap) on the same posed polytopes: depth within
// 1e-9 (double) / 1e-4 (float) relative (plus 8 ulps of the pair's size, the rounding of its coordinates), the
// direction realising that depth (the push-out along it, from full vertex projections, is the depth), and the same
// separated/penetrating answer. 1000 seeded pairs per hull size
// (30, 100, 300 points on an ellipsoid) and scalar, a sixth of each kind:
//  - random poses of two hulls (edge-edge and face minima, about two thirds penetrating);
//  - a box and a hull in random poses;
//  - a face of one hull anti-parallel to a face of the other (exactly, or tilted by 1e-9 .. 1e-4 rad), slightly
//    overlapping: coplanar and near-parallel faces;
//  - a hull shrunk 3x .. 20x well inside the other (deep containment);
//  - size ratio 1e4 (scales 100 and 0.01) at the large hull's surface, either shape first;
//  - both hulls stretched along random axes (0.3 .. 3).
// The shares of searches run over the trees and answered by the full SAT (no usable Gauss map) are printed and
// checked. The 300-point hulls run in the Large suite (label `long`: the full SAT reference takes most of its time).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <memory>
#include <vector>

#include "gq/cooking.h"
#include "overlap/polytope.h"
#include "penetration/penetration.h"
#include "penetration/polytope_mtd.h"
#include "random_hulls.h"
#include "test_util.h"

namespace gq::test {
namespace {

using detail::Polytope;

enum class Kind { RandomHulls, BoxHull, ParallelFaces, Containment, SizeRatio, Stretched, Count };

template <class T> struct Case {
  Geometry<T> g0, g1;
  Transform<T> p0, p1;
  T size;  // the larger shape's extent
};

// The world outward normal and a point of polygon `f` of an unscaled hull at `pose`.
template <class T> Vec3<T> faceNormal(const ConvexMesh<T>& m, std::size_t f, const Transform<T>& pose) {
  return pose.rotate(m.polygons[f].normal);
}
template <class T> Vec3<T> facePoint(const ConvexMesh<T>& m, std::size_t f, const Transform<T>& pose) {
  return pose.transform(m.vertices[m.polygonVertices[m.polygons[f].indexBase]]);
}

template <class T>
Case<T> makeCase(Kind kind, const std::shared_ptr<const ConvexMesh<T>>& h0, const std::shared_ptr<const ConvexMesh<T>>& h1,
                 Rng& rng) {
  Case<T> c{ConvexMeshGeometry<T>(h0), ConvexMeshGeometry<T>(h1), rng.pose<T>(2.0), Transform<T>(), T(1)};
  const auto around = [&](const Transform<T>& base, double reach) {
    return Transform<T>(Vec3<T>(base.p + rng.unitVector<T>() * T(rng.uniform(0, reach))), rng.rotation<T>());
  };
  switch (kind) {
    case Kind::RandomHulls: c.p1 = around(c.p0, 2.0); break;
    case Kind::BoxHull:
      c.g0 = BoxGeometry<T>(rng.vec<T>(0.2, 1.0));
      c.p1 = around(c.p0, 2.0);
      break;
    case Kind::ParallelFaces: {
      // Hull 1's face g turned against hull 0's face f (then tilted), its plane `overlap` inside f's plane, its
      // first vertex over f's first vertex plus a small slide.
      const std::size_t f = std::size_t(rng.uniform(0, double(h0->polygons.size())));
      const std::size_t g = std::size_t(rng.uniform(0, double(h1->polygons.size())));
      const Vec3<T> nf = faceNormal(*h0, f, c.p0);
      const double tilt = rng.chance(0.5) ? 0.0 : std::pow(10.0, rng.uniform(-9, -4));
      const Vec3<T> axis = nf.cross(rng.unitVector<T>()).normalized();
      const Vec3<T> target = Eigen::AngleAxis<T>(T(tilt), axis) * Vec3<T>(-nf);
      const Quat<T> turn = Quat<T>::FromTwoVectors(h1->polygons[g].normal, target);
      c.p1 = Transform<T>(Vec3<T>::Zero(), turn.normalized());
      const Vec3<T> anchor = facePoint(*h0, f, c.p0) - nf * T(rng.uniform(0, 0.05)) +
                             (rng.inBox<T>(0.1) - nf * nf.dot(rng.inBox<T>(0.1)));
      c.p1.p = anchor - facePoint(*h1, g, c.p1);
      break;
    }
    case Kind::Containment: {
      const T shrink = T(1) / T(rng.uniform(3, 20));
      c.g1 = ConvexMeshGeometry<T>(h1, MeshScale<T>(Vec3<T>::Constant(shrink), Quat<T>::Identity()));
      c.p1 = around(c.p0, 0.3);
      break;
    }
    case Kind::SizeRatio: {
      c.g0 = ConvexMeshGeometry<T>(h0, MeshScale<T>(Vec3<T>::Constant(T(100)), Quat<T>::Identity()));
      c.g1 = ConvexMeshGeometry<T>(h1, MeshScale<T>(Vec3<T>::Constant(T(0.01)), Quat<T>::Identity()));
      const Vec3<T> surface = c.p0.transform(Vec3<T>(h0->vertices[std::size_t(rng.uniform(0, double(h0->vertices.size())))] * T(100)));
      c.p1 = around(Transform<T>(surface, Quat<T>::Identity()), 0.012);
      c.size = T(100);
      if (rng.chance(0.5)) std::swap(c.g0, c.g1), std::swap(c.p0, c.p1);
      break;
    }
    case Kind::Stretched:
      c.g0 = ConvexMeshGeometry<T>(h0, rng.meshScale<T>(0.3, 3.0));
      c.g1 = ConvexMeshGeometry<T>(h1, rng.meshScale<T>(0.3, 3.0));
      c.p1 = around(c.p0, 3.0);
      c.size = T(3);
      break;
    case Kind::Count: break;
  }
  return c;
}

template <class T> void buildPolytope(const Geometry<T>& g, const Transform<T>& pose, Polytope<T>& out) {
  if (const auto* box = g.template getIf<BoxGeometry<T>>()) return detail::buildBoxPolytope(*box, pose, out);
  detail::buildConvexPolytope(g.template get<ConvexMeshGeometry<T>>(), pose, out);
}

template <class T> bool kernel(const Case<T>& c, Vec3<T>& direction, T& depth) {
  if (const auto* box = c.g0.template getIf<BoxGeometry<T>>())
    return detail::penetrationBoxConvex(*box, c.p0, c.g1.template get<ConvexMeshGeometry<T>>(), c.p1, direction, depth);
  return detail::penetrationConvexConvex(c.g0.template get<ConvexMeshGeometry<T>>(), c.p0,
                                         c.g1.template get<ConvexMeshGeometry<T>>(), c.p1, direction, depth);
}

// `pairs` seeded pairs of `points`-point hulls: every answer checked, the full SAT's share printed and bounded.
template <class T> void checkHullSize(int points, int pairs) {
  const double rel = Tol<T>::kRel;
  Polytope<T> a, b;
  Rng rng(4000 + std::uint64_t(points));
  const std::vector<std::shared_ptr<const ConvexMesh<T>>> hulls = {ellipsoidHull<T>(points, rng), ellipsoidHull<T>(points, rng)};
  const detail::PolytopeMtdCounts before = detail::polytopeMtdCounts();
  int penetrating = 0, failures = 0;
  for (int i = 0; i < pairs; ++i) {
    const Kind kind = Kind(i % int(Kind::Count));
    const Case<T> c = makeCase<T>(kind, hulls[std::size_t(i) % 2], hulls[std::size_t(i / 2) % 2], rng);
    Vec3<T> direction;
    T depth = T(-1);
    const bool hit = kernel(c, direction, depth);
    buildPolytope(c.g0, c.p0, a);
    buildPolytope(c.g1, c.p1, b);
    const detail::SatResult<T> sat = detail::satMinimumOverlap(a, b, false);
    const bool satHit = sat.depth >= T(0);
    penetrating += satHit;
    // Relative to the depth, plus the rounding of projections at the pair's coordinates (a float pair at 100 and
    // 0.01 rounds its projections to ~1e-5 whatever the depth).
    const T tol = T(rel) * sat.depth + T(8) * std::numeric_limits<T>::epsilon() * c.size;
    bool ok = hit == satHit;
    // Pushing a out along the answer: max over b minus min over a of the projections on it.
    const T push = hit ? -detail::minProjection(b, Vec3<T>(-direction)) - detail::minProjection(a, direction) : T(0);
    if (ok && hit) ok = std::abs(depth - sat.depth) <= tol && std::abs(push - sat.depth) <= tol;
    if (!ok && ++failures <= 3)
      ADD_FAILURE() << points << " points, pair " << i << " (kind " << int(kind) << "): certified " << hit << " depth "
                    << depth << " push " << push << ", full SAT " << satHit << " depth " << sat.depth;
  }
  EXPECT_EQ(failures, 0) << points << " points";
  EXPECT_GT(penetrating, pairs / 2) << points << " points";
  const detail::PolytopeMtdCounts& after = detail::polytopeMtdCounts();
  const std::uint64_t searches = after.searches - before.searches, fullSat = after.fullSat - before.fullSat;
  const std::uint64_t inFrame = after.inFrame - before.inFrame;
  std::printf("%d points: %llu searches, %llu in geom0's frame, %llu answered by the full SAT\n", points,
              (unsigned long long)searches, (unsigned long long)inFrame, (unsigned long long)fullSat);
  EXPECT_EQ(searches, std::uint64_t(pairs)) << points << " points";
  EXPECT_LE(fullSat, searches / 100) << points << " points";
  // Every kind but the stretched hulls (scaled non-uniformly: posed) is searched in geom0's frame.
  EXPECT_EQ(inFrame, searches - searches / std::uint64_t(Kind::Count)) << points << " points";
}

template <class T> class HullPenetrationMatchesFullSat : public ::testing::Test {};
TYPED_TEST_SUITE(HullPenetrationMatchesFullSat, Scalars);

// 167 pairs of each kind at 30 and 100 points; the 300-point run (the full SAT reference costs milliseconds a pair)
// is the Large suite's.
TYPED_TEST(HullPenetrationMatchesFullSat, OnSeededPairsOfSmallHulls) {
  checkHullSize<TypeParam>(30, 1002);
  checkHullSize<TypeParam>(100, 1002);
}

template <class T> class HullPenetrationMatchesFullSatLarge : public ::testing::Test {};
TYPED_TEST_SUITE(HullPenetrationMatchesFullSatLarge, Scalars);

TYPED_TEST(HullPenetrationMatchesFullSatLarge, OnSeededPairsOf300PointHulls) { checkHullSize<TypeParam>(300, 1002); }

}  // namespace
}  // namespace gq::test
