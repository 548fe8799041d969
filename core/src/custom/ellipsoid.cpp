// Ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 <= 1 (radii (a, b, c), D = diag(a, b, c)).
// Support along d: the point D u with u the unit vector along D d, i.e. D^2 d / |D d|. Raycast: in the unit sphere's
// space x' = D^-1 x the ray is o' + t d' (d' = D^-1 d, not unit, t unchanged): |o' + t d'|^2 = 1, a quadratic
// a t^2 + 2 b t + c = 0 whose discriminant is formed as a - |o' x d'|^2 (Lagrange's identity) and whose roots are
// taken without cancellation. Normal: the gradient D^-2 x at the hit, normalised.
#include <cmath>
#include <utility>

#include "custom/ray_interval.h"
#include "gq/custom_shapes.h"

namespace gq {

// d scaled by its largest component first: GJK's directions reach any magnitude, and |D d| of a tiny or huge d
// under- or overflows. shape_ = D / max radius keeps |shape_ d| in [min/max radius, sqrt 3].
template <class T> Vec3<T> EllipsoidCallbacks<T>::support(const Vec3<T>& dir) const {
  const T largest = dir.cwiseAbs().maxCoeff();
  if (!(largest > T(0)) || !std::isfinite(largest)) return Vec3<T>(radii_.x(), T(0), T(0));
  const Vec3<T> scaled = shape_.cwiseProduct(dir / largest);  // D d, up to a positive factor
  return radii_.cwiseProduct(scaled / scaled.norm());
}

template <class T>
bool EllipsoidCallbacks<T>::raycast(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist, HitFlags flags,
                                    RaycastHit<T>& hit) const {
  const Vec3<T> o = origin.cwiseQuotient(radii_), d = unitDir.cwiseQuotient(radii_);
  const T a = d.squaredNorm(), b = o.dot(d), c = o.squaredNorm() - T(1);
  const T disc = a - o.cross(d).squaredNorm();  // b^2 - a c
  if (disc < T(0)) return false;
  // Roots (-b -+ s) / a; the one without cancellation first, the other through the product c / a.
  const T s = std::sqrt(disc);
  const T q = b >= T(0) ? -(b + s) : -(b - s);
  T t0 = q / a, t1 = q != T(0) ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  detail::RayInterval<T> r;
  r.clip(t0, t1, 0);
  const auto normalAt = [&](int, const Vec3<T>& p) {
    return Vec3<T>(p.cwiseQuotient(radii_.cwiseProduct(radii_)).normalized());
  };
  return detail::writeIntervalHit(r, origin, unitDir, maxDist, flags, normalAt, hit);
}

template <class T> Status makeEllipsoid(const Vec3<T>& radii, CustomGeometry<T>& out) {
  if (!(isFinite(radii) && radii.minCoeff() > T(0)))
    return Status::invalid("ellipsoid radii must be finite and > 0");
  out = CustomGeometry<T>(std::make_shared<EllipsoidCallbacks<T>>(radii));
  return {};
}

template class EllipsoidCallbacks<float>;
template class EllipsoidCallbacks<double>;
template Status makeEllipsoid<float>(const Vec3<float>&, CustomGeometry<float>&);
template Status makeEllipsoid<double>(const Vec3<double>&, CustomGeometry<double>&);

}  // namespace gq
