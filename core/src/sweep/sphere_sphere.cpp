// Sphere against sphere in closed form: the centre c0 moving along dir meets the sphere of radius R = r0 + r1 around
// c1 at the smaller root of |m + t dir|^2 = R^2 (m = c0 - c1): t = -b - sqrt(b^2 - c) with b = m.dir, c = m.m - R^2,
// evaluated as c / (-b + sqrt(b^2 - c)) to avoid cancellation. c <= 0 is an initial overlap of depth R - |m|.
#include "sweep/sweep.h"
#include "common/unit_vector.h"

namespace gq::detail {

template <class T>
void sweepSphereSphere(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                       const SweepQuery<T>& q, SweepOutcome<T>& out) {
  const T r0 = g0.template get<SphereGeometry<T>>().radius + q.inflation;
  const T r1 = g1.template get<SphereGeometry<T>>().radius;
  const T radius = r0 + r1;
  const Vec3<T> m = p0.p - p1.p;
  const T b = m.dot(q.dir);
  const T c = m.squaredNorm() - radius * radius;
  if (c <= T(0)) {
    const T len = m.norm();
    const Vec3<T> n = unitOr(m, Vec3<T>(-q.dir));  // coincident centres: push back along -dir
    out.hit = true;
    out.initialOverlap = q.testInitialOverlap;
    out.normal = n;
    out.position = p1.p + r1 * n;
    out.mtdValid = true;
    out.mtdDepth = radius - len;
    out.mtdNormal = n;
    out.mtdPosition = p0.p - r0 * n;
    return;
  }
  if (!(b < T(0))) return;  // moving away from (or tangentially past) the target's centre
  const T disc = b * b - c;
  if (disc < T(0)) return;
  const T t = c / (-b + std::sqrt(disc));
  if (!(t <= q.maxDist)) return;
  const Vec3<T> n = (m + t * q.dir) / radius;
  out.hit = true;
  out.distance = t;
  out.normal = n.normalized();
  out.position = p1.p + r1 * out.normal;
}

template void sweepSphereSphere<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&,
                                       const Transform<float>&, const SweepQuery<float>&, SweepOutcome<float>&);
template void sweepSphereSphere<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&,
                                        const Transform<double>&, const SweepQuery<double>&, SweepOutcome<double>&);

}  // namespace gq::detail
