// Plane (the solid half-space x <= 0 of its frame) against triangle meshes and heightfields: overlap and signed
// distance against the lowest used vertex found by brute force in long double, on seeded poses, scales and holes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <vector>

#include "gq/cooking.h"
#include "gq/query.h"

namespace {

using namespace gq;
using LD = long double;

template <class T> Transform<T> randomPose(std::mt19937_64& gen, double spread) {
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> u(-spread, spread);
  const double w = n(gen), qx = n(gen), qy = n(gen), qz = n(gen);
  const double x = u(gen), y = u(gen), z = u(gen);
  return Transform<T>(Vec3<T>(T(x), T(y), T(z)), Eigen::Quaterniond(w, qx, qy, qz).normalized().cast<T>());
}

// The plane's signed height of a world point, in long double: n . (x - p), n = the plane frame's +X.
template <class T> LD heightOver(const Transform<T>& plane, const Vec3<T>& x) {
  const Vec3<T> n = plane.rotate(Vec3<T>::UnitX());
  LD h = 0;
  for (int k = 0; k < 3; ++k) h += LD(n[k]) * (LD(x[k]) - LD(plane.p[k]));
  return h;
}

template <class T> struct PlaneSurface : ::testing::Test {
  // Relative to the coordinates' size (~5): the kernels' heights are one dot product and a sum.
  static constexpr double kTol = std::is_same_v<T, double> ? 1e-12 : 5e-5;
};
using Scalars = ::testing::Types<float, double>;

// ---- triangle mesh -------------------------------------------------------------------------------------------

// A random triangle soup over 40 vertices of which the last 10 are never used (they must not count).
template <class T> std::shared_ptr<const TriangleMesh<T>> randomSoup(std::mt19937_64& gen, std::set<std::uint32_t>& used) {
  std::normal_distribution<double> n;
  std::uniform_int_distribution<std::uint32_t> pick(0, 29);
  std::vector<Vec3<T>> v;
  for (int i = 0; i < 40; ++i) v.emplace_back(T(n(gen)), T(n(gen)), T(n(gen)));
  for (int i = 30; i < 40; ++i) v[i] *= T(10);  // far out, unused
  std::vector<TriangleIndices> t;
  while (t.size() < 25) {
    const std::uint32_t a = pick(gen), b = pick(gen), c = pick(gen);
    if (a != b && b != c && a != c) t.push_back({a, b, c});
  }
  for (const TriangleIndices& tri : t)
    for (std::uint32_t i : tri) used.insert(i);
  std::shared_ptr<const TriangleMesh<T>> mesh;
  EXPECT_TRUE(cookTriangleMesh<T>(v, t, mesh).ok());
  return mesh;
}

template <class T> struct Lowest {
  LD height;
  Vec3<T> point;
};

// The brute force shared by both surfaces: the point of `local` (surface frame) lowest over the plane, in world.
template <class T>
Lowest<T> lowestOver(const Transform<T>& plane, const Transform<T>& pose, const std::vector<Vec3<T>>& local) {
  Lowest<T> best{std::numeric_limits<LD>::infinity(), Vec3<T>::Zero()};
  for (const Vec3<T>& v : local) {
    const Vec3<T> x = pose.transform(v);
    const LD h = heightOver(plane, x);
    if (h < best.height) best = {h, x};
  }
  return best;
}

template <class T>
Lowest<T> bruteForceMesh(const TriangleMeshGeometry<T>& g, const std::set<std::uint32_t>& used, const Transform<T>& pose,
                         const Transform<T>& plane) {
  std::vector<Vec3<T>> local;
  for (std::uint32_t i : used) local.emplace_back(g.scale.toMatrix() * g.mesh->vertices[i]);
  return lowestOver(plane, pose, local);
}

template <class T> using OverlapPlaneTriangleMesh = PlaneSurface<T>;
template <class T> using DistancePlaneTriangleMesh = PlaneSurface<T>;
TYPED_TEST_SUITE(OverlapPlaneTriangleMesh, Scalars);
TYPED_TEST_SUITE(DistancePlaneTriangleMesh, Scalars);

TYPED_TEST(OverlapPlaneTriangleMesh, MeshBelowPlaneOverlapsAndMeshAboveDoesNot) {
  using T = TypeParam;
  // The triangle (1,0,0), (2,0,0), (1,1,0) lies above the half-space x <= 0 by 1 when untranslated.
  std::shared_ptr<const TriangleMesh<T>> m;
  ASSERT_TRUE(cookTriangleMesh<T>({Vec3<T>(1, 0, 0), Vec3<T>(2, 0, 0), Vec3<T>(1, 1, 0)}, {{0, 1, 2}}, m).ok());
  const Geometry<T> mesh = TriangleMeshGeometry<T>(m), plane = PlaneGeometry<T>();
  bool out = true;
  for (const T shift : {T(-0.999), T(-1), T(-1.001), T(-5)}) {
    const Transform<T> pose(Vec3<T>(shift, T(3), T(-2)));
    ASSERT_TRUE(overlap<T>(plane, Transform<T>(), mesh, pose, out).ok());
    EXPECT_EQ(out, shift <= T(-1)) << shift;  // touching at x = 0 counts
    ASSERT_TRUE(overlap<T>(mesh, pose, plane, Transform<T>(), out).ok());
    EXPECT_EQ(out, shift <= T(-1)) << shift;
  }
}

TYPED_TEST(OverlapPlaneTriangleMesh, AgreesWithTheLowestUsedVertexOnSeededPoses) {
  using T = TypeParam;
  std::mt19937_64 gen(41);
  int decided = 0;
  for (int i = 0; i < 300; ++i) {
    std::set<std::uint32_t> used;
    const auto m = randomSoup<T>(gen, used);
    ASSERT_TRUE(m);
    std::uniform_real_distribution<double> s(0.5, 2);
    const MeshScale<T> scale(Vec3<T>(T(s(gen)), T(s(gen)), T(s(gen))), randomPose<T>(gen, 0).q);
    const TriangleMeshGeometry<T> g(m, scale);
    const Transform<T> meshPose = randomPose<T>(gen, 3), planePose = randomPose<T>(gen, 3);
    const LD lowest = bruteForceMesh(g, used, meshPose, planePose).height;
    if (std::abs(double(lowest)) < 10 * this->kTol) continue;  // undecided within rounding
    ++decided;
    bool out = false;
    ASSERT_TRUE(overlap<T>(PlaneGeometry<T>(), planePose, g, meshPose, out).ok());
    EXPECT_EQ(out, lowest < 0) << i << " lowest " << double(lowest);
  }
  EXPECT_GT(decided, 250);
}

TYPED_TEST(DistancePlaneTriangleMesh, IsTheSignedHeightOfTheLowestVertexWithItsWitnesses) {
  using T = TypeParam;
  std::mt19937_64 gen(43);
  for (int i = 0; i < 300; ++i) {
    std::set<std::uint32_t> used;
    const auto m = randomSoup<T>(gen, used);
    ASSERT_TRUE(m);
    std::uniform_real_distribution<double> s(-2, 2);
    Vec3<T> sv(T(s(gen)), T(s(gen)), T(s(gen)));
    for (int k = 0; k < 3; ++k)
      if (std::abs(sv[k]) < T(0.25)) sv[k] = T(0.5);  // mirrored scales included, none near 0
    const TriangleMeshGeometry<T> g(m, MeshScale<T>(sv, randomPose<T>(gen, 0).q));
    const Transform<T> meshPose = randomPose<T>(gen, 3), planePose = randomPose<T>(gen, 3);
    const Lowest<T> expected = bruteForceMesh(g, used, meshPose, planePose);
    DistanceResult<T> d;
    ASSERT_TRUE(distance<T>(d, PlaneGeometry<T>(), planePose, g, meshPose).ok());
    EXPECT_NEAR(double(d.distance), double(expected.height), this->kTol) << i;
    const Vec3<T> n = planePose.rotate(Vec3<T>::UnitX());
    EXPECT_NEAR((d.normal - n).norm(), 0.0, this->kTol) << i;  // from the plane towards the mesh
    EXPECT_NEAR((d.point1 - expected.point).norm(), 0.0, 10 * this->kTol) << i;
    EXPECT_NEAR(double(heightOver(planePose, d.point0)), 0.0, 10 * this->kTol) << i;  // on the plane
    EXPECT_NEAR((d.point1 - d.point0 - d.distance * n).norm(), 0.0, 10 * this->kTol) << i;
    // Mesh first: the same distance, witnesses exchanged, normal reversed.
    DistanceResult<T> e;
    ASSERT_TRUE(distance<T>(e, g, meshPose, PlaneGeometry<T>(), planePose).ok());
    EXPECT_EQ(e.distance, d.distance);
    EXPECT_NEAR((e.point0 - d.point1).norm(), 0.0, 10 * this->kTol);
    EXPECT_NEAR((e.normal + d.normal).norm(), 0.0, this->kTol);
  }
}

TYPED_TEST(DistancePlaneTriangleMesh, NegativeByTheDepthOfTheDeepestVertex) {
  using T = TypeParam;
  std::shared_ptr<const TriangleMesh<T>> m;
  ASSERT_TRUE(cookTriangleMesh<T>({Vec3<T>(T(-0.25), 0, 0), Vec3<T>(2, 0, 0), Vec3<T>(1, 1, 0), Vec3<T>(T(-9), 0, 0)},
                                  {{0, 1, 2}}, m).ok());
  DistanceResult<T> d;
  ASSERT_TRUE(distance<T>(d, PlaneGeometry<T>(), Transform<T>(), TriangleMeshGeometry<T>(m), Transform<T>()).ok());
  EXPECT_EQ(d.distance, T(-0.25));  // vertex 3 (x = -9) belongs to no triangle
  EXPECT_EQ(d.normal, Vec3<T>(1, 0, 0));
  EXPECT_EQ(d.point1, Vec3<T>(T(-0.25), 0, 0));
  EXPECT_EQ(d.point0, Vec3<T>(0, 0, 0));
  bool out = false;
  ASSERT_TRUE(overlap<T>(PlaneGeometry<T>(), Transform<T>(Vec3<T>(T(-0.3), 0, 0)), TriangleMeshGeometry<T>(m),
                         Transform<T>(), out).ok());
  EXPECT_FALSE(out);
}

// ---- heightfield -----------------------------------------------------------------------------------------------

// 12 x 10 samples (11 x 9 cells: two blocks of cells each way), random heights, a fifth of the cells holes.
template <class T> HeightFieldDesc<T> randomField(std::mt19937_64& gen) {
  HeightFieldDesc<T> desc;
  desc.rows = 12;
  desc.columns = 10;
  std::normal_distribution<double> n;
  for (std::uint32_t i = 0; i < desc.rows * desc.columns; ++i) desc.heights.push_back(T(n(gen)));
  std::uniform_int_distribution<int> hole(0, 4);
  for (std::uint32_t c = 0; c < (desc.rows - 1) * (desc.columns - 1); ++c)
    if (hole(gen) == 0) desc.holes.push_back(c);
  return desc;
}

template <class T>
Lowest<T> bruteForceField(const HeightFieldDesc<T>& desc, const HeightFieldGeometry<T>& g, const Transform<T>& pose,
                          const Transform<T>& plane) {
  const std::set<std::uint32_t> holes(desc.holes.begin(), desc.holes.end());
  std::vector<Vec3<T>> local;  // the corners of every cell that is no hole
  for (std::uint32_t r = 0; r + 1 < desc.rows; ++r)
    for (std::uint32_t c = 0; c + 1 < desc.columns; ++c) {
      if (holes.count(r * (desc.columns - 1) + c)) continue;
      for (std::uint32_t k = 0; k < 4; ++k) {
        const std::uint32_t sr = r + (k >> 1), sc = c + (k & 1);
        local.emplace_back(T(sr) * g.rowScale, desc.heights[sr * desc.columns + sc] * g.heightScale,
                           T(sc) * g.columnScale);
      }
    }
  return lowestOver(plane, pose, local);
}

template <class T> using OverlapPlaneHeightField = PlaneSurface<T>;
template <class T> using DistancePlaneHeightField = PlaneSurface<T>;
TYPED_TEST_SUITE(OverlapPlaneHeightField, Scalars);
TYPED_TEST_SUITE(DistancePlaneHeightField, Scalars);

TYPED_TEST(OverlapPlaneHeightField, AgreesWithTheLowestSampleOfACellThatIsNoHole) {
  using T = TypeParam;
  std::mt19937_64 gen(47);
  int decided = 0, overlapping = 0;
  for (int i = 0; i < 300; ++i) {
    const HeightFieldDesc<T> desc = randomField<T>(gen);
    std::shared_ptr<const HeightField<T>> field;
    ASSERT_TRUE(cookHeightField(desc, field).ok());
    std::uniform_real_distribution<double> s(0.2, 0.6);
    const HeightFieldGeometry<T> g(field, T(s(gen)), T(s(gen)), T(s(gen)));
    const Transform<T> hfPose = randomPose<T>(gen, 2), planePose = randomPose<T>(gen, 4);
    const LD lowest = bruteForceField(desc, g, hfPose, planePose).height;
    if (std::abs(double(lowest)) < 10 * this->kTol) continue;
    ++decided;
    bool out = false;
    ASSERT_TRUE(overlap<T>(g, hfPose, PlaneGeometry<T>(), planePose, out).ok());
    EXPECT_EQ(out, lowest < 0) << i << " lowest " << double(lowest);
    overlapping += out;
  }
  EXPECT_GT(decided, 250);
  EXPECT_GT(overlapping, 30);
  EXPECT_LT(overlapping, decided - 30);
}

TYPED_TEST(DistancePlaneHeightField, IsTheSignedHeightOfTheLowestSampleWithItsWitnesses) {
  using T = TypeParam;
  std::mt19937_64 gen(53);
  for (int i = 0; i < 300; ++i) {
    const HeightFieldDesc<T> desc = randomField<T>(gen);
    std::shared_ptr<const HeightField<T>> field;
    ASSERT_TRUE(cookHeightField(desc, field).ok());
    std::uniform_real_distribution<double> s(0.2, 0.6);
    const HeightFieldGeometry<T> g(field, T(s(gen)), T(s(gen)), T(s(gen)));
    const Transform<T> hfPose = randomPose<T>(gen, 2), planePose = randomPose<T>(gen, 4);
    const Lowest<T> expected = bruteForceField(desc, g, hfPose, planePose);
    DistanceResult<T> d;
    ASSERT_TRUE(distance<T>(d, PlaneGeometry<T>(), planePose, g, hfPose).ok());
    EXPECT_NEAR(double(d.distance), double(expected.height), this->kTol) << i;
    EXPECT_NEAR((d.point1 - expected.point).norm(), 0.0, 10 * this->kTol) << i;
    EXPECT_NEAR(double(heightOver(planePose, d.point0)), 0.0, 10 * this->kTol) << i;
    DistanceResult<T> e;
    ASSERT_TRUE(distance<T>(e, g, hfPose, PlaneGeometry<T>(), planePose).ok());
    EXPECT_EQ(e.distance, d.distance);
    EXPECT_NEAR((e.normal + d.normal).norm(), 0.0, this->kTol);
  }
}

TYPED_TEST(DistancePlaneHeightField, AllHolesIsADegenerateSurfaceAndOverlapsNothing) {
  using T = TypeParam;
  HeightFieldDesc<T> desc;
  desc.rows = desc.columns = 3;
  desc.heights.assign(9, T(-1));
  desc.holes = {0, 1, 2, 3};
  std::shared_ptr<const HeightField<T>> field;
  ASSERT_TRUE(cookHeightField(desc, field).ok());
  const Geometry<T> hf = HeightFieldGeometry<T>(field, T(1), T(1), T(1));
  DistanceResult<T> d;
  d.distance = T(42);
  EXPECT_EQ(distance<T>(d, PlaneGeometry<T>(), Transform<T>(), hf, Transform<T>()).code, StatusCode::DegenerateMesh);
  EXPECT_EQ(d.distance, T(42));  // untouched
  bool out = true;
  ASSERT_TRUE(overlap<T>(PlaneGeometry<T>(), Transform<T>(), hf, Transform<T>(), out).ok());
  EXPECT_FALSE(out);
}

}  // namespace
