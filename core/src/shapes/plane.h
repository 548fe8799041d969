#pragma once
// The plane convention, written once.
#include "gq/transform.h"

namespace gq::detail {
// Outward normal (+X of its frame) of a plane at `pose`; the solid half-space is n.(x - pose.p) <= 0.
template <class T> Vec3<T> planeNormal(const Transform<T>& pose) { return pose.rotate(Vec3<T>::UnitX()); }
}  // namespace gq::detail
