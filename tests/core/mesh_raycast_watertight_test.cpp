// Watertightness of mesh raycasts: rays aimed exactly at vertices and at points of edges of closed meshes cross the
// surface there, so each must hit no farther than its target (a leak through a shared edge or vertex would reach the
// far side, or miss). Float and double, through prepared shapes (the fast path), both faces and front faces only.
// MeshWatertightRays: generated closed meshes (a subdivided icosphere and a twisted, non-convex torus), always run.
// MeshWatertightLong (label long): 10M rays per precision at the closed shared meshes (fandisk, spot); skipped,
// naming the path, when the shared data folder does not hold them.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "gq/io.h"
#include "gq/query.h"
#include "gq/shape.h"
#include "mesh_test_helpers.h"

namespace gq {
namespace {

using meshtest::Scalars;

// A closed torus (major radius 3, minor radius 1 modulated along the ring, so it is not convex anywhere near a
// circle of symmetry), `ring` x `tube` quads, two triangles each, wound outward.
template <class T> MeshData<T> wavyTorus(int ring, int tube) {
  MeshData<T> m;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < ring; ++i)
    for (int j = 0; j < tube; ++j) {
      const double u = 2 * pi * i / ring, v = 2 * pi * j / tube;
      const double r = 1.0 + 0.3 * std::sin(5 * u) * std::cos(3 * v);
      m.vertices.push_back(Vec3<double>((3 + r * std::cos(v)) * std::cos(u), (3 + r * std::cos(v)) * std::sin(u),
                                        r * std::sin(v))
                               .cast<T>());
    }
  auto id = [&](int i, int j) { return std::uint32_t(((i + ring) % ring) * tube + (j + tube) % tube); };
  for (int i = 0; i < ring; ++i)
    for (int j = 0; j < tube; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

// Area-weighted vertex normals (outward for outward winding), in double.
template <class T> std::vector<Vec3<double>> vertexNormals(const MeshData<T>& m) {
  std::vector<Vec3<double>> n(m.vertices.size(), Vec3<double>::Zero());
  for (const auto& t : m.triangles) {
    const Vec3<double> a = m.vertices[t[0]].template cast<double>(), b = m.vertices[t[1]].template cast<double>(),
                       c = m.vertices[t[2]].template cast<double>();
    const Vec3<double> f = (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k) n[t[k]] += f;
  }
  for (auto& x : n) x.normalize();
  return n;
}

struct LeakCount {
  std::uint64_t rays = 0, leaks = 0;
};

// `count` rays aimed at vertices (every 4th ray) or at points of edges (the others, at exact midpoints or random
// parameters), from a distance along the outward normal with a small tilt; each must hit at a distance no larger than
// its target's, up to the rounding of the aim.
template <class T> LeakCount castAtFeatures(const MeshData<T>& m, std::uint64_t count, std::uint64_t seed) {
  std::shared_ptr<const TriangleMesh<T>> cooked;
  EXPECT_TRUE(cookTriangleMesh(m.vertices, m.triangles, cooked).ok());
  Shape<T> shape;
  EXPECT_TRUE(Shape<T>::make(TriangleMeshGeometry<T>(cooked), shape).ok());
  const std::vector<Vec3<double>> normals = vertexNormals(m);
  Bounds3<double> b;
  for (const auto& v : m.vertices) b.include(v.template cast<double>());
  const double size = (b.max - b.min).norm();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g;
  LeakCount out;
  RaycastHit<T> hit;
  for (std::uint64_t r = 0; r < count; ++r) {
    const auto& t = m.triangles[std::size_t(u(rng) * double(m.triangles.size())) % m.triangles.size()];
    const int k = int(r % 3);
    Vec3<T> target;
    Vec3<double> normal;
    if (r % 4 == 0) {
      target = m.vertices[t[k]];
      normal = normals[t[k]];
    } else {
      const Vec3<T>& a = m.vertices[t[k]];
      const Vec3<T>& c = m.vertices[t[(k + 1) % 3]];
      const T s = r % 4 == 1 ? T(0.5) : T(u(rng));
      target = a + (c - a) * s;
      normal = (normals[t[k]] + normals[t[(k + 1) % 3]]).normalized();
    }
    const Vec3<double> tilt(g(rng), g(rng), g(rng));
    const Vec3<double> off = (normal + 0.1 * tilt).normalized() * (0.05 + u(rng)) * size;
    const Vec3<T> origin = (target.template cast<double>() + off).template cast<T>();
    const Vec3<T> dir = Vec3<T>(target - origin).normalized();
    const T reach = Vec3<T>(target - origin).norm();
    const HitFlags flags = r % 2 ? kDefaultHitFlags | HitFlag::MeshBothSides : kDefaultHitFlags;
    std::uint32_t n = 0;
    const Status s = raycast(origin, dir, shape, Transform<T>(), T(4 * size), flags, 1, &hit, n);
    ++out.rays;
    // The aim is exact up to the rounding of dir; 64 ulps of the reach cover it.
    const T slack = reach * T(64) * std::numeric_limits<T>::epsilon() + T(64) * std::numeric_limits<T>::epsilon() * T(size);
    if (!s.ok() || n != 1 || hit.distance > reach + slack) ++out.leaks;
  }
  return out;
}

template <class T> class MeshWatertightRays : public ::testing::Test {};
TYPED_TEST_SUITE(MeshWatertightRays, Scalars);

TYPED_TEST(MeshWatertightRays, RaysAtVerticesAndEdgesOfAClosedIcosphereNeverLeak) {
  const LeakCount c = castAtFeatures(meshtest::icosphere<TypeParam>(4), 40000, 1);
  EXPECT_EQ(c.rays, 40000u);
  EXPECT_EQ(c.leaks, 0u);
}

TYPED_TEST(MeshWatertightRays, RaysAtVerticesAndEdgesOfAClosedNonConvexTorusNeverLeak) {
  const LeakCount c = castAtFeatures(wavyTorus<TypeParam>(96, 48), 40000, 2);
  EXPECT_EQ(c.rays, 40000u);
  EXPECT_EQ(c.leaks, 0u);
}

template <class T> class MeshWatertightLong : public ::testing::Test {};
TYPED_TEST_SUITE(MeshWatertightLong, Scalars);

// 10M rays per precision: 5M at each closed shared mesh.
TYPED_TEST(MeshWatertightLong, TenMillionRaysAtVerticesAndEdgesOfTheClosedSharedMeshesNeverLeak) {
  std::uint64_t rays = 0, leaks = 0;
  for (const char* name : {"fandisk", "spot"}) {
    const std::string path = gqtest::sharedPath(std::string("meshes/") + name + ".obj");
    GQ_REQUIRE_SHARED_FILE(path);
    MeshData<double> d;
    const Status s = loadMeshFile(path, d);
    ASSERT_TRUE(s.ok()) << s.toString();
    MeshData<TypeParam> m;
    for (const auto& v : d.vertices) m.vertices.push_back(v.cast<TypeParam>());
    m.triangles = d.triangles;
    const LeakCount c = castAtFeatures(m, 5000000, 3);
    EXPECT_EQ(c.leaks, 0u) << name;
    rays += c.rays;
    leaks += c.leaks;
  }
  EXPECT_EQ(rays, 10000000u);
  EXPECT_EQ(leaks, 0u);
}

}  // namespace
}  // namespace gq
