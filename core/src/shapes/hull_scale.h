#pragma once
// A convex hull under MeshScale: x_shape = S * x_mesh with S = R diag(s) R^T (symmetric). Points map with S, a
// shape-space point back to the hull frame with S^-1, and plane normals from the hull frame with S^-T = S^-1
// (the inverse-transpose, then renormalised).
#include "gq/geometry.h"

namespace gq::detail {

template <class T> struct HullScale {
  Mat3<T> toShape;    // S
  Mat3<T> toMesh;     // S^-1
  bool identity;

  explicit HullScale(const MeshScale<T>& s) : identity(s.isIdentity()) {
    if (identity) {
      toShape.setIdentity();
      toMesh.setIdentity();
      return;
    }
    const Mat3<T> r = s.rotation.normalized().toRotationMatrix();
    toShape = r * s.scale.asDiagonal() * r.transpose();
    toMesh = r * s.scale.cwiseInverse().asDiagonal() * r.transpose();
  }

  Vec3<T> pointToShape(const Vec3<T>& v) const { return identity ? v : Vec3<T>(toShape * v); }
  Vec3<T> vectorToMesh(const Vec3<T>& v) const { return identity ? v : Vec3<T>(toMesh * v); }
  // Unit normal in shape space of a hull-frame plane normal.
  Vec3<T> normalToShape(const Vec3<T>& n) const { return identity ? n : Vec3<T>((toMesh * n).normalized()); }
};

}  // namespace gq::detail
