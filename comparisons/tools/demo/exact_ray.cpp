#include "exact_ray.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gq::demo {
namespace {

constexpr Real kMiss = -1;

Real within(Real t, Real maxDist) { return t <= maxDist ? t : kMiss; }

// First root t >= 0 of |o + t d - c|^2 = r^2 for an origin outside the sphere (|d| = 1), or kMiss.
Real sphereEntry(const VecR& o, const VecR& d, const VecR& c, Real r) {
  const VecR m = o - c;
  const Real b = m.dot(d);
  const Real disc = b * b - (m.squaredNorm() - r * r);
  if (disc < 0) return kMiss;
  const Real t = -b - std::sqrt(disc);
  return t >= 0 ? t : kMiss;
}

}  // namespace

Real exactRaySphere(const VecR& o, const VecR& d, Real radius, Real maxDist) {
  if (o.squaredNorm() <= radius * radius) return 0;
  const Real t = sphereEntry(o, d, VecR::Zero(), radius);
  return t < 0 ? kMiss : within(t, maxDist);
}

Real exactRayPlane(const VecR& o, const VecR& d, Real maxDist) {
  // Plane x = 0, normal +X: hit only from the front (origin x >= 0, moving towards -X).
  if (o.x() < 0 || d.x() >= 0) return kMiss;
  return within(-o.x() / d.x(), maxDist);
}

Real exactRayBox(const VecR& o, const VecR& d, const VecR& h, Real maxDist) {
  if ((o.cwiseAbs().array() <= h.array()).all()) return 0;
  // Slabs: the ray is inside slab i for t in [(-h_i - o_i)/d_i, (h_i - o_i)/d_i] (ordered).
  Real enter = -std::numeric_limits<Real>::infinity(), leave = std::numeric_limits<Real>::infinity();
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0) {
      if (std::abs(o[i]) > h[i]) return kMiss;
      continue;
    }
    Real t0 = (-h[i] - o[i]) / d[i], t1 = (h[i] - o[i]) / d[i];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  if (enter > leave || enter < 0) return kMiss;
  return within(enter, maxDist);
}

Real exactRayCapsule(const VecR& o, const VecR& d, Real radius, Real halfHeight, Real maxDist) {
  // Inside when the distance to the segment [-hh, hh] x {0} x {0} is <= radius.
  const VecR nearest(std::clamp(o.x(), -halfHeight, halfHeight), 0, 0);
  if ((o - nearest).squaredNorm() <= radius * radius) return 0;
  // From outside, the entry into the union is the earliest entry into a cap sphere or the cylinder side.
  Real best = std::numeric_limits<Real>::infinity();
  for (Real cx : {-halfHeight, halfHeight}) {
    const Real t = sphereEntry(o, d, VecR(cx, 0, 0), radius);
    if (t >= 0) best = std::min(best, t);
  }
  const Real a = d.y() * d.y() + d.z() * d.z();
  if (a > 0) {
    const Real b = o.y() * d.y() + o.z() * d.z();
    const Real c = o.y() * o.y() + o.z() * o.z() - radius * radius;
    const Real disc = b * b - a * c;
    if (disc >= 0) {
      const Real t = (-b - std::sqrt(disc)) / a;
      if (t >= 0 && std::abs(o.x() + t * d.x()) <= halfHeight) best = std::min(best, t);
    }
  }
  if (!std::isfinite(best)) return kMiss;
  return within(best, maxDist);
}

}  // namespace gq::demo
