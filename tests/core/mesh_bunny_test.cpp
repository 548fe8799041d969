// BVH queries on the Stanford bunny (69,451 triangles) against brute-force loops over every triangle:
// closest-hit raycasts and closest points, in float and double. The brute force runs on 2 threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

#include "gq/query.h"
#include "mesh/triangle.h"
#include "mesh_test_helpers.h"
#include "point_distance/point_distance.h"

namespace gq {
namespace {

using meshtest::Scalars;
using LD = long double;
using Vec3L = Eigen::Matrix<LD, 3, 1>;

template <class F> void parallelFor(std::size_t n, F&& body) {
  constexpr int kThreads = 2;
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (std::size_t i = t; i < n; i += kThreads) body(i);
    });
  for (auto& th : threads) th.join();
}

// Needs the bunny from the shared data folder: skipped when it is missing. Cooked once per suite, on first use.
template <class T> class MeshBunnyData : public ::testing::Test {
 protected:
  void SetUp() override {
    GQ_REQUIRE_BUNNY();
    if (data == nullptr) {
      data = new MeshData<T>(meshtest::bunny<T>());
      mesh = new std::shared_ptr<const TriangleMesh<T>>(meshtest::cook(data->vertices, data->triangles));
    }
    ASSERT_TRUE(*mesh);
  }
  static void TearDownTestSuite() {
    delete data;
    delete mesh;
    data = nullptr;
    mesh = nullptr;
  }
  static MeshData<T>* data;
  static std::shared_ptr<const TriangleMesh<T>>* mesh;
};
template <class T> MeshData<T>* MeshBunnyData<T>::data = nullptr;
template <class T> std::shared_ptr<const TriangleMesh<T>>* MeshBunnyData<T>::mesh = nullptr;
TYPED_TEST_SUITE(MeshBunnyData, Scalars);

struct Sphere { Eigen::Vector3d c; double r; };

// The brute force's own culling (independent of the BVH): triangles sorted along a Morton curve of their
// centroids, cut into chunks of 32, each chunk and triangle with a bounding sphere (inflated against rounding).
struct SphereChunks {
  static constexpr std::size_t kChunk = 32;
  std::vector<std::uint32_t> order;  // input triangle indices, Morton-sorted
  std::vector<Sphere> tri;           // per entry of `order`
  std::vector<Sphere> chunk;
};

template <class T> SphereChunks makeChunks(const MeshData<T>& m) {
  SphereChunks sc;
  std::vector<Sphere> spheres;
  Eigen::AlignedBox3d box;
  for (const auto& t : m.triangles) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (auto v : t) c += m.vertices[v].template cast<double>() / 3.0;
    double r = 0;
    for (auto v : t) r = std::max(r, (m.vertices[v].template cast<double>() - c).norm());
    spheres.push_back({c, r * (1 + 1e-6) + 1e-9});
    box.extend(c);
  }
  auto morton = [&](const Eigen::Vector3d& c) {
    const Eigen::Vector3d q = (c - box.min()).cwiseQuotient(box.sizes().cwiseMax(1e-30)) * 1023.0;
    std::uint64_t code = 0;
    for (int b = 9; b >= 0; --b)
      for (int a = 0; a < 3; ++a) code = (code << 1) | ((std::uint64_t(q[a]) >> b) & 1u);
    return code;
  };
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  for (std::uint32_t i = 0; i < spheres.size(); ++i) keyed.push_back({morton(spheres[i].c), i});
  std::sort(keyed.begin(), keyed.end());
  for (const auto& k : keyed) {
    sc.order.push_back(k.second);
    sc.tri.push_back(spheres[k.second]);
  }
  for (std::size_t b = 0; b < sc.tri.size(); b += SphereChunks::kChunk) {
    const std::size_t e = std::min(sc.tri.size(), b + SphereChunks::kChunk);
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (std::size_t i = b; i < e; ++i) c += sc.tri[i].c / double(e - b);
    double r = 0;
    for (std::size_t i = b; i < e; ++i) r = std::max(r, (sc.tri[i].c - c).norm() + sc.tri[i].r);
    sc.chunk.push_back({c, r * (1 + 1e-9)});
  }
  return sc;
}

bool lineMissesSphere(const Sphere& s, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  const Eigen::Vector3d w = s.c - o;
  const double along = w.dot(d);
  return w.squaredNorm() - along * along > s.r * s.r;
}

// Closest front-face hit over all triangles (the same watertight triangle test, equal distances resolved to the
// lower input index); bounding spheres skip triangles far from the ray's line.
template <class T> struct BruteHit { bool hit = false; T t = T(0); std::uint32_t face = 0; };
template <class T>
BruteHit<T> bruteRaycast(const MeshData<T>& m, const SphereChunks& sc, const Vec3<T>& o, const Vec3<T>& d,
                         T maxDist) {
  const detail::WatertightRay<T> ray = detail::makeWatertightRay(o, d);
  const Eigen::Vector3d od = o.template cast<double>(), dd = d.template cast<double>();
  BruteHit<T> best;
  T bestT = maxDist;
  for (std::size_t c = 0; c < sc.chunk.size(); ++c) {
    if (lineMissesSphere(sc.chunk[c], od, dd)) continue;
    const std::size_t end = std::min(sc.order.size(), (c + 1) * SphereChunks::kChunk);
    for (std::size_t k = c * SphereChunks::kChunk; k < end; ++k) {
      if (lineMissesSphere(sc.tri[k], od, dd)) continue;
      const std::uint32_t i = sc.order[k];
      const auto& t = m.triangles[i];
      detail::TriangleRayHit<T> h;
      if (!detail::intersectRayTriangle(ray, m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], bestT, true, h))
        continue;
      if (best.hit && h.t == bestT && i > best.face) continue;
      best = {true, h.t, i};
      bestT = h.t;
    }
  }
  return best;
}

TYPED_TEST(MeshBunnyData, ClosestHitEqualsBruteForceOn100kRays) {
  using T = TypeParam;
  const MeshData<T>& m = *this->data;
  const TriangleMesh<T>& mesh = **this->mesh;
  const SphereChunks spheres = makeChunks(m);
  const Vec3<T> center = mesh.localBounds.center();
  const T radius = mesh.localBounds.extents().norm();
  constexpr int kRays = 100000;
  std::vector<Vec3<T>> origins(kRays), dirs(kRays);
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> n;
  // One draw per declarator: argument evaluation order is unspecified (GCC and clang differ).
  auto unit = [&] {
    const double x = n(rng), y = n(rng), z = n(rng);
    return Eigen::Vector3d(x, y, z).normalized();
  };
  for (int i = 0; i < kRays; ++i) {
    if (i % 2 == 0) {  // aimed at a random point of a random triangle, from outside the bounds
      const auto& t = m.triangles[std::size_t(u(rng) * m.triangles.size()) % m.triangles.size()];
      double a = u(rng), b = u(rng);
      if (a + b > 1) { a = 1 - a; b = 1 - b; }
      const Eigen::Vector3d target = (1 - a - b) * m.vertices[t[0]].template cast<double>() +
                                     a * m.vertices[t[1]].template cast<double>() +
                                     b * m.vertices[t[2]].template cast<double>();
      const Eigen::Vector3d o = center.template cast<double>() + unit() * (2.0 * double(radius));
      origins[i] = o.template cast<T>();
      dirs[i] = (target - o).normalized().template cast<T>();
    } else {  // random origin in the (enlarged) bounds, random direction
      const double x = u(rng), y = u(rng), z = u(rng);
      origins[i] =
          (center.template cast<double>() + Eigen::Vector3d(x - 0.5, y - 0.5, z - 0.5) * (3.0 * double(radius)))
              .template cast<T>();
      dirs[i] = unit().template cast<T>();
    }
  }
  const T maxDist = T(10) * radius;
  std::atomic<int> mismatches{0}, hits{0};
  const TriangleMeshGeometry<T> g(*this->mesh);
  parallelFor(kRays, [&](std::size_t i) {
    RaycastHit<T> hit;
    std::uint32_t count = 0;
    const Status s = raycast(origins[i], dirs[i], Geometry<T>(g), Transform<T>(), maxDist, kDefaultHitFlags, 1, &hit,
                             count);
    const BruteHit<T> ref = bruteRaycast(m, spheres, origins[i], dirs[i], maxDist);
    const bool same = s.ok() && (count == 1) == ref.hit &&
                      (!ref.hit || (hit.distance == ref.t && hit.faceIndex == ref.face));
    if (!same) ++mismatches;
    if (ref.hit) ++hits;
  });
  EXPECT_EQ(mismatches.load(), 0);
  EXPECT_GT(hits.load(), kRays / 2);  // the aimed half hits, plus some of the random half
}

// Independent point-triangle distance (long double): the plane projection if it falls inside, else the nearest of
// the three edges.
LD pointSegmentDistance(const Vec3L& p, const Vec3L& a, const Vec3L& b) {
  const Vec3L ab = b - a;
  const LD s = std::clamp((p - a).dot(ab) / ab.squaredNorm(), LD(0), LD(1));
  return (p - (a + s * ab)).norm();
}
LD pointTriangleDistance(const Vec3L& p, const Vec3L& a, const Vec3L& b, const Vec3L& c) {
  const Vec3L nrm = (b - a).cross(c - a);
  const Vec3L q = p - nrm * ((p - a).dot(nrm) / nrm.squaredNorm());
  const bool inside = (b - a).cross(q - a).dot(nrm) >= 0 && (c - b).cross(q - b).dot(nrm) >= 0 &&
                      (a - c).cross(q - c).dot(nrm) >= 0;
  if (inside) return (p - q).norm();
  return std::min({pointSegmentDistance(p, a, b), pointSegmentDistance(p, b, c), pointSegmentDistance(p, c, a)});
}

TYPED_TEST(MeshBunnyData, PointDistanceEqualsBruteForceUnderScaleAndPose) {
  using T = TypeParam;
  const MeshData<T>& m = *this->data;
  const MeshScale<T> scale(Vec3<T>(T(1.3), T(-0.8), T(2.1)),
                           Quat<T>(Eigen::AngleAxis<T>(T(0.4), Vec3<T>(1, 1, 0).normalized())));
  const Transform<T> pose(Vec3<T>(T(0.5), T(-1), T(2)), Quat<T>(Eigen::AngleAxis<T>(T(2.0), Vec3<T>(0, 1, 1).normalized())));
  const TriangleMeshGeometry<T> g(*this->mesh, scale);
  // World vertices in long double.
  const Eigen::Matrix<LD, 3, 3> S = scale.toMatrix().template cast<LD>();
  const Eigen::Matrix<LD, 3, 3> R = pose.q.toRotationMatrix().template cast<LD>();
  std::vector<Vec3L> world;
  for (const auto& v : m.vertices) world.push_back(R * (S * v.template cast<LD>()) + pose.p.template cast<LD>());
  MeshData<double> worldMesh;
  for (const auto& w : world) worldMesh.vertices.push_back(w.template cast<double>());
  worldMesh.triangles = m.triangles;
  const SphereChunks chunks = makeChunks(worldMesh);
  Eigen::AlignedBox<LD, 3> box;
  for (const auto& w : world) box.extend(w);
  const LD size = box.diagonal().norm();
  const LD tol = (std::is_same_v<T, float> ? LD(2e-5) : LD(1e-11)) * size;
  constexpr int kPoints = 2000;
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-0.8, 0.8);
  std::vector<Vec3<T>> points;
  for (int i = 0; i < kPoints; ++i) {
    const double x = u(rng), y = u(rng), z = u(rng);
    const Vec3L p = box.center() + Vec3L(x, y, z).cwiseProduct(box.sizes()) * (i % 2 ? 0.7L : 1.5L);
    points.push_back(p.template cast<T>());
  }
  std::atomic<int> bad{0};
  parallelFor(kPoints, [&](std::size_t i) {
    PointDistanceResult<T> r;
    detail::pointDistanceTriangleMesh(g, pose, points[i], r);
    const Vec3L p = points[i].template cast<LD>();
    const Eigen::Vector3d pd = p.template cast<double>();
    // Chunks nearest first; a chunk (or triangle) whose sphere is farther than the best so far cannot win.
    std::vector<std::pair<double, std::size_t>> chunkOrder;
    for (std::size_t c = 0; c < chunks.chunk.size(); ++c)
      chunkOrder.push_back({(chunks.chunk[c].c - pd).norm() - chunks.chunk[c].r, c});
    std::sort(chunkOrder.begin(), chunkOrder.end());
    LD best = std::numeric_limits<LD>::infinity();
    for (const auto& [lower, c] : chunkOrder) {
      if (LD(lower) > best * (1 + 1e-9L)) break;
      const std::size_t end = std::min(chunks.order.size(), (c + 1) * SphereChunks::kChunk);
      for (std::size_t k = c * SphereChunks::kChunk; k < end; ++k) {
        if (LD((chunks.tri[k].c - pd).norm() - chunks.tri[k].r) > best * (1 + 1e-9L)) continue;
        const auto& t = m.triangles[chunks.order[k]];
        best = std::min(best, pointTriangleDistance(p, world[t[0]], world[t[1]], world[t[2]]));
      }
    }
    if (r.closestIndex >= m.triangles.size()) { ++bad; return; }
    const auto& t = m.triangles[r.closestIndex];
    const LD own = pointTriangleDistance(p, world[t[0]], world[t[1]], world[t[2]]);
    const LD onTriangle = pointTriangleDistance(r.closestPoint.template cast<LD>(), world[t[0]], world[t[1]], world[t[2]]);
    const bool ok = std::abs(LD(r.distance) - best) <= tol && std::abs(own - best) <= tol && onTriangle <= tol &&
                    std::abs((r.closestPoint.template cast<LD>() - p).norm() - LD(r.distance)) <= tol;
    if (!ok) ++bad;
  });
  EXPECT_EQ(bad.load(), 0);
}

}  // namespace
}  // namespace gq
