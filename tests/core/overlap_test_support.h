#pragma once
// Helpers for the overlap / penetration tests: hand-built convex hulls (independent of the cooker), call
// wrappers that assert Ok, and support functions in long double for independent MTD checks.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "gq/cooking.h"
#include "gq/query.h"
#include "test_util.h"

namespace gq::test {

// A convex hull from vertices and faces (vertex loops counter-clockwise seen from outside), built directly.
template <class T>
std::shared_ptr<const ConvexMesh<T>> makeHull(const std::vector<Vec3<T>>& vertices,
                                              const std::vector<std::vector<std::uint32_t>>& faces) {
  auto mesh = std::make_shared<ConvexMesh<T>>();
  mesh->vertices = vertices;
  std::vector<std::vector<std::uint32_t>> adjacent(vertices.size());
  for (const auto& f : faces) {
    const Vec3<T> n = (vertices[f[1]] - vertices[f[0]]).cross(vertices[f[2]] - vertices[f[0]]).normalized();
    mesh->polygons.push_back({n, -n.dot(vertices[f[0]]), std::uint32_t(mesh->polygonVertices.size()),
                              std::uint32_t(f.size())});
    for (std::size_t i = 0; i < f.size(); ++i) {
      mesh->polygonVertices.push_back(f[i]);
      adjacent[f[i]].push_back(f[(i + 1) % f.size()]);
    }
  }
  mesh->adjacencyOffsets.push_back(0);
  for (auto& a : adjacent) {
    mesh->adjacency.insert(mesh->adjacency.end(), a.begin(), a.end());
    mesh->adjacencyOffsets.push_back(std::uint32_t(mesh->adjacency.size()));
  }
  Vec3<T> c = Vec3<T>::Zero();
  for (const Vec3<T>& v : vertices) {
    mesh->localBounds.include(v);
    c += v;
  }
  mesh->center = c / T(vertices.size());
  return mesh;
}

// Regular octahedron |x| + |y| + |z| <= s.
template <class T> std::shared_ptr<const ConvexMesh<T>> octahedronHull(T s) {
  const std::vector<Vec3<T>> v = {{s, 0, 0}, {-s, 0, 0}, {0, s, 0}, {0, -s, 0}, {0, 0, s}, {0, 0, -s}};
  return makeHull<T>(v, {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}});
}

// Axis-aligned box [-h, h] as a hull (to compare hull paths with the box paths).
template <class T> std::shared_ptr<const ConvexMesh<T>> boxHull(const Vec3<T>& h) {
  std::vector<Vec3<T>> v;
  for (int i = 0; i < 8; ++i) v.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
  return makeHull<T>(v, {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}});
}

// Tetrahedron with corners 0, s*e_x, s*e_y, s*e_z.
template <class T> std::shared_ptr<const ConvexMesh<T>> cornerTetrahedron(T s) {
  const std::vector<Vec3<T>> v = {{0, 0, 0}, {s, 0, 0}, {0, s, 0}, {0, 0, s}};
  return makeHull<T>(v, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
}

template <class T>
bool overlaps(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1) {
  bool result = false;
  const Status s = overlap(g0, p0, g1, p1, result);
  EXPECT_TRUE(s.ok()) << s.toString();
  return result;
}

template <class T>
PenetrationResult<T> penetration(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                 const Transform<T>& p1) {
  PenetrationResult<T> r;
  const Status s = computePenetration(r, g0, p0, g1, p1);
  EXPECT_TRUE(s.ok()) << s.toString();
  return r;
}

// Support function h(n) = max over the shape of n.x, in long double (n unit, world frame), for bounded convex shapes.
template <class T> LD supportLD(const Geometry<T>& g, const Transform<T>& pose, const Vec3L& n) {
  const Mat3L r = rotationLD(pose.q);
  const Vec3L p = toLD(pose.p);
  const Vec3L nl = r.transpose() * n;  // local direction
  switch (g.type()) {
    case GeometryType::Sphere: return n.dot(p) + LD(g.template get<SphereGeometry<T>>().radius);
    case GeometryType::Capsule: {
      const auto& c = g.template get<CapsuleGeometry<T>>();
      return n.dot(p) + std::abs(nl.x()) * LD(c.halfHeight) + LD(c.radius);
    }
    case GeometryType::Box: return n.dot(p) + nl.cwiseAbs().dot(toLD(g.template get<BoxGeometry<T>>().halfExtents));
    case GeometryType::ConvexMesh: {
      const auto& c = g.template get<ConvexMeshGeometry<T>>();
      const Mat3L s = c.scale.toMatrix().template cast<LD>();
      LD best = -std::numeric_limits<LD>::infinity();
      for (const Vec3<T>& v : c.mesh->vertices) best = std::max(best, nl.dot(s * toLD(v)));
      return n.dot(p) + best;
    }
    default: ADD_FAILURE() << "no support function for this shape"; return 0;
  }
}

// Translation of geom0 along unit n needed to separate it from geom1: h1(n) + h0(-n).
template <class T>
LD pushAlong(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1, const Vec3L& n) {
  return supportLD(g1, p1, n) + supportLD(g0, p0, Vec3L(-n));
}

}  // namespace gq::test
