#pragma once
// FCL geometry -> gq geometry for one call. FCL's capsule, cylinder and cone lie along local Z with full length lz;
// gq's along local X with halfHeight, so their gq frame is the FCL frame turned by a quarter turn that takes X onto Z.
// Halfspace n.x <= d and Plane n.x = d become gq's plane (x = 0, solid x <= 0) in a frame taking +X onto n.
// Primitives (sphere, box, capsule, cylinder, cone, ellipsoid, triangle, planes) are built in the Converted object
// itself, without allocating: the support callbacks of the custom shapes live inside it and the gq geometry borrows
// them. Convex (-> cookConvexMesh of its vertices) and triangle BVHModels (-> cookTriangleMesh, faceIndex = FCL's
// triangle id) come from the cache (geometry_cache.h). Octrees and point clouds are not converted.
#include <cstdint>
#include <variant>

#include "gq/custom_shapes.h"
#include "gq/geometry.h"
#include "gq/tolerances.h"
#include "gq/transform.h"
#include "support_shapes.h"

namespace fcl {
template <typename S> class CollisionGeometry;
}
namespace gq::detail {
template <class T> struct ConvexShape;  // gjk/gjk.h
}

namespace gq::fcl::detail {

enum class FclShape : std::uint8_t {
  Sphere, Box, Capsule, Cylinder, Cone, Ellipsoid, Convex, TriangleP, Halfspace, Plane, Mesh, Unsupported
};

// What a conversion found: a gq geometry, input gq (and FCL) cannot answer (null, NaN or non-positive sizes, an
// empty or unfinished BVHModel: the call writes nothing), or a type gq does not model (FCL answers it).
enum class Conversion : std::uint8_t { Ok, Invalid, NotModelled };

// How the gq shape frame sits in the FCL geometry's frame.
enum class Frame : std::uint8_t {
  Same,             // box, convex, mesh, ellipsoid, triangle
  TranslationOnly,  // sphere: the rotation does not matter
  XOntoZ,           // capsule, cylinder, cone: gq's axis X along FCL's Z (R_y(-90 deg))
  Offset,           // planes: `offset`
};

// The stand-in that findOverlapTriangleMesh takes for a shape it does not take itself (pair_kernels.h), in the
// shape's local frame: a box or sphere `volume` centred at `centre`.
template <class T> struct CandidateVolume {
  Geometry<T> volume;
  Vec3<T> centre = Vec3<T>::Zero();
};

// What the cache (geometry_cache.h) cooked once for a Convex or a BVHModel: the gq geometry and, for a Convex, its
// candidate volume and its GJK support mapping at the identity pose (the table of start vertices found).
template <class T> struct Cooked {
  FclShape shape = FclShape::Unsupported;
  const Geometry<T>* geometry = nullptr;
  const CandidateVolume<T>* candidate = nullptr;
  const gq::detail::ConvexShape<T>* support = nullptr;
};

template <class T> class Converted {
 public:
  Converted() = default;
  Converted(const Converted&) = delete;  // the geometry may borrow this object's callbacks
  Converted& operator=(const Converted&) = delete;

  FclShape shape = FclShape::Unsupported;
  Frame frame = Frame::Same;
  Transform<T> offset;  // Frame::Offset: the gq shape frame expressed in the FCL geometry's local frame

  const Geometry<T>& geometry() const { return *geometry_; }
  bool isPlaneLike() const { return shape == FclShape::Halfspace || shape == FclShape::Plane; }
  bool isMesh() const { return shape == FclShape::Mesh; }
  // A closed convex solid (or a half-space): gq's pair kernels answer it directly.
  bool isSolid() const { return shape != FclShape::Mesh && shape != FclShape::Plane && shape != FclShape::Unsupported; }

  void setLocal(const Geometry<T>& g) {
    local_ = g;
    geometry_ = &local_;
  }
  // Custom shape whose callbacks live here (no allocation); the geometry holds a non-owning pointer to them.
  template <class Callbacks, class... Args> void setCallbacks(const Args&... args) {
    const Callbacks& c = callbacks_.template emplace<Callbacks>(args...);
    local_ = CustomGeometry<T>(std::shared_ptr<const CustomGeometryCallbacks<T>>(std::shared_ptr<const void>(), &c));
    geometry_ = &local_;
  }
  // Cached geometry, kept alive by the cache for the duration of the call (see geometry_cache.h).
  void setCached(const Cooked<T>& cooked) {
    shape = cooked.shape;
    geometry_ = cooked.geometry;
    candidate_ = cooked.candidate;
    support_ = cooked.support;
  }
  const CandidateVolume<T>* cachedCandidate() const { return candidate_; }
  const gq::detail::ConvexShape<T>* cachedSupport() const { return support_; }

 private:
  Geometry<T> local_;
  const Geometry<T>* geometry_ = &local_;
  const CandidateVolume<T>* candidate_ = nullptr;
  const gq::detail::ConvexShape<T>* support_ = nullptr;
  std::variant<std::monostate, CylinderCallbacks<T>, ConeCallbacks<T>, EllipsoidCallbacks<T>, TriangleCallbacks<T>>
      callbacks_;
};

template <class T> Conversion convert(const ::fcl::CollisionGeometry<T>* geometry, Converted<T>& out);
template <class T> void forget(const ::fcl::CollisionGeometry<T>* geometry);
void clearCache();

// FCL's Transform3 as a gq pose. The quaternion of a rotation matrix is unit up to round-off; a linear part that
// is not a rotation (scaled, NaN) gives a non-unit quaternion, which poseUsable rejects.
template <class T> Transform<T> toGq(const Eigen::Transform<T, 3, Eigen::Isometry>& tf) {
  return Transform<T>(tf.translation(), Quat<T>(tf.linear()));
}

// Every entry of both transforms finite: x * 0 is 0 for a finite x and NaN otherwise (no overflow, unlike a sum of
// the entries), and Eigen reduces the contiguous 4x4 arrays in SIMD packets (~25 instructions for the pair; a scalar
// loop over the two 3x4 blocks cost ~70). Forced inline: as a call it cost the sphere pairs ~10 more.
template <class T>
[[gnu::always_inline]] inline bool isFiniteTransforms(const Eigen::Transform<T, 3, Eigen::Isometry>& a,
                                                      const Eigen::Transform<T, 3, Eigen::Isometry>& b) {
  return (a.matrix().array() * T(0) + b.matrix().array() * T(0)).sum() == T(0);
}

// The world pose of the converted gq shape.
template <class T> Transform<T> shapePose(const Converted<T>& c, const Eigen::Transform<T, 3, Eigen::Isometry>& tf) {
  switch (c.frame) {
    case Frame::TranslationOnly: return Transform<T>(Vec3<T>(tf.translation()));
    case Frame::XOntoZ: {  // R R_y(-90 deg) = [R e_z, R e_y, -R e_x]
      Mat3<T> r;
      r << tf.linear().col(2), tf.linear().col(1), -tf.linear().col(0);
      return Transform<T>(tf.translation(), Quat<T>(r));
    }
    case Frame::Offset: return toGq(tf) * c.offset;
    case Frame::Same: break;
  }
  return toGq(tf);
}

// The pose's rotation is unit within the façade's tolerance (tol::kUnitQuaternion): false when FCL's linear part
// was not a rotation (scaled, sheared) or not finite.
template <class T> bool isRotation(const Transform<T>& pose) {
  constexpr T lo = T((1 - tol::kUnitQuaternion) * (1 - tol::kUnitQuaternion));
  constexpr T hi = T((1 + tol::kUnitQuaternion) * (1 + tol::kUnitQuaternion));
  const T n2 = pose.q.squaredNorm();
  return n2 >= lo && n2 <= hi;
}

}  // namespace gq::fcl::detail
