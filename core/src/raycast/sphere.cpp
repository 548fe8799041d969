// Ray vs sphere: inside test, then the closest-approach entry root (shapes/ray_sphere.h).
#include "raycast/raycast.h"
#include "shapes/ray_hit.h"
#include "shapes/ray_sphere.h"
#include "common/unit_vector.h"

namespace gq::detail {

template <class T>
std::uint32_t raycastSphere(const SphereGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray,
                            RaycastHit<T>* hits) {
  const Vec3<T> m = ray.origin - pose.p;
  if (m.squaredNorm() <= g.radius * g.radius) {
    writeInsideHit(ray, hits[0]);
    return 1;
  }
  T t;
  if (!raySphereEntry(m, ray.dir, g.radius, t) || t > ray.maxDist) return 0;
  const auto normal = [&] { return unitOr(Vec3<T>(m + t * ray.dir), Vec3<T>(-ray.dir)); };
  writeSurfaceHit(ray, t, kInvalidFaceIndex, normal, hits[0]);
  return 1;
}

template std::uint32_t raycastSphere<float>(const SphereGeometry<float>&, const Transform<float>&, const RayQuery<float>&, RaycastHit<float>*);
template std::uint32_t raycastSphere<double>(const SphereGeometry<double>&, const Transform<double>&, const RayQuery<double>&, RaycastHit<double>*);

}  // namespace gq::detail
