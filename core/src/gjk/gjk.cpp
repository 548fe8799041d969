// GJK distance between the cores of two support-mapped shapes (Gilbert-Johnson-Keerthi 1988 with the
// signed-volume simplex solver), plus the boolean early-out variant.
//
// v is the current closest point of the Minkowski difference D = A - B to the origin, w = s_D(-v) the support
// point. |v| is an upper bound of the core distance and v.w/|v| a lower bound, so the duality gap
// g = v.(v - w) >= 0 bounds the error: |v| - dist <= g/|v|. GJK stops once that bound is below tolerance.
#include <cmath>

#include "gjk/gjk.h"
#include "gjk/simplex.h"

namespace gq::detail {
namespace {

template <class T> SupportPoint<T> supportOfDifference(const ConvexShape<T>& a, const ConvexShape<T>& b, const Vec3<T>& d) {
  SupportPoint<T> p;
  p.a = a.support(d);
  p.b = b.support(-d);
  p.w = p.a - p.b;
  p.d = d;
  return p;
}

// Rebuilds the cached simplex from its search directions (valid support points whatever the poses now are).
template <class T> void seedSimplex(const ConvexShape<T>& a, const ConvexShape<T>& b, const GjkCache<T>& cache, GjkSimplex<T>& s) {
  for (std::uint32_t k = 0; k < std::min<std::uint32_t>(cache.simplexSize, 4); ++k) {
    const Vec3<T>& local = cache.simplexDirections[k];
    if (!isFinite(local) || !(local.squaredNorm() > T(0))) continue;
    const SupportPoint<T> p = supportOfDifference(a, b, a.pose.rotate(local));
    bool repeated = false;
    for (std::uint32_t j = 0; j < s.size; ++j) repeated = repeated || s.points[j].w == p.w;
    if (!repeated) s.points[s.size++] = p;
  }
}

// First search direction: the cached one (a's local frame), else the centre difference, else +X.
template <class T> Vec3<T> initialDirection(const ConvexShape<T>& a, const ConvexShape<T>& b, const GjkCache<T>* cache) {
  if (cache && cache->direction.squaredNorm() > T(0) && isFinite(cache->direction)) return a.pose.rotate(cache->direction);
  const Vec3<T> d = a.center() - b.center();
  return d.squaredNorm() > T(0) ? d : Vec3<T>(Vec3<T>::UnitX());
}

template <class T> bool alreadyInSimplex(const GjkSimplex<T>& s, const Vec3<T>& w) {
  for (std::uint32_t k = 0; k < s.size; ++k)
    if (s.points[k].w == w) return true;
  return false;
}

// Writes witnesses, normal and the signed distance of the full shapes from the core closest points.
template <class T>
void finishSeparated(const ConvexShape<T>& a, const ConvexShape<T>& b, const Vec3<T>& coreA, const Vec3<T>& coreB,
                     const Vec3<T>& v, GjkResult<T>& r) {
  const T coreDistance = v.norm();
  r.normal = -v / coreDistance;  // v = a - b, so -v points from a to b
  r.distance = coreDistance - a.margin - b.margin;
  r.point0 = coreA + a.margin * r.normal;
  r.point1 = coreB - b.margin * r.normal;
}

}  // namespace

template <class T> GjkResult<T> gjkDistance(const ConvexShape<T>& a, const ConvexShape<T>& b, GjkCache<T>* cache) {
  const T tolerance = gjkTolerance(a, b);
  GjkResult<T> r;
  GjkSimplex<T>& s = r.simplex;
  Vec3<T> v = initialDirection(a, b, cache);
  std::array<T, 4> lambda = {T(1), T(0), T(0), T(0)};
  T gapBound = std::numeric_limits<T>::infinity();
  bool converged = false;
  struct Best {
    GjkSimplex<T> s;
    std::array<T, 4> lambda;
    Vec3<T> v;
  } best{s, lambda, Vec3<T>::Constant(std::numeric_limits<T>::infinity())};
  std::uint32_t stalls = 0;
  std::uint32_t it = 0;
  if (cache) seedSimplex(a, b, *cache, s);
  if (s.size > 0) {
    const SimplexClosest<T> c = closestOnSimplex(s);
    r.coresOverlap = converged = c.containsOrigin || c.v.norm() <= tolerance;
    v = c.v;
    lambda = c.lambda;
    best = {s, lambda, v};
  }
  while (!r.coresOverlap && it < kGjkMaxIterations) {
    ++it;
    const SupportPoint<T> p = supportOfDifference(a, b, Vec3<T>(-v));
    if (s.size > 0) {
      const T vNorm = v.norm();
      gapBound = std::max(T(0), v.dot(v - p.w)) / vNorm;
      // A repeated support point means D has no point closer along -v: v is optimal up to rounding.
      converged = gapBound <= tolerance || alreadyInSimplex(s, p.w);
      if (converged) break;
    }
    s.points[s.size++] = p;
    const SimplexClosest<T> c = closestOnSimplex(s);
    if (c.containsOrigin || c.v.norm() <= tolerance) {
      r.coresOverlap = true;
      lambda = c.lambda;
      v = c.v;
      converged = true;
      break;
    }
    // |v| must decrease strictly. Near the origin rounding can stall it (the simplex is then nearly flat
    // around the origin): keep going from the new simplex, which usually closes around the origin next, and
    // give up after kGjkMaxStalls, answering with the best simplex seen.
    if (!(c.v.squaredNorm() < best.v.squaredNorm()) && ++stalls > kGjkMaxStalls) break;
    v = c.v;
    lambda = c.lambda;
    if (v.squaredNorm() < best.v.squaredNorm()) best = {s, lambda, v};
  }
  if (!r.coresOverlap && best.v.squaredNorm() < v.squaredNorm()) {
    s = best.s;
    lambda = best.lambda;
    v = best.v;
  }
  r.iterations = it;
  r.errorBound = r.coresOverlap ? T(0) : gapBound;
  if (!converged && !(gapBound <= tolerance))
    r.status = Status::notConverged("GJK stopped after " + std::to_string(it) + " iterations with error bound " +
                                    std::to_string(double(gapBound)));
  if (!r.coresOverlap) {
    Vec3<T> coreA, coreB;
    simplexWitnesses(s, lambda, coreA, coreB);
    finishSeparated(a, b, coreA, coreB, v, r);
  } else {
    r.distance = -(a.margin + b.margin);  // lower bound; EPA gives the true depth
  }
  if (cache) {
    cache->iterations = it;
    if (!r.coresOverlap) cache->direction = a.pose.rotateInv(v);
    cache->simplexSize = s.size;
    for (std::uint32_t k = 0; k < s.size; ++k) cache->simplexDirections[k] = a.pose.rotateInv(s.points[k].d);
  }
  return r;
}

template <class T> bool gjkOverlap(const ConvexShape<T>& a, const ConvexShape<T>& b) {
  const T tolerance = gjkTolerance(a, b);
  const T margins = a.margin + b.margin;
  GjkSimplex<T> s;
  Vec3<T> v = initialDirection<T>(a, b, nullptr);
  T bestSquared = std::numeric_limits<T>::infinity();
  std::uint32_t stalls = 0;
  for (std::uint32_t it = 0; it < kGjkMaxIterations; ++it) {
    const SupportPoint<T> p = supportOfDifference(a, b, Vec3<T>(-v));
    if (s.size > 0) {
      const T vNorm = v.norm();
      // Separating axis: the lower bound v.w/|v| already exceeds the margins.
      if (v.dot(p.w) > (margins + tolerance) * vNorm) return false;
      // Converged: |v| is the core distance within tolerance.
      if (v.dot(v - p.w) <= tolerance * vNorm || alreadyInSimplex(s, p.w)) return vNorm <= margins + tolerance;
    }
    s.points[s.size++] = p;
    const SimplexClosest<T> c = closestOnSimplex(s);
    if (c.containsOrigin || c.v.norm() <= margins + tolerance) return true;
    // Rounding stall (see gjkDistance): keep going, at most kGjkMaxStalls times.
    if (!(c.v.squaredNorm() < bestSquared) && ++stalls > kGjkMaxStalls) return std::sqrt(bestSquared) <= margins + tolerance;
    v = c.v;
    bestSquared = std::min(bestSquared, v.squaredNorm());
  }
  return v.norm() <= margins + tolerance;
}

template GjkResult<float> gjkDistance<float>(const ConvexShape<float>&, const ConvexShape<float>&, GjkCache<float>*);
template GjkResult<double> gjkDistance<double>(const ConvexShape<double>&, const ConvexShape<double>&, GjkCache<double>*);
template bool gjkOverlap<float>(const ConvexShape<float>&, const ConvexShape<float>&);
template bool gjkOverlap<double>(const ConvexShape<double>&, const ConvexShape<double>&);

}  // namespace gq::detail
