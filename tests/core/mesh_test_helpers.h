#pragma once
// Helpers for the triangle-mesh tests: small meshes built in code (quad stacks, icosphere), the bunny (loaded once),
// and cooking shortcuts.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "gq/cooking.h"
#include "gq/geometry.h"
#include "gq/io.h"
#include "shared_data.h"

namespace gq::meshtest {

using Scalars = ::testing::Types<float, double>;

template <class T> std::shared_ptr<const TriangleMesh<T>> cook(const std::vector<Vec3<T>>& v,
                                                                const std::vector<TriangleIndices>& t) {
  std::shared_ptr<const TriangleMesh<T>> mesh;
  const Status s = cookTriangleMesh(v, t, mesh);
  EXPECT_TRUE(s.ok()) << s.toString();
  return mesh;
}

// `count` squares [-1,1]^2 at z = 0, 1, ..., count-1, two triangles each (2k: y <= x half, 2k+1: y >= x half),
// wound so the outward normal is +Z.
template <class T> MeshData<T> quadStack(int count) {
  MeshData<T> m;
  for (int k = 0; k < count; ++k) {
    const auto b = std::uint32_t(m.vertices.size());
    const T z = T(k);
    m.vertices.push_back({T(-1), T(-1), z});
    m.vertices.push_back({T(1), T(-1), z});
    m.vertices.push_back({T(1), T(1), z});
    m.vertices.push_back({T(-1), T(1), z});
    m.triangles.push_back({b, b + 1, b + 2});
    m.triangles.push_back({b, b + 2, b + 3});
  }
  return m;
}

// Unit icosphere: an icosahedron with every triangle split in 4 `levels` times, vertices projected to the sphere.
// Computed in double, then converted, so float and double meshes share the topology. Outward winding.
template <class T> MeshData<T> icosphere(int levels) {
  const double p = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> v = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
                                    {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
  for (auto& x : v) x.normalize();
  std::vector<TriangleIndices> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back((v[a] + v[b]).normalized());
      const auto id = std::uint32_t(v.size() - 1);
      mid[key] = id;
      return id;
    };
    std::vector<TriangleIndices> next;
    for (const auto& t : f) {
      const std::uint32_t a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]), c = midpoint(t[2], t[0]);
      next.push_back({t[0], a, c});
      next.push_back({t[1], b, a});
      next.push_back({t[2], c, b});
      next.push_back({a, b, c});
    }
    f = std::move(next);
  }
  for (auto& t : f) {  // orient outward: the normal points away from the center
    if ((v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).dot(v[t[0]] + v[t[1]] + v[t[2]]) < 0) std::swap(t[1], t[2]);
  }
  MeshData<T> m;
  for (const auto& x : v) m.vertices.push_back(x.cast<T>());
  m.triangles = f;
  return m;
}

inline std::string bunnyPath() { return gqtest::sharedPath("meshes/stanford-bunny.obj"); }

// The bunny as loaded in double (loaded once per process) and the status of that load.
struct BunnyLoad {
  MeshData<double> data;
  Status status;
};
inline const BunnyLoad& bunnyLoad() {
  static const BunnyLoad load = [] {
    BunnyLoad l;
    l.status = loadMeshFile(bunnyPath(), l.data);
    return l;
  }();
  return load;
}
inline const MeshData<double>& bunnyData() { return bunnyLoad().data; }

template <class T> MeshData<T> bunny() {
  MeshData<T> out;
  for (const auto& v : bunnyData().vertices) out.vertices.push_back(v.cast<T>());
  out.triangles = bunnyData().triangles;
  return out;
}

}  // namespace gq::meshtest

// Skips the running test when the bunny file is missing (naming its path) and fails it when the file does not load;
// after it, meshtest::bunny<T>() holds the 69,451 triangles. For test bodies and fixtures' SetUp.
#define GQ_REQUIRE_BUNNY()                                                                          \
  do {                                                                                              \
    GQ_REQUIRE_SHARED_FILE(::gq::meshtest::bunnyPath());                                            \
    ASSERT_TRUE(::gq::meshtest::bunnyLoad().status.ok()) << ::gq::meshtest::bunnyLoad().status.toString(); \
  } while (false)
