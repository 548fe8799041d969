// Sphere vs box, in the box frame: outside, the closest box point is the clamped centre; inside, the sphere leaves
// through the nearest face (depth = radius + distance of the centre to that face).
#include <cmath>

#include "distance/distance.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

// Centre c inside the box: the face axis with the least room h_i - |c_i|.
template <class T> DistanceResult<T> distanceSphereInsideBox(T cx, T cy, T cz, T r, T hx, T hy, T hz) {
  const Vec3<T> c(cx, cy, cz), h(hx, hy, hz);
  DistanceResult<T> local;
  Eigen::Index axis;
  const Vec3<T> room = h - c.cwiseAbs();
  room.minCoeff(&axis);
  const T side = c[axis] < T(0) ? T(-1) : T(1);
  Vec3<T> face = c;
  face[axis] = side * h[axis];
  local.normal = -side * Vec3<T>::Unit(axis);  // moving the box this way pushes the sphere out of that face
  local.distance = -(room[axis] + r);
  local.point0 = c + r * local.normal;
  local.point1 = face;
  return local;
}

template <class T>
void distanceSphereBox(const SphereGeometry<T>& g0, const Transform<T>& pose0, const BoxGeometry<T>& g1,
                       const Transform<T>& pose1, DistanceResult<T>& out) {
  DistanceResult<T> local;
  distanceSphereBox(pose1.transformInv(pose0.p), g0.radius, g1.halfExtents, local);
  out.distance = local.distance;
  out.normal = pose1.rotate(local.normal);
  out.point0 = pose1.transform(local.point0);
  out.point1 = pose1.transform(local.point1);
}

template void distanceSphereBox<float>(const SphereGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&, DistanceResult<float>&);
template void distanceSphereBox<double>(const SphereGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&, DistanceResult<double>&);
template DistanceResult<float> distanceSphereInsideBox<float>(float, float, float, float, float, float, float);
template DistanceResult<double> distanceSphereInsideBox<double>(double, double, double, double, double, double, double);

}  // namespace gq::kernels
