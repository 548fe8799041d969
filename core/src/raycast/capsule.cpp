// Ray vs capsule (axis local X). The capsule is the union of two end spheres and a finite cylinder; from an
// outside origin, the first entry into the union is the smallest entry into its parts (the cylinder's flat ends
// lie inside the spheres, so only its side counts, restricted to |x| <= halfHeight).
#include <limits>

#include "raycast/raycast.h"
#include "shapes/ray_hit.h"
#include "shapes/ray_sphere.h"
#include "shapes/segment.h"
#include "common/unit_vector.h"

namespace gq::detail {
namespace {

// Entry into the infinite cylinder y^2 + z^2 = r^2 from an origin outside it: the closest-approach form of
// raySphereEntry in the (y, z) plane.
template <class T> bool rayCylinderSideEntry(const Vec3<T>& o, const Vec3<T>& d, T radius, T& t) {
  const Eigen::Matrix<T, 2, 1> m(o.y(), o.z()), e(d.y(), d.z());
  const T a = e.squaredNorm();
  if (!(a > T(0))) return false;  // parallel to the axis: only the caps can be hit
  const T b = m.dot(e);
  const T c = m.squaredNorm() - radius * radius;
  if (c <= T(0) || b >= T(0)) return false;  // starts within the infinite cylinder, or moves away from it
  const Eigen::Matrix<T, 2, 1> q = m - (b / a) * e;
  const T h2 = radius * radius - q.squaredNorm();
  if (h2 < T(0)) return false;
  t = c / (-b + std::sqrt(a * h2));
  return true;
}

}  // namespace

template <class T>
std::uint32_t raycastCapsule(const CapsuleGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray,
                             RaycastHit<T>* hits) {
  const Vec3<T> o = pose.transformInv(ray.origin);
  const Vec3<T> d = pose.rotateInv(ray.dir);
  const T r = g.radius, hh = g.halfHeight;
  if ((o - closestPointOnCapsuleAxis(hh, o)).squaredNorm() <= r * r) {
    writeInsideHit(ray, hits[0]);
    return 1;
  }
  T best = std::numeric_limits<T>::infinity();
  T t;
  if (rayCylinderSideEntry(o, d, r, t) && std::abs(o.x() + t * d.x()) <= hh) best = t;
  const Vec3<T> capCenter(hh, T(0), T(0));
  if (raySphereEntry(Vec3<T>(o - capCenter), d, r, t)) best = std::min(best, t);
  if (raySphereEntry(Vec3<T>(o + capCenter), d, r, t)) best = std::min(best, t);
  if (best == std::numeric_limits<T>::infinity() || best > ray.maxDist) return 0;
  const auto normal = [&] {
    const Vec3<T> p = o + best * d;
    return pose.rotate(unitOr(Vec3<T>(p - closestPointOnCapsuleAxis(hh, p)), Vec3<T>(-d)));
  };
  writeSurfaceHit(ray, best, kInvalidFaceIndex, normal, hits[0]);
  return 1;
}

template std::uint32_t raycastCapsule<float>(const CapsuleGeometry<float>&, const Transform<float>&, const RayQuery<float>&, RaycastHit<float>*);
template std::uint32_t raycastCapsule<double>(const CapsuleGeometry<double>&, const Transform<double>&, const RayQuery<double>&, RaycastHit<double>*);

}  // namespace gq::detail
