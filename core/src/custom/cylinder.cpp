// Cylinder along local X: |x| <= h, y^2 + z^2 <= r^2.
// Support: (sign(d.x) h, r (d.y, d.z) / |(d.y, d.z)|). Raycast: the slab |x| <= h clipped with the infinite
// cylinder, whose entry/exit are the roots of (o_yz + t d_yz)^2 = r^2. Overlap with a sphere: closed form
// (overlap/sphere_cylinder.cpp); with a box: the certificates of overlap/cylinder_box.cpp, which decide most poses
// without GJK. Distance to a separated box: the certified closest pairs of distance/box_cylinder.cpp.
#include <cmath>
#include <limits>

#include "common/unit_vector.h"
#include "custom/ray_interval.h"
#include "distance/distance.h"
#include "gq/custom_shapes.h"
#include "overlap/overlap.h"

namespace gq {
namespace {
enum Surface { kCap = 0, kSide = 1 };
}

template <class T> Bounds3<T> CylinderCallbacks<T>::localBounds() const {
  return Bounds3<T>::fromCenterExtents(Vec3<T>::Zero(), Vec3<T>(halfHeight_, radius_, radius_));
}

// The rim direction (d.y, d.z) / |(d.y, d.z)|; where its squared length is subnormal or overflows, by tryUnit: GJK's
// directions reach any magnitude (concentric shapes give tiny ones), and a float component under 1e-19 or over 1e19
// lost the rim (a float sphere inside a cylinder 1e30 wide was "apart").
template <class T> Vec3<T> CylinderCallbacks<T>::support(const Vec3<T>& d) const {
  const T x = d.x() < T(0) ? -halfHeight_ : halfHeight_;
  const T radialSq = d.y() * d.y() + d.z() * d.z();
  if (radialSq >= std::numeric_limits<T>::min() && radialSq <= std::numeric_limits<T>::max()) {
    const T radial = std::sqrt(radialSq);
    return Vec3<T>(x, radius_ * d.y() / radial, radius_ * d.z() / radial);
  }
  Vec3<T> rim;
  if (!detail::tryUnit(Vec3<T>(T(0), d.y(), d.z()), rim)) return Vec3<T>(x, T(0), T(0));
  return Vec3<T>(x, radius_ * rim.y(), radius_ * rim.z());
}

template <class T>
bool CylinderCallbacks<T>::raycast(const Vec3<T>& o, const Vec3<T>& d, T maxDist, HitFlags flags,
                                   RaycastHit<T>& hit) const {
  detail::RayInterval<T> r;
  detail::clipSlab(r, o.x(), d.x(), -halfHeight_, halfHeight_, kCap);
  const T a = d.y() * d.y() + d.z() * d.z();
  const T b = o.y() * d.y() + o.z() * d.z();
  const T c = o.y() * o.y() + o.z() * o.z() - radius_ * radius_;
  if (a == T(0)) {
    if (c > T(0)) return false;  // parallel to the axis, outside the side
  } else {
    // b^2 - a c = r^2 |d_yz|^2 - (o_yz x d_yz)^2 (Lagrange's identity): no cancellation for rays grazing the side.
    const T cross = o.y() * d.z() - o.z() * d.y();
    const T disc = radius_ * radius_ * a - cross * cross;
    if (disc < T(0)) return false;
    // Roots (-b -+ sqrt(disc)) / a, the first through c / (-b + sqrt) when that avoids cancellation.
    const T s = std::sqrt(disc);
    const T q = b >= T(0) ? -(b + s) : -(b - s);
    T t0 = q / a, t1 = q != T(0) ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    r.clip(t0, t1, kSide);
  }
  const auto normalAt = [&](int surface, const Vec3<T>& p) {
    if (surface == kCap) return Vec3<T>(d.x() < T(0) ? T(1) : T(-1), T(0), T(0));
    return Vec3<T>(Vec3<T>(T(0), p.y(), p.z()).normalized());
  };
  return detail::writeIntervalHit(r, o, d, maxDist, flags, normalAt, hit);
}

namespace {

// The cylinder (axis = local X) in the frame of a box at `boxPose` (given in the cylinder's frame): centre
// R^T (0 - t), axis R^T e_x, as the box/cylinder kernels take it.
template <class T> struct CylinderInBox {
  Vec3<T> centre, axis;
};
template <class T> CylinderInBox<T> inBoxFrame(const Transform<T>& boxPose) {
  return {boxPose.transformInv(Vec3<T>::Zero()), boxPose.rotateInv(Vec3<T>::UnitX())};
}

}  // namespace

template <class T>
bool CylinderCallbacks<T>::overlap(const Geometry<T>& other, const Transform<T>& otherPose, bool& overlapping) const {
  if (other.type() == GeometryType::Sphere) {
    overlapping = detail::overlapSphereCylinder(otherPose.p, other.template get<SphereGeometry<T>>().radius, radius_,
                                                halfHeight_);
    return true;
  }
  if (other.type() != GeometryType::Box) return false;
  const Vec3<T>& h = other.template get<BoxGeometry<T>>().halfExtents;
  const CylinderInBox<T> c = inBoxFrame(otherPose);
  switch (detail::cylinderBoxCertificate(c.centre, c.axis, radius_, halfHeight_, h)) {
    case detail::OverlapCertificate::Apart: overlapping = false; return true;
    case detail::OverlapCertificate::Overlapping: overlapping = true; return true;
    case detail::OverlapCertificate::Unknown: break;
  }
  return false;
}

template <class T>
bool CylinderCallbacks<T>::distance(const Geometry<T>& other, const Transform<T>& otherPose,
                                    DistanceResult<T>& result) const {
  if (other.type() != GeometryType::Box) return false;
  const Vec3<T>& h = other.template get<BoxGeometry<T>>().halfExtents;
  const CylinderInBox<T> c = inBoxFrame(otherPose);
  DistanceResult<T> inBox;  // the box's frame, the box first
  if (detail::distanceBoxCylinderLocal(h, c.centre, c.axis, radius_, halfHeight_, inBox) !=
      detail::BoxCylinderDistance::Separated)
    return false;
  result.distance = inBox.distance;
  result.normal = -otherPose.rotate(inBox.normal);
  result.point0 = otherPose.transform(inBox.point1);
  result.point1 = otherPose.transform(inBox.point0);
  return true;
}

template <class T> Status makeCylinder(T radius, T halfHeight, CustomGeometry<T>& out) {
  if (!(std::isfinite(radius) && std::isfinite(halfHeight) && radius > T(0) && halfHeight > T(0)))
    return Status::invalid("cylinder radius and halfHeight must be finite and > 0");
  out = CustomGeometry<T>(std::make_shared<CylinderCallbacks<T>>(radius, halfHeight));
  return {};
}

template class CylinderCallbacks<float>;
template class CylinderCallbacks<double>;
template Status makeCylinder<float>(float, float, CustomGeometry<float>&);
template Status makeCylinder<double>(double, double, CustomGeometry<double>&);

}  // namespace gq
