#pragma once
// Conversions between Bullet's and gq's math types (btScalar is the scalar of both sides), and the finiteness
// checks the adapter applies to Bullet's numbers before converting them.
#include <cmath>

#include <LinearMath/btTransform.h>

#include "gq/math.h"
#include "gq/transform.h"

namespace gq::bullet {

using Real = btScalar;
using V3 = Vec3<Real>;
using Pose = Transform<Real>;

inline V3 toGq(const btVector3& v) { return V3(v.x(), v.y(), v.z()); }
inline btVector3 toBt(const V3& v) { return btVector3(v.x(), v.y(), v.z()); }

inline Pose toGq(const btTransform& t) {
  const btQuaternion q = t.getRotation();
  Quat<Real> r(q.w(), q.x(), q.y(), q.z());
  r.normalize();
  return Pose(toGq(t.getOrigin()), r);
}

using gq::isFinite;  // gq's overloads for Eigen vectors stay visible beside Bullet's
inline bool isFinite(const btVector3& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}
inline bool isFinite(const btTransform& t) {
  const btMatrix3x3& b = t.getBasis();
  return isFinite(t.getOrigin()) && isFinite(b[0]) && isFinite(b[1]) && isFinite(b[2]);
}
// A local scaling gq can apply: finite, no zero factor.
inline bool isUsableScaling(const btVector3& s) {
  return isFinite(s) && s.x() != Real(0) && s.y() != Real(0) && s.z() != Real(0);
}

}  // namespace gq::bullet
