// Custom geometry's optional overlap, penetration and distance callbacks, asked by the dispatch tables (see
// callback_queries.h).
#include "custom/callback_queries.h"

#include <cmath>
#include <string>

#include "gq/tolerances.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers
namespace {

template <class T> const CustomGeometryCallbacks<T>* callbacksIf(const Geometry<T>& g) {
  const auto* c = g.template getIf<CustomGeometry<T>>();
  return c ? c->callbacks.get() : nullptr;
}

template <class T> Status badAnswer(const CustomGeometryCallbacks<T>& cb, CustomIssue issue) {
  return Status::aboutCustom(StatusCode::InternalError, issue, cb.name());
}

// The penetration callback of `self` (at pSelf) against `other` (at pOther). `sign` = +1 when self is geom0, -1 when
// it is geom1 (then geom0 moves the other way).
template <class T>
Status askPenetration(const CustomGeometryCallbacks<T>& self, const Transform<T>& pSelf, const Geometry<T>& other,
                      const Transform<T>& pOther, T sign, bool& answered, bool& penetrating, Vec3<T>& direction,
                      T& depth) {
  bool pen = false;
  Vec3<T> dirLocal = Vec3<T>::UnitX();
  T d = T(0);
  answered = self.computePenetration(other, pOther.relativeTo(pSelf), pen, dirLocal, d);
  if (!answered) return {};
  if (pen) {
    const T unitError = std::abs(dirLocal.norm() - T(1));
    if (!isFinite(dirLocal) || !std::isfinite(d) || d < T(0) || !(unitError <= T(tol::kUnitDirection)))
      return badAnswer(self, CustomIssue::BadPenetration);
    direction = sign * pSelf.rotate(dirLocal.normalized());
    depth = d;
  }
  penetrating = pen;
  return {};
}

// The distance callback of `self` (at pSelf) against `other` (at pOther), brought to the caller's frame; `flip`
// when self is geom1.
template <class T>
Status askDistance(const CustomGeometryCallbacks<T>& self, const Transform<T>& pSelf, const Geometry<T>& other,
                   const Transform<T>& pOther, bool flip, bool& answered, DistanceResult<T>& out) {
  DistanceResult<T> local;
  answered = self.distance(other, pOther.relativeTo(pSelf), local);
  if (!answered) return {};
  const T unitError = std::abs(local.normal.norm() - T(1));
  if (!std::isfinite(local.distance) || !isFinite(local.point0) || !isFinite(local.point1) ||
      !(unitError <= T(tol::kUnitDirection)))
    return badAnswer(self, CustomIssue::BadDistance);
  out.distance = local.distance;
  out.normal = (flip ? T(-1) : T(1)) * pSelf.rotate(local.normal);
  out.point0 = pSelf.transform(flip ? local.point1 : local.point0);
  out.point1 = pSelf.transform(flip ? local.point0 : local.point1);
  return {};
}

}  // namespace

template <class T>
bool customOverlap(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                   bool& overlapping) {
  if (const auto* cb = callbacksIf(g0); cb && cb->overlap(g1, p1.relativeTo(p0), overlapping)) return true;
  if (const auto* cb = callbacksIf(g1); cb && cb->overlap(g0, p0.relativeTo(p1), overlapping)) return true;
  return false;
}

template <class T>
Status customPenetration(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                         bool& answered, bool& penetrating, Vec3<T>& direction, T& depth) {
  answered = false;
  if (const auto* cb = callbacksIf(g0))
    if (Status s = askPenetration(*cb, p0, g1, p1, T(1), answered, penetrating, direction, depth); !s.ok() || answered)
      return s;
  if (const auto* cb = callbacksIf(g1))
    return askPenetration(*cb, p1, g0, p0, T(-1), answered, penetrating, direction, depth);
  return {};
}

template <class T>
Status customDistance(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                      bool& answered, DistanceResult<T>& out) {
  answered = false;
  if (const auto* cb = callbacksIf(g0))
    if (Status s = askDistance(*cb, p0, g1, p1, false, answered, out); !s.ok() || answered) return s;
  if (const auto* cb = callbacksIf(g1)) return askDistance(*cb, p1, g0, p0, true, answered, out);
  return {};
}

template bool customOverlap<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&,
                                   const Transform<float>&, bool&);
template bool customOverlap<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&,
                                    const Transform<double>&, bool&);
template Status customPenetration<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&,
                                         const Transform<float>&, bool&, bool&, Vec3<float>&, float&);
template Status customPenetration<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&,
                                          const Transform<double>&, bool&, bool&, Vec3<double>&, double&);

template Status customDistance<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&,
                                      const Transform<float>&, bool&, DistanceResult<float>&);
template Status customDistance<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&,
                                       const Transform<double>&, bool&, DistanceResult<double>&);

}  // namespace gq::kernels
