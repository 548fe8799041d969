// Sphere vs cylinder with the sphere's centre inside the cylinder (its frame: axis X, radius r, half height hh): the
// sphere leaves through the cap or the side with the least room (depth = radius + that room). The outside cases are
// inline (distance.h).
#include <algorithm>
#include <cmath>

#include "distance/distance.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T> DistanceResult<T> distanceSphereInsideCylinder(T cx, T cy, T cz, T r0, T r, T hh) {
  const Vec3<T> c(cx, cy, cz);
  DistanceResult<T> local;
  const T rho = std::sqrt(c.y() * c.y() + c.z() * c.z());
  const Vec3<T> radial = rho > T(0) ? Vec3<T>(T(0), c.y() / rho, c.z() / rho) : Vec3<T>(Vec3<T>::UnitY());
  const T axialRoom = hh - std::abs(c.x()), radialRoom = r - rho;
  Vec3<T> exit = c;
  if (axialRoom <= radialRoom) {
    const T side = c.x() < T(0) ? T(-1) : T(1);
    exit.x() = side * hh;
    local.normal = -side * Vec3<T>::UnitX();  // moving the cylinder this way pushes the sphere out of the cap
  } else {
    exit = Vec3<T>(c.x(), T(0), T(0)) + r * radial;
    local.normal = -radial;
  }
  local.distance = -(std::min(axialRoom, radialRoom) + r0);
  local.point0 = c + r0 * local.normal;
  local.point1 = exit;
  return local;
}

template DistanceResult<float> distanceSphereInsideCylinder<float>(float, float, float, float, float, float);
template DistanceResult<double> distanceSphereInsideCylinder<double>(double, double, double, double, double, double);

}  // namespace gq::kernels
