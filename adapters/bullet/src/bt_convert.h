#pragma once
// Conversions between Bullet's and gq's math types (btScalar is the scalar of both sides).
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

}  // namespace gq::bullet
