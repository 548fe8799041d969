// Sphere/cylinder overlap, in the cylinder's frame (axis X, radius r, half height hh): the solid cylinder's point
// nearest the centre clamps its axial coordinate to [-hh, hh] and its distance from the axis to [0, r], so the
// centre's distance to the cylinder is |(axial excess, radial excess)|.
#include <algorithm>
#include <cmath>

#include "overlap/overlap.h"

namespace gq::detail {

template <class T> bool overlapSphereCylinder(const Vec3<T>& c, T radius, T cylinderRadius, T halfHeight) {
  const T axial = std::max(std::abs(c.x()) - halfHeight, T(0));
  const T radial = std::max(std::sqrt(c.y() * c.y() + c.z() * c.z()) - cylinderRadius, T(0));
  return axial * axial + radial * radial <= radius * radius;
}

template bool overlapSphereCylinder<float>(const Vec3<float>&, float, float, float);
template bool overlapSphereCylinder<double>(const Vec3<double>&, double, double, double);

}  // namespace gq::detail
