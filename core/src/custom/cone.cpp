// Cone along local X: base disk of radius r at x = -h, apex at x = +h. With k = r / (2h) the solid is
// x >= -h and y^2 + z^2 <= k^2 (h - x)^2 with h - x >= 0 (one nappe of the double cone).
// Support: the apex or the base rim point along d, whichever is farther. Raycast: the base slab clipped with the
// nappe; f(t) = |o_yz + t d_yz|^2 - k^2 (w0 - t d.x)^2 (w = h - x) is a quadratic A t^2 + 2 B t + C whose
// non-positive set, restricted to w >= 0, is the nappe's interval. Its discriminant is evaluated in a cancellation-free
// form (see clipNappe).
#include <cmath>
#include <limits>

#include "common/unit_vector.h"
#include "custom/ray_interval.h"
#include "gq/custom_shapes.h"

namespace gq {
namespace {
enum Surface { kBase = 0, kSide = 1 };

// Interval of t where the line lies in the nappe: {f <= 0} intersected with {w = w0 - t dx >= 0}.
template <class T> void clipNappe(detail::RayInterval<T>& r, const Vec3<T>& o, const Vec3<T>& d, T h, T k) {
  const T k2 = k * k, w0 = h - o.x();
  const T A = d.y() * d.y() + d.z() * d.z() - k2 * d.x() * d.x();
  const T B = o.y() * d.y() + o.z() * d.z() + k2 * w0 * d.x();
  const T C = o.y() * o.y() + o.z() * o.z() - k2 * w0 * w0;
  constexpr T kInf = std::numeric_limits<T>::infinity();
  // {w >= 0}: w0 - t dx >= 0.
  T wLo = -kInf, wHi = kInf;
  if (d.x() > T(0)) wHi = w0 / d.x();
  else if (d.x() < T(0)) wLo = w0 / d.x();
  else if (w0 < T(0)) { r.exit = -kInf; return; }
  const auto clipPiece = [&](T lo, T hi) {
    const T a = std::max(lo, wLo), b = std::min(hi, wHi);
    if (a <= b) { r.clip(a, b, kSide); return true; }
    return false;
  };
  if (A == T(0)) {
    if (B == T(0)) { if (C > T(0) || !clipPiece(-kInf, kInf)) r.exit = -kInf; return; }
    const T t = -C / (T(2) * B);
    if (!(B > T(0) ? clipPiece(-kInf, t) : clipPiece(t, kInf))) r.exit = -kInf;
    return;
  }
  // B^2 - AC with the k^4 terms cancelled symbolically: k^2 |w0 d_yz + dx o_yz|^2 - (o_yz x d_yz)^2. On the axis
  // (apex double root) both terms vanish exactly instead of leaving rounding noise of order eps, whose square root
  // moved the apex hit by sqrt(eps).
  const T my = w0 * d.y() + d.x() * o.y(), mz = w0 * d.z() + d.x() * o.z();
  const T cross = o.y() * d.z() - o.z() * d.y();
  const T disc = k2 * (my * my + mz * mz) - cross * cross;
  if (disc < T(0)) {
    if (A > T(0) || !clipPiece(-kInf, kInf)) r.exit = -kInf;
    return;
  }
  const T s = std::sqrt(disc);
  const T q = B >= T(0) ? -(B + s) : -(B - s);
  T t0 = q / A, t1 = q != T(0) ? C / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  if (A > T(0)) {
    if (!clipPiece(t0, t1)) r.exit = -kInf;
  } else if (!clipPiece(-kInf, t0) && !clipPiece(t1, kInf)) {
    r.exit = -kInf;  // A < 0: two half-lines, one per nappe
  }
}
}  // namespace

template <class T> Bounds3<T> ConeCallbacks<T>::localBounds() const {
  return Bounds3<T>::fromCenterExtents(Vec3<T>::Zero(), Vec3<T>(halfHeight_, radius_, radius_));
}

// The apex's value d.x h against the base rim's -d.x h + r |d_yz|. GJK's directions reach any magnitude, whose
// squares or products can leave the range (a float component under 1e-19 or over 1e19): then on the unit direction
// (tryUnit), with the rim direction by tryUnit too.
template <class T> Vec3<T> ConeCallbacks<T>::support(const Vec3<T>& d) const {
  const Vec3<T> apex(halfHeight_, T(0), T(0));
  const T radialSq = d.y() * d.y() + d.z() * d.z();
  if (radialSq >= std::numeric_limits<T>::min() && radialSq <= std::numeric_limits<T>::max()) {
    const T radial = std::sqrt(radialSq);
    const T atApex = d.x() * halfHeight_, atRim = -d.x() * halfHeight_ + radius_ * radial;
    if (std::isfinite(atApex) && std::isfinite(atRim)) {
      if (atApex >= atRim) return apex;
      return Vec3<T>(-halfHeight_, radius_ * d.y() / radial, radius_ * d.z() / radial);
    }
  }
  Vec3<T> u, rim;
  if (!detail::tryUnit(d, u)) return apex;
  const Vec3<T> yz(T(0), u.y(), u.z());
  const bool round = detail::tryUnit(yz, rim);
  const T radial = round ? rim.dot(yz) : T(0);
  if (u.x() * halfHeight_ >= -u.x() * halfHeight_ + radius_ * radial) return apex;
  if (!round) return Vec3<T>(-halfHeight_, T(0), T(0));
  return Vec3<T>(-halfHeight_, radius_ * rim.y(), radius_ * rim.z());
}

template <class T>
bool ConeCallbacks<T>::raycast(const Vec3<T>& o, const Vec3<T>& d, T maxDist, HitFlags flags, RaycastHit<T>& hit) const {
  const T k = radius_ / (T(2) * halfHeight_);
  detail::RayInterval<T> r;
  detail::clipSlab(r, o.x(), d.x(), -halfHeight_, halfHeight_, kBase);
  clipNappe(r, o, d, halfHeight_, k);
  const auto normalAt = [&](int surface, const Vec3<T>& p) {
    if (surface == kBase) return Vec3<T>(-T(1), T(0), T(0));
    // Gradient of y^2 + z^2 - k^2 (h - x)^2; at the apex it vanishes: report the axis.
    const Vec3<T> g(k * k * (halfHeight_ - p.x()), p.y(), p.z());
    return g.squaredNorm() > T(0) ? Vec3<T>(g.normalized()) : Vec3<T>(Vec3<T>::UnitX());
  };
  return detail::writeIntervalHit(r, o, d, maxDist, flags, normalAt, hit);
}

template <class T> Status makeCone(T radius, T halfHeight, CustomGeometry<T>& out) {
  if (!(std::isfinite(radius) && std::isfinite(halfHeight) && radius > T(0) && halfHeight > T(0)))
    return Status::invalid("cone radius and halfHeight must be finite and > 0");
  out = CustomGeometry<T>(std::make_shared<ConeCallbacks<T>>(radius, halfHeight));
  return {};
}

template class ConeCallbacks<float>;
template class ConeCallbacks<double>;
template Status makeCone<float>(float, float, CustomGeometry<float>&);
template Status makeCone<double>(double, double, CustomGeometry<double>&);

}  // namespace gq
