// Sweeps against heightfields and triangle meshes (anyHit), float and double, against the exact time of impact: the
// first root of the exact long-double distance to each triangle, found by bisection (sweep_reference.h), minimised
// over the triangles. The terrain is built here from the documented sample layout (gq/cooking.h: sample (r, c) at
// (r rowScale, h heightScale, c columnScale), cell triangles (v00, v01, v10) and (v01, v11, v10), facing +Y), and
// swept from above along directions within 24 degrees of -Y, so every triangle faces the sweep (none is culled).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "gq/cooking.h"
#include "gq/query.h"
#include "sweep_reference.h"
#include "test_util.h"

namespace {

using namespace gq;
using sweeptest::Core;
using sweeptest::L;
using sweeptest::VL;

template <class T> constexpr double kToiTol = std::is_same_v<T, double> ? 1e-7 : 2e-4;
// A distance error e moves the contact time by e / |dot(normal, dir)|: grazing contacts (a triangle met edge-on
// behind the first contact, as anyHit may report) are ill-conditioned. In float, e is about 5e-5 on these
// coordinates (|x| <= 6); double stays within kToiTol.
template <class T> double toiTol(double closing) {
  return std::is_same_v<T, double> ? kToiTol<T> : std::max(kToiTol<T>, 5e-5 / std::max(std::abs(closing), 1e-3));
}
constexpr std::uint32_t kSamples = 6;  // per side
constexpr double kSpacing = 0.5, kMaxHeight = 0.3, kMaxDist = 4;

template <class T> struct SweepSurfaces : ::testing::Test {
  gq::test::Rng rng{701};
  std::vector<T> heights;
  std::shared_ptr<const HeightField<T>> field;
  std::shared_ptr<const TriangleMesh<T>> mesh;
  std::vector<std::array<VL, 3>> localTriangles;  // terrain triangles in its local frame, in face-index order

  void SetUp() override {
    HeightFieldDesc<T> desc;
    desc.rows = desc.columns = kSamples;
    for (std::uint32_t i = 0; i < kSamples * kSamples; ++i) desc.heights.push_back(T(rng.uniform(0, kMaxHeight)));
    heights = desc.heights;
    ASSERT_TRUE(cookHeightField(desc, field).ok());
    std::vector<Vec3<T>> vertices;
    for (std::uint32_t r = 0; r < kSamples; ++r)
      for (std::uint32_t c = 0; c < kSamples; ++c)
        vertices.emplace_back(T(r * kSpacing), heights[r * kSamples + c], T(c * kSpacing));
    std::vector<TriangleIndices> tris;
    for (std::uint32_t r = 0; r + 1 < kSamples; ++r)
      for (std::uint32_t c = 0; c + 1 < kSamples; ++c) {
        const std::uint32_t v00 = r * kSamples + c, v01 = v00 + 1, v10 = v00 + kSamples, v11 = v10 + 1;
        tris.push_back({v00, v01, v10});
        tris.push_back({v01, v11, v10});
      }
    for (const TriangleIndices& t : tris)
      localTriangles.push_back({sweeptest::toL(vertices[t[0]]), sweeptest::toL(vertices[t[1]]), sweeptest::toL(vertices[t[2]])});
    ASSERT_TRUE(cookTriangleMesh(vertices, tris, mesh).ok());
  }

  Geometry<T> heightField() const { return HeightFieldGeometry<T>(field, T(1), T(kSpacing), T(kSpacing)); }
  Geometry<T> triangleMesh() const { return TriangleMeshGeometry<T>(mesh); }

  std::vector<Geometry<T>> sweptShapes() {
    std::vector<Vec3<T>> points;
    for (int i = 0; i < 12; ++i) {
      const Vec3<T> dir = rng.unitVector<T>();
      points.push_back(dir * T(rng.uniform(0.15, 0.25)));
    }
    std::shared_ptr<const ConvexMesh<T>> hull;
    EXPECT_TRUE(cookConvexMesh(points, hull).ok());
    return {SphereGeometry<T>(T(0.2)), CapsuleGeometry<T>(T(0.15), T(0.25)), BoxGeometry<T>(T(0.2), T(0.15), T(0.1)),
            ConvexMeshGeometry<T>(hull)};
  }

  // Exact TOI against every triangle (world), with the triangle index of the first contact; -1 on a miss.
  // Triangles farther from the swept centre's path than the two bounding radii cannot be touched: skipped.
  static std::pair<L, int> exactToi(const Core& swept, const std::vector<Core>& tris, const VL& dir) {
    VL centre = VL::Zero();
    for (const VL& v : swept.v) centre += v / L(swept.v.size());
    L reach = 0;
    for (const VL& v : swept.v) reach = std::max(reach, (v - centre).norm());
    reach += swept.margin;
    std::pair<L, int> best{-1, -1};
    for (std::size_t i = 0; i < tris.size(); ++i) {
      const VL triCentre = (tris[i].v[0] + tris[i].v[1] + tris[i].v[2]) / L(3);
      L triReach = 0;
      for (const VL& v : tris[i].v) triReach = std::max(triReach, (v - triCentre).norm());
      if (sweeptest::pointSegment(triCentre, centre, centre + L(kMaxDist) * dir) > reach + triReach) continue;
      const L t = sweeptest::exactToi(swept, tris[i], dir, L(kMaxDist), L(kToiTol<T>) / 16);
      if (t >= 0 && (best.second < 0 || t < best.first)) best = {t, int(i)};
    }
    return best;
  }

  // A random terrain pose, a swept-shape pose above the interior and a direction within 24 degrees of local -Y.
  struct Case {
    Transform<T> terrain, start;
    Vec3<T> dir;
  };
  Case randomCase() {
    Case c;
    c.terrain = rng.pose<T>(3);
    const double x = rng.uniform(0.8, 1.7), y = rng.uniform(1.0, 2.0), z = rng.uniform(0.8, 1.7);
    const Vec3<T> local{T(x), T(y), T(z)};
    c.start = Transform<T>(c.terrain.transform(local), rng.rotation<T>());
    const double dx = rng.uniform(-0.4, 0.4), dz = rng.uniform(-0.4, 0.4);
    c.dir = c.terrain.rotate(Vec3<T>(T(dx), T(-1), T(dz)).normalized());
    return c;
  }
  std::vector<Core> worldTriangles(const Transform<T>& terrain) const {
    std::vector<Core> out;
    for (const auto& t : localTriangles)
      out.push_back(sweeptest::triangleCore(sweeptest::applyL(terrain, t[0]), sweeptest::applyL(terrain, t[1]),
                                            sweeptest::applyL(terrain, t[2])));
    return out;
  }
};
TYPED_TEST_SUITE(SweepSurfaces, gq::test::Scalars);

TYPED_TEST(SweepSurfaces, HeightFieldHitIsAtTheExactTimeOfImpactWithItsTriangleIndex) {
  using T = TypeParam;
  int hits = 0;
  for (const Geometry<T>& shape : this->sweptShapes())
    for (int i = 0; i < 10; ++i) {
      const auto c = this->randomCase();
      const std::vector<Core> tris = this->worldTriangles(c.terrain);
      const Core swept = sweeptest::coreOf(shape, c.start);
      const VL dir = sweeptest::toL(c.dir).normalized();
      const auto [exact, index] = this->exactToi(swept, tris, dir);
      SweepHit<T> hit;
      bool hasHit = false;
      ASSERT_TRUE(sweep(c.dir, T(kMaxDist), shape, c.start, this->heightField(), c.terrain, hit, hasHit).ok());
      ASSERT_EQ(hasHit, index >= 0) << "shape " << int(shape.type()) << " case " << i;
      if (!hasHit) continue;
      ++hits;
      EXPECT_FALSE(hit.hadInitialOverlap());
      EXPECT_NEAR(double(hit.distance), double(exact), toiTol<T>(double(hit.normal.dot(c.dir))))
          << "shape " << int(shape.type()) << " case " << i;
      EXPECT_LT(double(hit.normal.dot(c.dir)), 0.0);
      // The reported triangle touches at the reported distance (ties between neighbours are both right).
      ASSERT_LT(hit.faceIndex, tris.size());
      const L own = sweeptest::exactToi(swept, tris[hit.faceIndex], dir, L(kMaxDist), L(kToiTol<T>) / 16);
      EXPECT_NEAR(double(own), double(exact), 2 * toiTol<T>(double(hit.normal.dot(c.dir)))) << "face " << hit.faceIndex;
    }
  EXPECT_GT(hits, 32);  // the starts lie above the interior: nearly every sweep lands
}

TYPED_TEST(SweepSurfaces, MeshAnyHitReturnsATriangleTouchingAtTheReportedDistance) {
  using T = TypeParam;
  int hits = 0;
  for (const Geometry<T>& shape : this->sweptShapes())
    for (int i = 0; i < 10; ++i) {
      const auto c = this->randomCase();
      const std::vector<Core> tris = this->worldTriangles(c.terrain);
      const Core swept = sweeptest::coreOf(shape, c.start);
      const VL dir = sweeptest::toL(c.dir).normalized();
      const auto [exact, index] = this->exactToi(swept, tris, dir);
      SweepHit<T> any, closest;
      bool hasAny = false, hasClosest = false;
      ASSERT_TRUE(sweep(c.dir, T(kMaxDist), shape, c.start, this->triangleMesh(), c.terrain, any, hasAny,
                        kDefaultHitFlags | HitFlag::AnyHit).ok());
      ASSERT_TRUE(sweep(c.dir, T(kMaxDist), shape, c.start, this->triangleMesh(), c.terrain, closest, hasClosest).ok());
      ASSERT_EQ(hasAny, index >= 0);
      ASSERT_EQ(hasClosest, index >= 0);
      if (!hasAny) continue;
      ++hits;
      // Closest: the exact first contact. AnyHit: some triangle's exact contact, never before the first one.
      EXPECT_NEAR(double(closest.distance), double(exact), toiTol<T>(double(closest.normal.dot(c.dir))));
      ASSERT_LT(any.faceIndex, tris.size());
      const L own = sweeptest::exactToi(swept, tris[any.faceIndex], dir, L(kMaxDist), L(kToiTol<T>) / 16);
      ASSERT_GE(double(own), 0.0) << "anyHit reported triangle " << any.faceIndex << ", which the sweep misses";
      EXPECT_NEAR(double(any.distance), double(own), toiTol<T>(double(any.normal.dot(c.dir))))
          << "shape " << int(shape.type()) << " case " << i << ": triangle " << any.faceIndex;
      EXPECT_GE(double(any.distance), double(exact) - kToiTol<T>);
      EXPECT_LT(double(any.normal.dot(c.dir)), 0.0);
    }
  EXPECT_GT(hits, 32);
}

TYPED_TEST(SweepSurfaces, MeshInitialOverlapWithMtdReportsTheDepthAlongTheFaceNormal) {
  using T = TypeParam;
  // A flat square (two triangles, y = 0, facing +Y) at random poses; a sphere of radius 0.2 and a box of half height
  // 0.1 sink to height hc: depths 0.2 - hc and 0.1 - hc, escape along the face normal, sweep distance = -depth.
  const std::vector<Vec3<T>> v = {Vec3<T>(T(-2), T(0), T(-2)), Vec3<T>(T(-2), T(0), T(2)), Vec3<T>(T(2), T(0), T(2)),
                                  Vec3<T>(T(2), T(0), T(-2))};
  std::shared_ptr<const TriangleMesh<T>> square;
  ASSERT_TRUE(cookTriangleMesh(v, {TriangleIndices{0, 1, 2}, TriangleIndices{0, 2, 3}}, square).ok());
  const Geometry<T> mesh = TriangleMeshGeometry<T>(square);
  for (int i = 0; i < 20; ++i) {
    const Transform<T> pose = this->rng.template pose<T>(3);
    const Vec3<T> up = pose.rotate(Vec3<T>::UnitY());
    const double hc = this->rng.uniform(0.02, 0.09), x = this->rng.uniform(-1, 1), z = this->rng.uniform(-1, 1);
    const Vec3<T> centre = pose.transform(Vec3<T>(T(x), T(hc), T(z)));
    const std::pair<Geometry<T>, double> shapes[] = {{SphereGeometry<T>(T(0.2)), 0.2 - hc},
                                                      {BoxGeometry<T>(T(0.3), T(0.1), T(0.25)), 0.1 - hc}};
    for (const auto& [shape, depth] : shapes) {
      SweepHit<T> hit;
      bool hasHit = false;
      // The box keeps the square's orientation (its half height 0.1 along the square's normal).
      const Transform<T> start(centre, pose.q);
      ASSERT_TRUE(sweep(Vec3<T>(-up), T(1), shape, start, mesh, pose, hit, hasHit, kDefaultHitFlags | HitFlag::Mtd).ok());
      ASSERT_TRUE(hasHit);
      EXPECT_TRUE(hit.hadInitialOverlap());
      EXPECT_NEAR(double(hit.distance), -depth, 10 * kToiTol<T>) << "case " << i;
      EXPECT_NEAR(double((hit.normal - up).norm()), 0.0, 10 * kToiTol<T>);
    }
  }
}

}  // namespace
