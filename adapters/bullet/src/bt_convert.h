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
template <class T> btTransform toBt(const Transform<T>& t) {
  const btQuaternion q(Real(t.q.x()), Real(t.q.y()), Real(t.q.z()), Real(t.q.w()));
  return btTransform(q, toBt(t.p.template cast<Real>()));
}

using gq::isFinite;  // gq's overloads for Eigen vectors stay visible beside Bullet's
inline bool isFinite(const btVector3& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}
// x * 0 is 0 for a finite x and NaN otherwise: one test for the 12 numbers instead of a branch each (no overflow,
// unlike a plain sum).
inline bool isFinite(const btTransform& t) {
  const btMatrix3x3& b = t.getBasis();
  const btVector3& o = t.getOrigin();
  Real zero = Real(0);
  for (const btVector3* v : {&o, &b[0], &b[1], &b[2]}) zero += v->x() * Real(0) + v->y() * Real(0) + v->z() * Real(0);
  return zero == Real(0);
}
// A local scaling gq can apply: finite, no zero factor.
inline bool isUsableScaling(const btVector3& s) {
  return isFinite(s) && s.x() != Real(0) && s.y() != Real(0) && s.z() != Real(0);
}

}  // namespace gq::bullet
