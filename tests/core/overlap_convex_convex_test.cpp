// Convex/convex overlap (overlap/convex_convex.cpp): the cooked inner and outer balls decide a pair only where the
// exact answer (SAT over the hulls' face normals and edge pairs, long double) agrees, with and without mesh scale,
// and they decide most random poses (the point of having them).
#include "gjk_test_shapes.h"

namespace {

using namespace gjktest;

template <class T> class ConvexConvexOverlap : public ::testing::Test {};
TYPED_TEST_SUITE(ConvexConvexOverlap, Scalars);

// The scaled hull's vertices and face triangles in world space, in long double.
template <class T> Polytope scaledHull(const gq::ConvexMeshGeometry<T>& g, const gq::Transform<T>& pose) {
  Polytope p;
  const PoseL t = toL(pose);
  const Eigen::Matrix<L, 3, 3> s = g.scale.toMatrix().template cast<L>();
  for (const auto& v : g.mesh->vertices) p.v.push_back(t.apply(s * toL(v)));
  for (const auto& poly : g.mesh->polygons)
    for (std::uint32_t k = 1; k + 1 < poly.indexCount; ++k)
      p.tris.push_back({int(g.mesh->polygonVertices[poly.indexBase]), int(g.mesh->polygonVertices[poly.indexBase + k]),
                        int(g.mesh->polygonVertices[poly.indexBase + k + 1])});
  addEdgesFromTriangles(p);
  return p;
}

TYPED_TEST(ConvexConvexOverlap, BallsDecideOnlyWhereTheExactSeparationAgrees) {
  using T = TypeParam;
  Rng rng(4242);
  const double band = std::is_same_v<T, float> ? 1e-3 : 1e-7;  // |exact separation| below this is not asserted
  int outerApart = 0, innerOverlapping = 0, checked = 0;
  for (int i = 0; i < 600; ++i) {
    std::shared_ptr<const gq::ConvexMesh<T>> m0, m1;
    ASSERT_TRUE(gq::cookConvexMesh(pointsOnEllipsoid<T>(rng, 12 + i % 20, rng.vec(0.2, 0.8)), m0).ok());
    ASSERT_TRUE(gq::cookConvexMesh(pointsOnEllipsoid<T>(rng, 12 + i % 17, rng.vec(0.2, 0.8)), m1).ok());
    gq::ConvexMeshGeometry<T> g0(m0), g1(m1);
    if (i % 2) g0.scale = randomScale<T>(rng, 0.5, 2.0);
    if (i % 3 == 0) g1.scale = gq::MeshScale<T>(T(rng.uniform(0.5, 2.0)));
    const double spread = i % 4 < 2 ? 0.3 : 1.0;  // near centres for the inner balls, far for the outer ones
    const gq::Transform<T> p0 = randomPose<T>(rng, spread), p1 = randomPose<T>(rng, spread);
    bool got = false;
    ASSERT_TRUE(gq::overlap(gq::Geometry<T>(g0), p0, gq::Geometry<T>(g1), p1, got).ok());
    // The balls' own verdict, recomputed here in long double (the library's is in T).
    const Eigen::Vector3d s0 = g0.scale.scale.template cast<double>().cwiseAbs();
    const Eigen::Vector3d s1 = g1.scale.scale.template cast<double>().cwiseAbs();
    const VL c0 = toL(p0).apply(g0.scale.toMatrix().template cast<L>() * toL(m0->center));
    const VL c1 = toL(p1).apply(g1.scale.toMatrix().template cast<L>() * toL(m1->center));
    const L d = (c1 - c0).norm();
    if (d > L(s0.maxCoeff() * m0->outerRadius + s1.maxCoeff() * m1->outerRadius) * L(1.001)) ++outerApart;
    if (d < L(s0.minCoeff() * m0->innerRadius + s1.minCoeff() * m1->innerRadius) * L(0.999)) ++innerOverlapping;
    const L depth = polytopePenetration(scaledHull(g0, p0), scaledHull(g1, p1));  // < 0: a separating axis
    if (std::abs(double(depth)) < band) continue;
    ++checked;
    ASSERT_EQ(got, depth > 0) << "pose " << i << ": exact SAT depth " << double(depth) << ", centres " << double(d)
                              << " apart, inner radii " << m0->innerRadius << " " << m1->innerRadius;
  }
  EXPECT_GT(checked, 590);
  EXPECT_GT(outerApart, 60) << "outer balls apart: GJK skipped";
  EXPECT_GT(innerOverlapping, 100) << "inner balls overlapping: GJK skipped";
}

// Cubes of half-size 1: inner radius 1 (faces), outer sqrt 3 (corners). Face to face the inner balls touch where
// the faces do; corner to corner along the diagonal the outer balls touch where the corners do. A gap of delta
// either way is answered exactly, whatever rotation about the line of centres.
TYPED_TEST(ConvexConvexOverlap, CubesFaceToFaceAndCornerToCornerAreExactAtTheBalls) {
  using T = TypeParam;
  std::vector<gq::Vec3<T>> corners;
  for (int i = 0; i < 8; ++i) corners.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  std::shared_ptr<const gq::ConvexMesh<T>> cube;
  ASSERT_TRUE(gq::cookConvexMesh(corners, cube).ok());
  const gq::Geometry<T> g{gq::ConvexMeshGeometry<T>(cube)};
  const T delta = std::is_same_v<T, float> ? T(1e-3) : T(1e-6);
  const gq::Vec3<T> diagonal = gq::Vec3<T>::Ones().normalized();
  Rng rng(7);
  for (int i = 0; i < 50; ++i) {
    const gq::Quat<T> spinX(Eigen::AngleAxis<T>(T(rng.uniform(0, 6.3)), gq::Vec3<T>::UnitX()));
    const gq::Quat<T> spinDiagonal(Eigen::AngleAxis<T>(T(2 * M_PI / 3) * T(i % 3), diagonal));  // the cube's symmetry
    for (const T gap : {-delta, delta}) {
      bool hit = true;
      ASSERT_TRUE(gq::overlap(g, gq::Transform<T>(), g, gq::Transform<T>(gq::Vec3<T>(2 + gap, 0, 0), spinX), hit).ok());
      EXPECT_EQ(hit, gap < 0) << "face to face, gap " << gap;
      // The second cube's corner (-1,-1,-1) faces the first's (1,1,1): centres 2 sqrt 3 + gap apart.
      const gq::Vec3<T> at = diagonal * (T(2) * std::sqrt(T(3)) + gap);
      ASSERT_TRUE(gq::overlap(g, gq::Transform<T>(), g, gq::Transform<T>(at, spinDiagonal), hit).ok());
      EXPECT_EQ(hit, gap < 0) << "corner to corner, gap " << gap;
    }
  }
}

}  // namespace
