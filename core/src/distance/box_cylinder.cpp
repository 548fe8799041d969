// Box vs cylinder distance certificates, in the box's frame (box [-h, h]; cylinder centre c, unit axis a, radius r,
// half height hh). The cylinder is its axis segment grown by disks perpendicular to it, so two of its three kinds
// of closest feature have closed forms, each proven by a lower bound that a witness pair attains:
//  - cap: the cylinder lies below the plane of the cap facing the box, so the box's least height above that plane
//    bounds the distance from below; a lowest box point whose foot on the plane lies in the cap disk attains it.
//  - side: every cylinder point is within r of the axis, so dist(box, cylinder) >= dist(box, axis) - r. Where the
//    axis point nearest the box is interior to the segment, the box point p nearest it lies perpendicular to the
//    axis (the derivative of the squared distance along the axis vanishes), and the side point at radius r towards
//    p attains the bound.
//  - box face: the cylinder's least point along a face normal n (its support along -n) whose foot lies in that face
//    is at the gap of the face's plane, which bounds the distance from below.
//  - box corner: the cylinder point q nearest a corner v (a closed form) is the answer when v is the box's support
//    along q - v: the plane through v normal to q - v then separates them by |q - v|. From the corner towards the
//    cylinder's centre, the corner is moved to the box's support along q - v up to three times.
// A candidate is accepted only when its witnesses' distance is within `tolerance` of its lower bound. What is left
// is a rim against a box edge (a circle against a line leads to a quartic): Unknown, GJK answers.
#include <algorithm>
#include <cmath>

#include "distance/distance.h"
#include "gjk/support_map.h"
#include "overlap/segment_box.h"

namespace gq::detail {
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

template <class T>
BoxCylinderDistance cornerWitness(const Vec3<T>& h, const Vec3<T>& c, const Vec3<T>& a, T r, T hh, T tolerance,
                                  DistanceResult<T>& local) {
  Vec3<T> v = supportBox(h, c);
  for (int step = 0; step < 4; ++step) {
    const Vec3<T> q = nearestOnCylinder(c, a, r, hh, v);
    const Vec3<T> towards = q - v;
    const T dist = towards.norm();
    if (!(dist > tolerance)) return BoxCylinderDistance::Unknown;
    // The box's gap along n = towards / dist: h . |n| at the support, n . v at v; equal (within the tolerance)
    // when v is a support.
    const Vec3<T> n = towards / dist;
    const T lower = dist - (h.dot(n.cwiseAbs()) - n.dot(v));
    if (dist - lower <= tolerance) {
      writeSeparatedPair(v, q, dist, local);
      return BoxCylinderDistance::Separated;
    }
    v = supportBox(h, towards);
  }
  return BoxCylinderDistance::Unknown;
}

}  // namespace

template <class T>
BoxCylinderDistance distanceBoxCylinderLocal(const Vec3<T>& h, const Vec3<T>& c, const Vec3<T>& a, T r, T hh,
                                             T tolerance, DistanceResult<T>& local) {
  BoxCylinderDistance answer = capWitness(h, c, a, r, hh, tolerance, local);
  if (answer == BoxCylinderDistance::Unknown) answer = sideWitness(h, c, a, r, hh, tolerance, local);
  if (answer == BoxCylinderDistance::Unknown) answer = faceWitness(h, c, a, r, hh, tolerance, local);
  if (answer == BoxCylinderDistance::Unknown) answer = cornerWitness(h, c, a, r, hh, tolerance, local);
  return answer;
}

template BoxCylinderDistance distanceBoxCylinderLocal<float>(const Vec3<float>&, const Vec3<float>&,
                                                             const Vec3<float>&, float, float, float,
                                                             DistanceResult<float>&);
template BoxCylinderDistance distanceBoxCylinderLocal<double>(const Vec3<double>&, const Vec3<double>&,
                                                              const Vec3<double>&, double, double, double,
                                                              DistanceResult<double>&);

}  // namespace gq::detail
