#pragma once
// Shared by the hardening tests: one valid instance of every geometry type (cooked data built once per scalar type),
// every query family run on a pair, and bitwise comparison of outputs.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "gq/contacts.h"
#include "gq/cooking.h"
#include "gq/custom_shapes.h"
#include "gq/mesh_query.h"
#include "gq/query.h"

namespace gq::hardening {

using Scalars = ::testing::Types<float, double>;
template <class T> constexpr T kNaN = std::numeric_limits<T>::quiet_NaN();
template <class T> constexpr T kInf = std::numeric_limits<T>::infinity();

// Corners of the cube [-1,1]^3; bit i of the index picks the sign of coordinate i.
template <class T> std::vector<Vec3<T>> cubePoints() {
  std::vector<Vec3<T>> v;
  for (int i = 0; i < 8; ++i) v.emplace_back(T(i & 1 ? 1 : -1), T(i & 2 ? 1 : -1), T(i & 4 ? 1 : -1));
  return v;
}
// Closed cube surface over cubePoints(), outward winding.
inline std::vector<TriangleIndices> cubeTriangles() {
  return {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
          {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
}
// An octahedron's 6 points: a hull with non-axis-aligned faces.
template <class T> std::vector<Vec3<T>> octahedronPoints() {
  return {{T(1), T(0), T(0)}, {T(-1), T(0), T(0)}, {T(0), T(1), T(0)},
          {T(0), T(-1), T(0)}, {T(0), T(0), T(1)}, {T(0), T(0), T(-1)}};
}

// Cooked data shared by every test of a scalar type (cooked once; immutable afterwards).
template <class T> struct Cooked {
  std::shared_ptr<const ConvexMesh<T>> hull;
  std::shared_ptr<const TriangleMesh<T>> mesh;
  std::shared_ptr<const HeightField<T>> heightField;

  static const Cooked& get() {
    static const Cooked cooked = make();
    return cooked;
  }

 private:
  static Cooked make() {
    Cooked c;
    EXPECT_TRUE(cookConvexMesh(octahedronPoints<T>(), c.hull).ok());
    EXPECT_TRUE(cookTriangleMesh(cubePoints<T>(), cubeTriangles(), c.mesh).ok());
    // 9 x 9 samples of a bumpy surface h = 0.25 sin(r) cos(c), with two holes.
    HeightFieldDesc<T> desc;
    desc.rows = desc.columns = 9;
    for (std::uint32_t r = 0; r < 9; ++r)
      for (std::uint32_t col = 0; col < 9; ++col)
        desc.heights.push_back(T(0.25 * std::sin(double(r)) * std::cos(double(col))));
    desc.holes = {10, 33};
    EXPECT_TRUE(cookHeightField(desc, c.heightField).ok());
    return c;
  }
};

template <class T> HeightFieldGeometry<T> heightFieldGeometry() {
  return HeightFieldGeometry<T>(Cooked<T>::get().heightField, T(1), T(0.25), T(0.25));
}

// One valid geometry of each GeometryType, in enum order; the plane and the surfaces are unit-sized.
template <class T> std::vector<Geometry<T>> everyGeometry() {
  const Cooked<T>& c = Cooked<T>::get();
  CustomGeometry<T> cylinder;
  EXPECT_TRUE(makeCylinder(T(0.5), T(0.75), cylinder).ok());
  return {SphereGeometry<T>(T(0.5)),
          PlaneGeometry<T>(),
          CapsuleGeometry<T>(T(0.3), T(0.6)),
          BoxGeometry<T>(T(0.4), T(0.5), T(0.6)),
          ConvexMeshGeometry<T>(c.hull, MeshScale<T>(Vec3<T>(T(0.7), T(0.8), T(0.9)))),
          TriangleMeshGeometry<T>(c.mesh, MeshScale<T>(T(0.8))),
          heightFieldGeometry<T>(),
          cylinder};
}

// ---- Bitwise comparison: "outputs untouched" and "bitwise-identical results" -------------------------------------
template <class T> bool sameBits(const T& a, const T& b) {
  static_assert(std::is_arithmetic_v<T>);
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}
template <class T> bool sameBits(const Vec3<T>& a, const Vec3<T>& b) {
  return sameBits(a.x(), b.x()) && sameBits(a.y(), b.y()) && sameBits(a.z(), b.z());
}
template <class T> bool sameBits(const RaycastHit<T>& a, const RaycastHit<T>& b) {
  return sameBits(a.position, b.position) && sameBits(a.normal, b.normal) && sameBits(a.distance, b.distance) &&
         a.flags == b.flags && a.faceIndex == b.faceIndex && sameBits(a.u, b.u) && sameBits(a.v, b.v);
}
template <class T> bool sameBits(const SweepHit<T>& a, const SweepHit<T>& b) {
  return sameBits(a.position, b.position) && sameBits(a.normal, b.normal) && sameBits(a.distance, b.distance) &&
         a.flags == b.flags && a.faceIndex == b.faceIndex && a.initialOverlap == b.initialOverlap;
}
template <class T> bool sameBits(const PenetrationResult<T>& a, const PenetrationResult<T>& b) {
  return a.penetrating == b.penetrating && sameBits(a.direction, b.direction) && sameBits(a.depth, b.depth);
}
template <class T> bool sameBits(const DistanceResult<T>& a, const DistanceResult<T>& b) {
  return sameBits(a.distance, b.distance) && sameBits(a.point0, b.point0) && sameBits(a.point1, b.point1) &&
         sameBits(a.normal, b.normal);
}
template <class T> bool sameBits(const PointDistanceResult<T>& a, const PointDistanceResult<T>& b) {
  return sameBits(a.distance, b.distance) && sameBits(a.closestPoint, b.closestPoint) &&
         a.closestIndex == b.closestIndex;
}
template <class T> bool sameBits(const Bounds3<T>& a, const Bounds3<T>& b) {
  return sameBits(a.min, b.min) && sameBits(a.max, b.max);
}
template <class T> bool sameBits(const Triangle<T>& a, const Triangle<T>& b) {
  return sameBits(a.verts[0], b.verts[0]) && sameBits(a.verts[1], b.verts[1]) && sameBits(a.verts[2], b.verts[2]);
}

// A recognisable value no query computes: outputs start from it, and a rejected call must leave it.
template <class T> constexpr T kSentinel = T(-12345.5);
template <class T> Vec3<T> sentinelVec() { return Vec3<T>::Constant(kSentinel<T>); }
template <class T> RaycastHit<T> sentinelRaycastHit() {
  RaycastHit<T> h;
  h.position = h.normal = sentinelVec<T>();
  h.distance = h.u = h.v = kSentinel<T>;
  h.faceIndex = 4242;
  return h;
}
template <class T> SweepHit<T> sentinelSweepHit() {
  SweepHit<T> h;
  h.position = h.normal = sentinelVec<T>();
  h.distance = kSentinel<T>;
  h.faceIndex = 4242;
  h.initialOverlap = true;
  return h;
}
template <class T> PenetrationResult<T> sentinelPenetration() {
  PenetrationResult<T> r;
  r.penetrating = true;
  r.direction = sentinelVec<T>();
  r.depth = kSentinel<T>;
  return r;
}
template <class T> DistanceResult<T> sentinelDistance() {
  DistanceResult<T> r;
  r.distance = kSentinel<T>;
  r.point0 = r.point1 = r.normal = sentinelVec<T>();
  return r;
}
template <class T> PointDistanceResult<T> sentinelPointDistance() {
  PointDistanceResult<T> r;
  r.distance = kSentinel<T>;
  r.closestPoint = sentinelVec<T>();
  r.closestIndex = 4242;
  return r;
}
template <class T> Bounds3<T> sentinelBounds() { return Bounds3<T>::fromMinMax(sentinelVec<T>(), sentinelVec<T>()); }

}  // namespace gq::hardening
