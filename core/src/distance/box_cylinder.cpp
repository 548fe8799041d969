// Box vs cylinder distance certificates, in the box's frame (box [-h, h]; cylinder centre c, unit axis a, radius r,
// half height hh). The cylinder is its axis segment grown by disks perpendicular to it. Each candidate below is a
// box point and a cylinder point whose distance attains a lower bound (a separating plane's gap) within
// `tolerance`, which proves it the answer:
//  - cap: the cylinder lies below the plane of the cap facing the box, so the box's least height above that plane
//    bounds the distance from below; a lowest box point whose foot on the plane lies in the cap disk attains it.
//  - side: every cylinder point is within r of the axis, so dist(box, cylinder) >= dist(box, axis) - r. Where the
//    axis point nearest the box is interior to the segment, the box point p nearest it lies perpendicular to the
//    axis (the derivative of the squared distance along the axis vanishes), and the side point at radius r towards
//    p attains the bound.
//  - box face: the cylinder's least point along a face normal n (its support along -n) whose foot lies in that face
//    is at the gap of the face's plane, which bounds the distance from below.
//  - box corner: the cylinder point q nearest a corner v (a closed form) is the answer when v is the box's support
//    along q - v: the plane through v normal to q - v then separates them by |q - v|.
//  - box edge (a rim against an edge: a circle against a line leads to a quartic): the distance along the edge is
//    convex, its minimum found by a bracketed root search of its derivative, then proven as a corner's is.
// Nothing proven (touching within the tolerance, or a search that ends short of it): Unknown, GJK answers.
#include <algorithm>
#include <cmath>
#include <limits>

#include "distance/distance.h"
#include "gjk/pair_scale.h"
#include "gjk/support_map.h"
#include "overlap/overlap.h"
#include "overlap/segment_box.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers
namespace {

template <class T> void writeSeparatedPair(const Vec3<T>& onBox, const Vec3<T>& onCylinder, T dist,
                                           DistanceResult<T>& local) {
  local.distance = dist;
  local.normal = (onCylinder - onBox) / dist;
  local.point0 = onBox;
  local.point1 = onCylinder;
}

// The cap facing the box: centre e, outward normal n. A lowest box point along n takes -h_k sign(n_k) on every axis
// along which the height varies by more than the tolerance; on the others it is free, and the point nearest the cap
// centre is taken (a face or edge of the box lying flat on the cap).
template <class T>
BoxCylinderDistance capWitness(const Vec3<T>& h, const Vec3<T>& c, const Vec3<T>& a, T r, T hh, T tolerance,
                               DistanceResult<T>& local) {
  const Vec3<T> n = c.dot(a) > T(0) ? Vec3<T>(-a) : a;
  const Vec3<T> e = c + hh * n;
  const T lower = -h.dot(n.cwiseAbs()) - n.dot(e);  // least height of the box above the cap plane
  if (!(lower > tolerance)) return BoxCylinderDistance::Unknown;
  Vec3<T> p;
  for (int k = 0; k < 3; ++k)
    p[k] = T(2) * h[k] * std::abs(n[k]) <= tolerance ? std::clamp(e[k], -h[k], h[k]) : (n[k] > T(0) ? -h[k] : h[k]);
  const T height = n.dot(p - e);
  const Vec3<T> foot = p - height * n;
  if (!((foot - e).squaredNorm() <= r * r) || !(height - lower <= tolerance)) return BoxCylinderDistance::Unknown;
  writeSeparatedPair(p, foot, height, local);
  return BoxCylinderDistance::Separated;
}

// The side: the box point p nearest the axis segment and the side point towards it.
template <class T>
BoxCylinderDistance sideWitness(const Vec3<T>& h, const Vec3<T>& c, const Vec3<T>& a, T r, T hh, T tolerance,
                                DistanceResult<T>& local) {
  const SegmentBoxClosest<T> nearest = closestSegmentBox(c, Vec3<T>(hh * a), h);
  const Vec3<T>& p = nearest.onBox;
  const Vec3<T> fromAxis = p - c;
  const T s = fromAxis.dot(a);
  const Vec3<T> radial = fromAxis - s * a;
  const T rho = radial.norm();
  // p inside the cylinder is a common point, whatever the optimality of the pair.
  if (std::abs(s) <= hh && rho <= r) return BoxCylinderDistance::Overlapping;
  const T lower = std::sqrt(nearest.distSq) - r;
  if (!(lower > tolerance) || !(std::abs(s) < hh) || !(rho > T(0))) return BoxCylinderDistance::Unknown;
  const Vec3<T> onSide = c + s * a + (r / rho) * radial;
  const T upper = (p - onSide).norm();
  if (!(upper - lower <= tolerance)) return BoxCylinderDistance::Unknown;
  writeSeparatedPair(p, onSide, upper, local);
  return BoxCylinderDistance::Separated;
}

// The cylinder's support along -n (its least point along the unit n): the end facing -n, then the rim point
// facing -n (the cap's centre when n is along the axis).
template <class T> Vec3<T> leastAlong(const Vec3<T>& c, const Vec3<T>& a, T r, T hh, const Vec3<T>& n) {
  const T na = n.dot(a);
  const Vec3<T> across = n - na * a;
  const T acrossNorm = across.norm();
  const Vec3<T> end = c - (na > T(0) ? hh : -hh) * a;
  return acrossNorm > T(0) ? Vec3<T>(end - (r / acrossNorm) * across) : end;
}

// Box faces facing the cylinder: the one whose plane's gap is largest, when the cylinder's least point along its
// normal has its foot in the face.
template <class T>
BoxCylinderDistance faceWitness(const Vec3<T>& h, const Vec3<T>& c, const Vec3<T>& a, T r, T hh, T tolerance,
                                DistanceResult<T>& local) {
  int best = -1;
  T bestGap = T(0);
  Vec3<T> bestPoint;
  for (int k = 0; k < 3; ++k) {
    const T side = c[k] < T(0) ? T(-1) : T(1);
    const Vec3<T> q = leastAlong(c, a, r, hh, Vec3<T>(side * Vec3<T>::Unit(k)));
    const T gap = side * q[k] - h[k];
    if (gap > bestGap) { best = k; bestGap = gap; bestPoint = q; }
  }
  if (best < 0 || !(bestGap > tolerance)) return BoxCylinderDistance::Unknown;
  Vec3<T> foot = bestPoint;
  foot[best] = bestPoint[best] < T(0) ? -h[best] : h[best];
  if (!((foot.cwiseAbs() - h).maxCoeff() <= T(0))) return BoxCylinderDistance::Unknown;
  writeSeparatedPair(foot, bestPoint, bestGap, local);
  return BoxCylinderDistance::Separated;
}

// The cylinder point nearest p (outside the cylinder): the axial coordinate clamped to the ends, the radial
// distance to the radius.
template <class T> Vec3<T> nearestOnCylinder(const Vec3<T>& c, const Vec3<T>& a, T r, T hh, const Vec3<T>& p) {
  const Vec3<T> d = p - c;
  const T t = d.dot(a);
  const Vec3<T> radial = d - t * a;
  const T rho = radial.norm();
  const Vec3<T> onAxis = c + std::clamp(t, -hh, hh) * a;
  return rho > r ? Vec3<T>(onAxis + (r / rho) * radial) : onAxis + radial;
}

// A box point x and its nearest cylinder point q are the answer when x is the box's support along q - x: the plane
// through x normal to q - x then separates them by |q - x| (the box's reach past it, h . |n| - n . x, within the
// tolerance).
template <class T>
bool supportPairWitness(const Vec3<T>& h, const Vec3<T>& x, const Vec3<T>& q, T tolerance, DistanceResult<T>& local) {
  const Vec3<T> towards = q - x;
  const T dist = towards.norm();
  if (!(dist > tolerance)) return false;
  const Vec3<T> n = towards / dist;
  if (!(h.dot(n.cwiseAbs()) - n.dot(x) <= tolerance)) return false;
  writeSeparatedPair(x, q, dist, local);
  return true;
}

// A box point x and a cylinder point q near a closest pair: alternating projections (the box point nearest a
// cylinder point, and back) converge to a closest pair of disjoint shapes, and to a common point of overlapping
// ones. A few steps settle the signs of q - x that pick the box's corner, and with it the edges, of the answer.
template <class T>
void approach(const Vec3<T>& h, const Vec3<T>& c, const Vec3<T>& a, T r, T hh, Vec3<T>& x, Vec3<T>& q) {
  x = c.cwiseMax(-h).cwiseMin(h);
  q = nearestOnCylinder(c, a, r, hh, x);
  for (int step = 0; step < 6; ++step) {
    x = q.cwiseMax(-h).cwiseMin(h);
    q = nearestOnCylinder(c, a, r, hh, x);
  }
}

template <class T> bool inCylinder(const Vec3<T>& c, const Vec3<T>& a, T r, T hh, const Vec3<T>& p) {
  const Vec3<T> d = p - c;
  const T t = d.dot(a);
  return std::abs(t) <= hh && (d - t * a).squaredNorm() <= r * r;
}

// The corner along the approach, moved to the box's support along q - v up to three times; `start` is the first
// corner (the edges of the answer meet there: the support steps may leave them). An approach that ends in the
// cylinder found a common point.
template <class T>
BoxCylinderDistance cornerWitness(const Vec3<T>& h, const Vec3<T>& c, const Vec3<T>& a, T r, T hh, T tolerance,
                                  Vec3<T>& start, DistanceResult<T>& local) {
  Vec3<T> x, q;
  approach(h, c, a, r, hh, x, q);
  if (inCylinder(c, a, r, hh, x)) return BoxCylinderDistance::Overlapping;
  start = supportBox(h, Vec3<T>(q - x));
  Vec3<T> v = start;
  for (int step = 0; step < 4; ++step) {
    q = nearestOnCylinder(c, a, r, hh, v);
    if (supportPairWitness(h, v, q, tolerance, local)) return BoxCylinderDistance::Separated;
    const Vec3<T> next = supportBox(h, Vec3<T>(q - v));
    if (next == v) break;
    v = next;
  }
  return BoxCylinderDistance::Unknown;
}

// The edges at corner v (a rim against an edge: no closed form). Along an edge x(t) = v + t e, t in [0, 1], the
// squared distance to the cylinder is convex with derivative 2 (x - q(t)).e, q(t) the nearest cylinder point: its
// root is bracketed and found by regula falsi (Illinois), and the pair there is accepted by supportPairWitness.
template <class T>
BoxCylinderDistance edgeWitness(const Vec3<T>& h, const Vec3<T>& c, const Vec3<T>& a, T r, T hh, T tolerance,
                                const Vec3<T>& v, DistanceResult<T>& local) {
  for (int k = 0; k < 3; ++k) {
    Vec3<T> e = Vec3<T>::Zero();
    e[k] = T(-2) * v[k];
    const auto slope = [&](T t) {
      const Vec3<T> x = v + t * e;
      return (x - nearestOnCylinder(c, a, r, hh, x)).dot(e);
    };
    T lo = T(0), hi = T(1), gLo = slope(lo), gHi = slope(hi);
    if (!(gLo < T(0) && gHi > T(0))) continue;  // this edge's nearest point is an end: a corner's case
    int side = 0;
    for (int it = 0; it < 64 && hi - lo > std::numeric_limits<T>::epsilon(); ++it) {
      const T t = std::clamp((lo * gHi - hi * gLo) / (gHi - gLo), lo, hi);
      const T g = slope(t);
      if (g == T(0)) { lo = hi = t; break; }
      if (g < T(0)) {
        lo = t, gLo = g;
        if (side == -1) gHi /= T(2);  // Illinois: halve the stale end's value
        side = -1;
      } else {
        hi = t, gHi = g;
        if (side == 1) gLo /= T(2);
        side = 1;
      }
    }
    const Vec3<T> x = v + T(0.5) * (lo + hi) * e;
    if (supportPairWitness(h, x, nearestOnCylinder(c, a, r, hh, x), tolerance, local))
      return BoxCylinderDistance::Separated;
  }
  return BoxCylinderDistance::Unknown;
}

}  // namespace

template <class T>
BoxCylinderDistance distanceBoxCylinderLocal(const Vec3<T>& h, const Vec3<T>& c, const Vec3<T>& a, T r, T hh,
                                             DistanceResult<T>& local) {
  // Squared lengths of pairs outside the range GJK runs unscaled in may leave T's range: GJK rescales those.
  const T length = cylinderBoxLength(h, c, r, hh);
  if (!(length >= kPairScaleLow<T> && length <= kPairScaleHigh<T>)) return BoxCylinderDistance::Unknown;
  const T tolerance = gjkRelativeTolerance<T>() * length;
  BoxCylinderDistance answer = capWitness(h, c, a, r, hh, tolerance, local);
  if (answer == BoxCylinderDistance::Unknown) answer = sideWitness(h, c, a, r, hh, tolerance, local);
  if (answer == BoxCylinderDistance::Unknown) answer = faceWitness(h, c, a, r, hh, tolerance, local);
  if (answer != BoxCylinderDistance::Unknown) return answer;
  Vec3<T> corner;
  answer = cornerWitness(h, c, a, r, hh, tolerance, corner, local);
  return answer == BoxCylinderDistance::Unknown ? edgeWitness(h, c, a, r, hh, tolerance, corner, local) : answer;
}

template BoxCylinderDistance distanceBoxCylinderLocal<float>(const Vec3<float>&, const Vec3<float>&,
                                                             const Vec3<float>&, float, float,
                                                             DistanceResult<float>&);
template BoxCylinderDistance distanceBoxCylinderLocal<double>(const Vec3<double>&, const Vec3<double>&,
                                                              const Vec3<double>&, double, double,
                                                              DistanceResult<double>&);

}  // namespace gq::kernels
