#pragma once
// FCL geometry -> gq geometry. FCL's capsule, cylinder and cone lie along local Z with full length lz; gq's along
// local X with halfHeight, so their gq frame is the FCL frame turned by a quarter turn that takes X onto Z.
// Halfspace n.x <= d and Plane n.x = d become gq's plane (x = 0, solid x <= 0) in a frame taking +X onto n.
// Convex -> cookConvexMesh of its vertices; BVHModel (triangles) -> cookTriangleMesh (faceIndex = FCL's triangle
// id); Ellipsoid and TriangleP -> support-mapped custom shapes. Octrees and point clouds are not converted.
#include <cstdint>

#include "gq/geometry.h"
#include "gq/transform.h"

namespace fcl {
template <typename S> class CollisionGeometry;
}

namespace gq::fcl::detail {

enum class FclShape : std::uint8_t {
  Sphere, Box, Capsule, Cylinder, Cone, Ellipsoid, Convex, TriangleP, Halfspace, Plane, Mesh, Unsupported
};

template <class T> struct Converted {
  FclShape shape = FclShape::Unsupported;
  Geometry<T> geom;
  Transform<T> offset;  // the gq shape frame expressed in the FCL geometry's local frame
  bool hasOffset = false;    // offset is not the identity
  bool rotationFree = false; // a sphere: the pose's rotation does not matter
  bool isPlaneLike() const { return shape == FclShape::Halfspace || shape == FclShape::Plane; }
};

// False when gq has no counterpart (octree, point cloud, unfinished or empty model, invalid sizes).
template <class T> bool convert(const ::fcl::CollisionGeometry<T>* geometry, Converted<T>& out);
template <class T> void forget(const ::fcl::CollisionGeometry<T>* geometry);
void clearCache();

// FCL's Transform3 (an isometry) as a gq pose; the linear part is taken as a rotation (gq validates |q| = 1 within
// 1e-3, which an FCL rotation meets without re-normalising).
template <class T> Transform<T> toGq(const Eigen::Transform<T, 3, Eigen::Isometry>& tf) {
  return Transform<T>(tf.translation(), Quat<T>(tf.linear()));
}

// The world pose of the converted gq shape.
template <class T> Transform<T> shapePose(const Converted<T>& c, const Eigen::Transform<T, 3, Eigen::Isometry>& tf) {
  if (c.rotationFree) return Transform<T>(Vec3<T>(tf.translation()));
  return c.hasOffset ? toGq(tf) * c.offset : toGq(tf);
}

}  // namespace gq::fcl::detail
