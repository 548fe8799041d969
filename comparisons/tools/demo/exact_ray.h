#pragma once
// Exact ray distances in long double, in the shape's local frame, with the spec's raycast rules: a ray starting
// inside a solid reports distance 0; a plane is single-sided (origin behind it: no hit). Returns -1 on a miss.
#include <Eigen/Core>

namespace gq::demo {

using Real = long double;
using VecR = Eigen::Matrix<Real, 3, 1>;

Real exactRaySphere(const VecR& o, const VecR& d, Real radius, Real maxDist);
Real exactRayPlane(const VecR& o, const VecR& d, Real maxDist);
Real exactRayBox(const VecR& o, const VecR& d, const VecR& halfExtents, Real maxDist);
Real exactRayCapsule(const VecR& o, const VecR& d, Real radius, Real halfHeight, Real maxDist);

}  // namespace gq::demo
