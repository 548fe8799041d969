// All hits (MeshMultiple) against the closed shared mesh spot: every triangle the ray crosses is reported exactly once,
// as a brute force over all triangles in long double decides on the same (T-rounded) ray and vertices. Rays from 4
// units outside the bounding sphere, half aimed at random surface points, half through random points of the bounds.
// A ray that passes so close to an edge that the long double signs are not certain is left out of the comparison
// (none is expected among these rays; the count is checked).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "shared_data.h"
#include "gq/io.h"
#include "gq/query.h"
#include "gq/shape.h"
#include "mesh_test_helpers.h"

namespace gq {
namespace {

using meshtest::Scalars;
using L = long double;

struct BruteHits {
  std::vector<std::uint32_t> triangles;  // input indices, ascending
  bool uncertain = false;
};

// Triangles whose closed interior the ray o + t d, 0 <= t <= maxDist, crosses (both faces), by the signs of the
// triple products d . (p_k x p_k+1) with p = vertex - o, computed in long double.
template <class T>
BruteHits bruteForce(const MeshData<T>& m, const Vec3<T>& o, const Vec3<T>& d, T maxDist) {
  BruteHits out;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    L p[3][3];
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) p[k][a] = L(m.vertices[m.triangles[t][k]][a]) - L(o[a]);
    L s[3];
    bool nearZero = false;
    for (int k = 0; k < 3; ++k) {
      const L* A = p[k];
      const L* B = p[(k + 1) % 3];
      const L cx = A[1] * B[2] - A[2] * B[1], cy = A[2] * B[0] - A[0] * B[2], cz = A[0] * B[1] - A[1] * B[0];
      s[k] = L(d[0]) * cx + L(d[1]) * cy + L(d[2]) * cz;
      const L magnitude = std::fabs(L(d[0]) * cx) + std::fabs(L(d[1]) * cy) + std::fabs(L(d[2]) * cz);
      nearZero = nearZero || std::fabs(s[k]) <= magnitude * 1e-15L;
    }
    const bool inside = (s[0] >= 0 && s[1] >= 0 && s[2] >= 0) || (s[0] <= 0 && s[1] <= 0 && s[2] <= 0);
    if (!inside || s[0] + s[1] + s[2] == 0) continue;
    L e1[3], e2[3];
    for (int a = 0; a < 3; ++a) {
      e1[a] = p[1][a] - p[0][a];
      e2[a] = p[2][a] - p[0][a];
    }
    const L n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const L dn = L(d[0]) * n[0] + L(d[1]) * n[1] + L(d[2]) * n[2];
    const L t0 = (p[0][0] * n[0] + p[0][1] * n[1] + p[0][2] * n[2]) / dn;
    if (t0 < 0 || t0 > L(maxDist)) continue;
    out.uncertain = out.uncertain || nearZero;
    out.triangles.push_back(std::uint32_t(t));
  }
  return out;
}

template <class T> class MeshRaycastAllHitsData : public ::testing::Test {};
TYPED_TEST_SUITE(MeshRaycastAllHitsData, Scalars);

TYPED_TEST(MeshRaycastAllHitsData, EveryCrossedTriangleOfSpotIsReportedOnce) {
  using T = TypeParam;
  const std::string path = gqtest::sharedPath("meshes/spot.obj");
  GQ_REQUIRE_SHARED_FILE(path);
  MeshData<double> d;
  const Status loaded = loadMeshFile(path, d);
  ASSERT_TRUE(loaded.ok()) << loaded.toString();
  MeshData<T> m;
  for (const auto& v : d.vertices) m.vertices.push_back(v.cast<T>());
  m.triangles = d.triangles;
  std::shared_ptr<const TriangleMesh<T>> cooked;
  ASSERT_TRUE(cookTriangleMesh(m.vertices, m.triangles, cooked).ok());
  Shape<T> shape;
  ASSERT_TRUE(Shape<T>::make(TriangleMeshGeometry<T>(cooked), shape).ok());

  Bounds3<double> b;
  for (const auto& v : d.vertices) b.include(v);
  const Vec3<double> center = b.center();
  const double radius = 0.5 * (b.max - b.min).norm(), distance = 4.0;
  const T maxDist = T(4 * (radius + distance));
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g;
  const HitFlags flags = kDefaultHitFlags | HitFlag::MeshBothSides | HitFlag::MeshMultiple;
  std::vector<RaycastHit<T>> hits(64);
  int compared = 0, uncertain = 0;
  std::uint64_t totalHits = 0;
  for (int r = 0; r < 3000; ++r) {
    Vec3<double> target;
    if (r % 2 == 0) {
      const auto& t = d.triangles[std::size_t(u(rng) * double(d.triangles.size())) % d.triangles.size()];
      double a = u(rng), c = u(rng);
      if (a + c > 1) { a = 1 - a; c = 1 - c; }
      target = (1 - a - c) * d.vertices[t[0]] + a * d.vertices[t[1]] + c * d.vertices[t[2]];
    } else {
      target = b.min + (b.max - b.min).cwiseProduct(Vec3<double>(u(rng), u(rng), u(rng)));
    }
    const Vec3<double> o = center + Vec3<double>(g(rng), g(rng), g(rng)).normalized() * (radius + distance);
    const Vec3<T> origin = o.cast<T>(), dir = (target - o).normalized().cast<T>();
    std::uint32_t n = 0;
    const Status s = raycast(origin, dir, shape, Transform<T>(), maxDist, flags, 64, hits.data(), n);
    ASSERT_TRUE(s.ok()) << s.toString();
    const BruteHits brute = bruteForce(m, origin, dir, maxDist);
    if (brute.uncertain) {
      ++uncertain;
      continue;
    }
    std::vector<std::uint32_t> reported;
    for (std::uint32_t i = 0; i < n; ++i) reported.push_back(hits[i].faceIndex);
    std::sort(reported.begin(), reported.end());
    EXPECT_EQ(reported, brute.triangles) << "ray " << r;
    ++compared;
    totalHits += n;
  }
  EXPECT_EQ(uncertain, 0);
  EXPECT_EQ(compared, 3000);
  EXPECT_GT(totalHits, 3000u);  // about two crossings per ray: the rays do reach the mesh
}

}  // namespace
}  // namespace gq
