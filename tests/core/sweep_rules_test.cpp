// Sweep rules of the spec, each a named test in float and double. Expected values are closed forms computed here.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "gq/cooking.h"
#include "gq/custom_shapes.h"
#include "gq/query.h"

namespace {

using namespace gq;

template <class T> struct SweepRules : ::testing::Test {
  static constexpr double kTol = std::is_same_v<T, double> ? 1e-9 : 1e-4;
  Vec3<T> x() const { return Vec3<T>::UnitX(); }
  SphereGeometry<T> unitSphere() const { return SphereGeometry<T>(T(1)); }
  Transform<T> at(double px, double py = 0, double pz = 0) const { return Transform<T>(Vec3<T>(T(px), T(py), T(pz))); }
  std::shared_ptr<const TriangleMesh<T>> quad() const {  // the square |y|,|z| <= 2 at x = 0, normal +X
    std::vector<Vec3<T>> v = {Vec3<T>(0, -2, -2), Vec3<T>(0, 2, -2), Vec3<T>(0, 2, 2), Vec3<T>(0, -2, 2)};
    std::vector<TriangleIndices> t = {{0, 1, 2}, {0, 2, 3}};
    std::shared_ptr<const TriangleMesh<T>> m;
    EXPECT_TRUE(cookTriangleMesh(v, t, m).ok());
    return m;
  }
};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(SweepRules, Scalars);

TYPED_TEST(SweepRules, SphereAgainstSphereHitsAtTheClosedFormDistance) {
  using T = TypeParam;
  SweepHit<T> hit;
  bool has = false;
  // Radii 1 and 0.5, centres 5 apart on X: contact after 5 - 1.5 = 3.5.
  ASSERT_TRUE(sweep(this->x(), T(10), Geometry<T>(this->unitSphere()), this->at(0), Geometry<T>(SphereGeometry<T>(T(0.5))),
                    this->at(5), hit, has).ok());
  ASSERT_TRUE(has);
  EXPECT_NEAR(double(hit.distance), 3.5, this->kTol);
  EXPECT_NEAR(double(hit.normal.x()), -1.0, this->kTol);
  EXPECT_NEAR(double(hit.position.x()), 4.5, this->kTol);
  EXPECT_EQ(hit.faceIndex, kInvalidFaceIndex);
  EXPECT_FALSE(hit.hadInitialOverlap());
}

TYPED_TEST(SweepRules, NonUnitDirectionIsRejectedAndWritesNothing) {
  using T = TypeParam;
  SweepHit<T> hit;
  hit.distance = T(42);
  bool has = true;
  const Status s = sweep(Vec3<T>(T(2), T(0), T(0)), T(1), Geometry<T>(this->unitSphere()), this->at(0),
                         Geometry<T>(this->unitSphere()), this->at(5), hit, has);
  EXPECT_EQ(s.code, StatusCode::InvalidArgument);
  EXPECT_EQ(hit.distance, T(42));
  EXPECT_TRUE(has);
}

TYPED_TEST(SweepRules, NegativeOrNaNMaxDistIsRejected) {
  using T = TypeParam;
  SweepHit<T> hit;
  bool has = false;
  const Geometry<T> s(this->unitSphere());
  EXPECT_EQ(sweep(this->x(), T(-1), s, this->at(0), s, this->at(5), hit, has).code, StatusCode::InvalidArgument);
  EXPECT_EQ(sweep(this->x(), std::numeric_limits<T>::quiet_NaN(), s, this->at(0), s, this->at(5), hit, has).code,
            StatusCode::InvalidArgument);
}

TYPED_TEST(SweepRules, MaxDistIsClampedToTheMaximumSweepDistance) {
  using T = TypeParam;
  SweepHit<T> hit;
  bool has = true;
  const Geometry<T> s(this->unitSphere());
  // A target beyond 1e8 is out of reach even with an infinite maxDist; one within it is hit.
  ASSERT_TRUE(sweep(this->x(), std::numeric_limits<T>::infinity(), s, this->at(0), s, this->at(3e8), hit, has).ok());
  EXPECT_FALSE(has);
  ASSERT_TRUE(sweep(this->x(), std::numeric_limits<T>::infinity(), s, this->at(0), s, this->at(5e7), hit, has).ok());
  EXPECT_TRUE(has);
}

TYPED_TEST(SweepRules, ZeroLengthSweepIsAnOverlapTest) {
  using T = TypeParam;
  SweepHit<T> hit;
  bool has = true;
  const Geometry<T> s(this->unitSphere());
  ASSERT_TRUE(sweep(this->x(), T(0), s, this->at(0), s, this->at(2.5), hit, has).ok());
  EXPECT_FALSE(has);
  ASSERT_TRUE(sweep(this->x(), T(0), s, this->at(0), s, this->at(1.5), hit, has).ok());
  ASSERT_TRUE(has);
  EXPECT_TRUE(hit.hadInitialOverlap());
}

TYPED_TEST(SweepRules, InitialOverlapWithoutMtdReportsZeroDistanceAndMinusDirNoPosition) {
  using T = TypeParam;
  SweepHit<T> hit;
  bool has = false;
  const Geometry<T> b(BoxGeometry<T>(T(1), T(1), T(1)));
  ASSERT_TRUE(sweep(this->x(), T(5), b, this->at(0), b, this->at(1.5), hit, has).ok());
  ASSERT_TRUE(has);
  EXPECT_TRUE(hit.hadInitialOverlap());
  EXPECT_EQ(hit.distance, T(0));
  EXPECT_TRUE(hit.flags.has(HitFlag::Normal));
  EXPECT_FALSE(hit.flags.has(HitFlag::Position));
  EXPECT_NEAR(double(hit.normal.x()), -1.0, this->kTol);
  EXPECT_EQ(hit.faceIndex, kInvalidFaceIndex);
}

TYPED_TEST(SweepRules, InitialOverlapWithMtdReportsNegativeDepthAndDepenetrationDirection) {
  using T = TypeParam;
  SweepHit<T> hit;
  bool has = false;
  // Unit spheres 1.5 apart along Y, sweeping along X: depth 0.5, depenetration -Y for the swept one.
  const Geometry<T> s(this->unitSphere());
  ASSERT_TRUE(sweep(this->x(), T(5), s, this->at(0, 0), s, this->at(0, 1.5), hit, has,
                    kDefaultHitFlags | HitFlag::Mtd).ok());
  ASSERT_TRUE(has);
  EXPECT_TRUE(hit.hadInitialOverlap());
  EXPECT_NEAR(double(hit.distance), -0.5, this->kTol);
  EXPECT_NEAR(double(hit.normal.y()), -1.0, this->kTol);
  EXPECT_TRUE(hit.flags.has(HitFlag::Position));
  EXPECT_NEAR(double(hit.position.y()), 1.0, this->kTol);  // on the swept sphere, deepest inside the target
}

TYPED_TEST(SweepRules, MtdWithPreciseSweepOrAssumeNoInitialOverlapWarnsAndIgnoresThem) {
  using T = TypeParam;
  SweepHit<T> hit;
  bool has = false;
  const Geometry<T> s(this->unitSphere());
  const Status st = sweep(this->x(), T(5), s, this->at(0), s, this->at(1.5), hit, has,
                          kDefaultHitFlags | HitFlag::Mtd | HitFlag::AssumeNoInitialOverlap);
  EXPECT_EQ(st.code, StatusCode::Warning);
  ASSERT_TRUE(has);
  EXPECT_TRUE(hit.hadInitialOverlap());  // the overlap test still ran
  EXPECT_NEAR(double(hit.distance), -0.5, this->kTol);
  EXPECT_EQ(sweep(this->x(), T(5), s, this->at(0), s, this->at(1.5), hit, has,
                  kDefaultHitFlags | HitFlag::Mtd | HitFlag::PreciseSweep).code, StatusCode::Warning);
}

TYPED_TEST(SweepRules, PreciseSweepWithInflationWarns) {
  using T = TypeParam;
  SweepHit<T> hit;
  bool has = false;
  const Geometry<T> s(this->unitSphere());
  const Status st = sweep(this->x(), T(10), s, this->at(0), s, this->at(5), hit, has,
                          kDefaultHitFlags | HitFlag::PreciseSweep, T(0.25));
  EXPECT_EQ(st.code, StatusCode::Warning);
  ASSERT_TRUE(has);
  EXPECT_NEAR(double(hit.distance), 2.75, this->kTol);
}

TYPED_TEST(SweepRules, InflationGrowsTheSweptShapeByARoundedShell) {
  using T = TypeParam;
  SweepHit<T> hit;
  bool has = false;
  // A unit box inflated by 0.5 reaching a sphere of radius 0.5 diagonally past its corner: the rounded corner
  // (a quarter sphere of radius 0.5 around the corner (1,1,0)) decides. Target centre (4, 1 + 1/sqrt2, 0) ... use the
  // face case: contact after 5 - 1 - 0.5 - 0.5 = 3.
  const Geometry<T> b(BoxGeometry<T>(T(1), T(1), T(1)));
  ASSERT_TRUE(sweep(this->x(), T(10), b, this->at(0), Geometry<T>(SphereGeometry<T>(T(0.5))), this->at(5), hit, has,
                    kDefaultHitFlags, T(0.5)).ok());
  ASSERT_TRUE(has);
  EXPECT_NEAR(double(hit.distance), 3.0, 1e3 * this->kTol);
  // Corner: target sphere at (5, 2.2, 0): the shell around edge x=1,y=1 meets it when |(c - (1+t, 1))| = 1.
  ASSERT_TRUE(sweep(this->x(), T(10), b, this->at(0), Geometry<T>(SphereGeometry<T>(T(0.5))), this->at(5, 1.6), hit,
                    has, kDefaultHitFlags, T(0.5)).ok());
  ASSERT_TRUE(has);
  const double expected = 5 - 1 - std::sqrt(1.0 - 0.6 * 0.6);
  EXPECT_NEAR(double(hit.distance), expected, 1e3 * this->kTol);
}

TYPED_TEST(SweepRules, PlaneIsASolidHalfSpace) {
  using T = TypeParam;
  SweepHit<T> hit;
  bool has = false;
  const Geometry<T> plane{PlaneGeometry<T>()};
  const Geometry<T> cap(CapsuleGeometry<T>(T(0.5), T(1)));
  // Capsule along X starting at x = 4 sweeping -X onto the plane x = 0: lowest point x = 4 - 1.5.
  ASSERT_TRUE(sweep(Vec3<T>(-this->x()), T(10), cap, this->at(4), plane, Transform<T>(), hit, has).ok());
  ASSERT_TRUE(has);
  EXPECT_NEAR(double(hit.distance), 2.5, this->kTol);
  EXPECT_NEAR(double(hit.normal.x()), 1.0, this->kTol);
  // Starting entirely behind the plane is an initial overlap, even far from the surface.
  ASSERT_TRUE(sweep(Vec3<T>(-this->x()), T(10), cap, this->at(-40), plane, Transform<T>(), hit, has).ok());
  ASSERT_TRUE(has);
  EXPECT_TRUE(hit.hadInitialOverlap());
  // Moving away from the plane misses.
  ASSERT_TRUE(sweep(this->x(), T(10), cap, this->at(4), plane, Transform<T>(), hit, has).ok());
  EXPECT_FALSE(has);
}

TYPED_TEST(SweepRules, MeshBackFacesAreCulledUnlessDoubleSidedOrMeshBothSides) {
  using T = TypeParam;
  SweepHit<T> hit;
  bool has = false;
  const Geometry<T> s(SphereGeometry<T>(T(0.5)));
  const TriangleMeshGeometry<T> single(this->quad());
  // From the back (x < 0) moving +X: the face normal is +X, along the sweep: culled.
  ASSERT_TRUE(sweep(this->x(), T(10), s, this->at(-3), Geometry<T>(single), Transform<T>(), hit, has).ok());
  EXPECT_FALSE(has);
  ASSERT_TRUE(sweep(this->x(), T(10), s, this->at(-3), Geometry<T>(single), Transform<T>(), hit, has,
                    kDefaultHitFlags | HitFlag::MeshBothSides).ok());
  ASSERT_TRUE(has);
  EXPECT_NEAR(double(hit.distance), 2.5, this->kTol);
  EXPECT_LT(double(hit.normal.dot(this->x())), 0.0);
  const TriangleMeshGeometry<T> both(this->quad(), MeshScale<T>(), MeshGeometryFlag::DoubleSided);
  ASSERT_TRUE(sweep(this->x(), T(10), s, this->at(-3), Geometry<T>(both), Transform<T>(), hit, has).ok());
  ASSERT_TRUE(has);
  EXPECT_NEAR(double(hit.distance), 2.5, this->kTol);
  EXPECT_NEAR(double(hit.normal.x()), -1.0, this->kTol);
  EXPECT_LT(hit.faceIndex, 2u);
  // From the front (x > 0) moving -X: hit on the front face.
  ASSERT_TRUE(sweep(Vec3<T>(-this->x()), T(10), s, this->at(3, 0.3, 0.1), Geometry<T>(single), Transform<T>(), hit, has).ok());
  ASSERT_TRUE(has);
  EXPECT_NEAR(double(hit.distance), 2.5, this->kTol);
  EXPECT_NEAR(double(hit.normal.x()), 1.0, this->kTol);
}

TYPED_TEST(SweepRules, MeshMultipleIsRejected) {
  using T = TypeParam;
  SweepHit<T> hit;
  bool has = false;
  const Geometry<T> s(this->unitSphere());
  EXPECT_EQ(sweep(this->x(), T(10), s, this->at(-3), Geometry<T>(TriangleMeshGeometry<T>(this->quad())), Transform<T>(),
                  hit, has, kDefaultHitFlags | HitFlag::MeshMultiple).code, StatusCode::InvalidArgument);
}

TYPED_TEST(SweepRules, OnlySphereCapsuleBoxAndConvexCanBeSwept) {
  using T = TypeParam;
  SweepHit<T> hit;
  bool has = false;
  EXPECT_EQ(sweep(this->x(), T(10), Geometry<T>(PlaneGeometry<T>()), Transform<T>(), Geometry<T>(this->unitSphere()),
                  this->at(5), hit, has).code, StatusCode::Unsupported);
}

TYPED_TEST(SweepRules, EqualDistanceMeshHitsPreferTheTriangleFacingTheSweepMost) {
  using T = TypeParam;
  // Two triangles touched at the same distance: a wall facing -X exactly (index 0) and a tilted one (index 1) whose
  // nearest point is at the same x. The wall faces the sweep most.
  std::vector<Vec3<T>> v = {Vec3<T>(2, -1, -1), Vec3<T>(2, 1, 0), Vec3<T>(2, -1, 1),
                            Vec3<T>(2, 0, 3), Vec3<T>(3, 1, 4), Vec3<T>(3, -1, 4)};
  std::vector<TriangleIndices> t = {{0, 1, 2}, {3, 4, 5}};
  std::shared_ptr<const TriangleMesh<T>> m;
  ASSERT_TRUE(cookTriangleMesh(v, t, m).ok());
  SweepHit<T> hit;
  bool has = false;
  const Geometry<T> b(BoxGeometry<T>(T(0.5), T(5), T(5)));
  ASSERT_TRUE(sweep(this->x(), T(10), b, Transform<T>(), Geometry<T>(TriangleMeshGeometry<T>(m, MeshScale<T>(),
                    MeshGeometryFlag::DoubleSided)), Transform<T>(), hit, has).ok());
  ASSERT_TRUE(has);
  EXPECT_NEAR(double(hit.distance), 1.5, 1e3 * this->kTol);
  EXPECT_EQ(hit.faceIndex, 0u);
}

TYPED_TEST(SweepRules, ConvexHitReportsThePolygonIndex) {
  using T = TypeParam;
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 8; ++i) pts.emplace_back((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
  std::shared_ptr<const ConvexMesh<T>> cube;
  ASSERT_TRUE(cookConvexMesh(pts, cube).ok());
  SweepHit<T> hit;
  bool has = false;
  ASSERT_TRUE(sweep(this->x(), T(10), Geometry<T>(SphereGeometry<T>(T(0.5))), this->at(-4, 0.2, 0.1),
                    Geometry<T>(ConvexMeshGeometry<T>(cube)), Transform<T>(), hit, has).ok());
  ASSERT_TRUE(has);
  EXPECT_NEAR(double(hit.distance), 2.5, this->kTol);
  ASSERT_LT(hit.faceIndex, cube->polygons.size());
  EXPECT_NEAR(double(cube->polygons[hit.faceIndex].normal.x()), -1.0, 1e-4);
}

TYPED_TEST(SweepRules, CustomCylinderIsSweptThroughItsSupportMapping) {
  using T = TypeParam;
  CustomGeometry<T> cyl;
  ASSERT_TRUE(makeCylinder(T(1), T(2), cyl).ok());
  SweepHit<T> hit;
  bool has = false;
  // Sphere r = 0.5 moving -Y onto the side of the cylinder (axis X, radius 1): contact after 5 - 1.5.
  ASSERT_TRUE(sweep(Vec3<T>(0, -1, 0), T(10), Geometry<T>(SphereGeometry<T>(T(0.5))), this->at(0.5, 5),
                    Geometry<T>(cyl), Transform<T>(), hit, has).ok());
  ASSERT_TRUE(has);
  EXPECT_NEAR(double(hit.distance), 3.5, 1e3 * this->kTol);
  EXPECT_NEAR(double(hit.normal.y()), 1.0, 1e-3);
}

}  // namespace
