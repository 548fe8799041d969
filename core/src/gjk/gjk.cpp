// GJK distance between the cores of two support-mapped shapes (Gilbert-Johnson-Keerthi 1988 with the
// signed-volume simplex solver), plus the boolean early-out variant.
//
// v is the current closest point of the Minkowski difference D = A - B to the origin, w = s_D(-v) the support
// point. |v| is an upper bound of the core distance. Any direction d with support w = s_D(-d) gives the lower bound
// d.w/|d| (every point z of D has d.z >= d.w), so |v| - max_k d_k.w_k/|d_k| bounds the error; GJK stops once it is
// below tolerance. With d = v this is the usual duality gap v.(v - w)/|v|.
//
// Plain GJK, no momentum: Nesterov acceleration (Montaut, Le Lidec, Petrik, Sivic, Carpentier, RSS 2022) cost 13-25%
// more instructions in the boolean GJK and ~8% in distance on hull pairs (docs/performance.md: its supports seldom
// pass the gap test and are retried without it), and plain GJK is what the termination argument covers.
#include <cmath>

#include "gjk/boolean_simplex.h"
#include "gjk/gjk.h"
#include "gjk/pair_scale.h"
#include "gjk/simplex.h"
#include "gjk/support_map.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers
namespace {

// Rebuilds the cached simplex from its search directions (valid support points whatever the poses now are).
template <class T>
void seedSimplex(SupportMap<T>& a, SupportMap<T>& b, const Mat3<T>& rotationA, const GjkCache<T>& cache,
                 GjkSimplex<T>& s) {
  for (std::uint32_t k = 0; k < std::min<std::uint32_t>(cache.simplexSize, 4); ++k) {
    const Vec3<T>& local = cache.simplexDirections[k];
    if (!isFinite(local) || !(local.squaredNorm() > T(0))) continue;
    const SupportPoint<T> p = supportOfDifference(a, b, Vec3<T>(rotationA * local));
    bool repeated = false;
    for (std::uint32_t j = 0; j < s.size; ++j) repeated = repeated || s.points[j].w == p.w;
    if (!repeated) s.points[s.size++] = p;
  }
}

// First search direction: the cached one (a's local frame), else the caller's `start`, else the centre difference;
// +X when that is zero or not finite.
template <class T>
Vec3<T> initialDirection(const ConvexShape<T>& a, const ConvexShape<T>& b, const GjkCache<T>* cache, const Vec3<T>* start) {
  if (cache && cache->direction.squaredNorm() > T(0) && isFinite(cache->direction))
    return a.rotation * cache->direction;
  const Vec3<T> d = start ? *start : Vec3<T>(a.center() - b.center());
  return d.squaredNorm() > T(0) ? d : Vec3<T>(Vec3<T>::UnitX());
}

// Cores without a rounded shell of their own (their margin is at most a caller's band).
template <class T> bool hasSharpCore(const ConvexShape<T>& s) {
  using Kind = typename ConvexShape<T>::Kind;
  return s.kind == Kind::Box || s.kind == Kind::Hull || s.kind == Kind::Custom;
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

// A pair outside the scales GJK squares safely runs rescaled (pair_scale.h), its answer back in the caller's frame.
template <class T> void unscale(GjkResult<T>& r, T back) {
  r.distance *= back;
  r.point0 *= back;
  r.point1 *= back;
  r.errorBound *= back;
  scaleSimplex(r.simplex, back);
}

template <class T>
[[gnu::noinline]] void distanceRescaled(const ConvexShape<T>& a, const ConvexShape<T>& b, GjkCache<T>* cache,
                                        T stopTolerance, const Vec3<T>* start, T farEnough, T factor,
                                        GjkResult<T>& r) {
  const ConvexShape<T> sa = scaledShape(a, factor), sb = scaledShape(b, factor);
  r = gjkDistance(sa, sb, cache, stopTolerance * factor, start, farEnough * factor);  // start: a direction
  unscale(r, T(1) / factor);
  keepHints(sa, a), keepHints(sb, b);
}

template <class T>
[[gnu::noinline]] bool overlapRescaled(const ConvexShape<T>& a, const ConvexShape<T>& b, GjkOverlapWitness<T>* witness,
                                       const Vec3<T>* start, T factor) {
  const ConvexShape<T> sa = scaledShape(a, factor), sb = scaledShape(b, factor);
  const bool overlapping = gjkOverlap(sa, sb, witness, start);
  if (overlapping && witness) {
    scaleSimplex(witness->simplex, T(1) / factor);
    witness->coreDistanceUpper /= factor;
  }
  keepHints(sa, a), keepHints(sb, b);
  return overlapping;
}

}  // namespace

template <class T>
GjkResult<T> gjkDistance(const ConvexShape<T>& a, const ConvexShape<T>& b, GjkCache<T>* cache, T stopTolerance,
                         const Vec3<T>* start, T farEnough) {
  const T length = gjkPairLength(a, b);
  GjkResult<T> r;
  if (needsRescale(length)) {
    distanceRescaled(a, b, cache, stopTolerance, start, farEnough, rescaleFactor(length), r);
    return r;
  }
  // Core lower bounds past this certify the shapes farther than farEnough (+inf: never). Only cores proven apart
  // (a positive bound) bound the signed distance from below: overlapping cores' depth has no lower bound here.
  const T farCore = std::max(farEnough + a.margin + b.margin, T(0));
  const bool bounded = farCore < std::numeric_limits<T>::infinity();
  const T tolerance = gjkToleranceFor(length);
  const T gapTolerance = std::max(tolerance, stopTolerance);  // overlap is still decided at `tolerance`
  SupportMap<T> sa(a), sb(b);
  GjkSimplex<T>& s = r.simplex;
  Vec3<T> v = initialDirection(a, b, cache, start);
  std::array<T, 4> lambda = {T(1), T(0), T(0), T(0)};
  T lowerBound = T(0);  // best lower bound of the core distance seen so far
  T gapBound = std::numeric_limits<T>::infinity();
  bool converged = false;
  // The state of smallest |v| so far. It is the current one until a step fails to decrease |v|; only then is it
  // copied (`saved`), so the usual strictly decreasing run copies no simplex.
  struct Best {
    GjkSimplex<T> s;
    std::array<T, 4> lambda;
    Vec3<T> v;
  } best;
  T bestSquared = std::numeric_limits<T>::infinity();
  bool saved = false;
  std::uint32_t stalls = 0;
  std::uint32_t it = 0;
  if (cache) seedSimplex(sa, sb, a.rotation, *cache, s);
  if (bounded) {  // a seed w = s_D(d) bounds every point z of D: -d.z >= -d.w, so |z| >= -d.w / |d|
    for (std::uint32_t k = 0; k < s.size; ++k)
      lowerBound = std::max(lowerBound, -s.points[k].d.dot(s.points[k].w) / s.points[k].d.norm());
    r.beyond = lowerBound > farCore;
  }
  if (s.size > 0 && !r.beyond) {
    const SimplexClosest<T> c = closestOnSimplex(s);
    r.coresOverlap = converged = c.containsOrigin || c.v.norm() <= tolerance;
    v = c.v;
    lambda = c.lambda;
    bestSquared = v.squaredNorm();
  }
  while (!r.coresOverlap && !r.beyond && it < kGjkMaxIterations) {
    ++it;
    // The support point along -v, written in the simplex's next slot: it joins the simplex unless GJK stops here.
    SupportPoint<T>& p = s.points[s.size];
    supportOfDifference(sa, sb, Vec3<T>(-v), p);
    if (s.size > 0 || bounded) {
      const T vNorm = v.norm();
      lowerBound = std::max(lowerBound, v.dot(p.w) / vNorm);
      if (lowerBound > farCore) { r.beyond = true; break; }
      if (s.size > 0) {  // v is a point of D (before the first step it is only a direction): the gap bounds
        gapBound = std::max(T(0), vNorm - lowerBound);
        if (gapBound <= gapTolerance) { converged = true; break; }
        // A repeated support point along -v means D has no point closer along -v: v is optimal up to rounding.
        if (alreadyInSimplex(s, p.w)) { converged = true; break; }
      }
    }
    ++s.size;
    const SimplexChoice<T> c = chooseOnSimplex(s);
    if (c.containsOrigin || c.v.norm() <= tolerance) {
      reduceSimplex(s, c);
      r.coresOverlap = true;
      lambda = c.lambda;
      v = c.v;
      converged = true;
      break;
    }
    // |v| must decrease strictly. Near the origin rounding can stall GJK (the simplex is then nearly flat around
    // the origin): keep going from the new simplex, which usually closes around the origin next, and give up after
    // kGjkMaxStalls with the best simplex seen.
    const T squared = c.v.squaredNorm();
    if (!(squared < bestSquared)) {
      if (!saved) {  // the state before this step is the best: keep it (the simplex without p)
        best = {s, lambda, v};
        --best.s.size;
        saved = true;
      }
      if (++stalls > kGjkMaxStalls) break;
    }
    reduceSimplex(s, c);
    v = c.v;
    lambda = c.lambda;
    if (squared < bestSquared) {
      bestSquared = squared;
      saved = false;
    }
  }
  // Only a GJK that gave up falls back to its best simplex. A converged one keeps its own: an earlier simplex whose
  // |v| is smaller by rounding has the distance right but can point v off by ~sqrt(rounding / distance).
  if (!r.coresOverlap && !converged && saved && bestSquared < v.squaredNorm()) {
    s = best.s;
    lambda = best.lambda;
    v = best.v;
  }
  r.iterations = it;
  r.errorBound = r.coresOverlap ? T(0) : std::max(T(0), v.norm() - lowerBound);
  if (!converged && !r.beyond && !(r.errorBound <= gapTolerance))
    r.status = Status::notConverged("GJK stopped without a certified distance").withIterations(it, float(r.errorBound));
  if (r.beyond) {
    r.distance = lowerBound - a.margin - b.margin;
  } else if (!r.coresOverlap) {
    Vec3<T> coreA, coreB;
    simplexWitnesses(s, lambda, coreA, coreB);
    finishSeparated(a, b, coreA, coreB, v, r);
  } else {
    r.distance = -(a.margin + b.margin);  // lower bound; EPA gives the true depth
  }
  a.climbStart = sa.hint();
  b.climbStart = sb.hint();
  if (cache) {
    cache->iterations = it;
    if (!r.coresOverlap) cache->direction = a.rotation.transpose() * v;
    cache->simplexSize = s.size;
    for (std::uint32_t k = 0; k < s.size; ++k) cache->simplexDirections[k] = a.rotation.transpose() * s.points[k].d;
  }
  return r;
}

template <class T>
bool gjkOverlap(const ConvexShape<T>& a, const ConvexShape<T>& b, GjkOverlapWitness<T>* witness, const Vec3<T>* start) {
  const T length = gjkPairLength(a, b);
  if (needsRescale(length)) return overlapRescaled(a, b, witness, start, rescaleFactor(length));
  // Positive answers leave the evidence: an enclosing simplex, or |v| (an upper bound of the cores' distance).
  const auto overlapping = [&](const GjkSimplex<T>& simplex, bool enclosing, T upper) {
    if (witness) *witness = {enclosing, simplex, upper};
    return true;
  };
  const T tolerance = gjkToleranceFor(length);
  const T margins = a.margin + b.margin;
  SupportMap<T> sa(a), sb(b);
  GjkSimplex<T> s;
  Vec3<T> v = initialDirection<T>(a, b, nullptr, start);
  // Polytope-like cores (no rounded shell of their own): the direction-only loop decides almost every pair; what it
  // cannot decide (cores within the margins, degenerate simplices) goes to the full loop below, from scratch.
  if (hasSharpCore(a) && hasSharpCore(b)) {
    Vec3<T> dir = -v;  // towards the origin from the centre difference
    for (std::uint32_t it = 0; it < kGjkBooleanFastIterations; ++it) {
      SupportPoint<T>& p = s.points[s.size];  // the simplex's next slot (booleanStep leaves at most three points)
      supportOfDifference(sa, sb, dir, p);
      // Separating axis: h_D(dir) = dir.w below -(margins + tolerance) |dir|.
      if (dir.dot(p.w) < -(margins + tolerance) * dir.norm()) return false;
      if (alreadyInSimplex(s, p.w)) break;
      ++s.size;
      const BooleanStep<T> step = s.size == 1 ? BooleanStep<T>{Vec3<T>(-p.w), false} : booleanStep(s);
      if (step.enclosed) return overlapping(s, true, T(0));
      if (!(step.dir.squaredNorm() > T(0)) || !isFinite(step.dir)) break;
      dir = step.dir;
    }
    s.size = 0;
  }
  T bestSquared = std::numeric_limits<T>::infinity();
  std::uint32_t stalls = 0;
  for (std::uint32_t it = 0; it < kGjkMaxIterations; ++it) {
    const SupportPoint<T> p = supportOfDifference(sa, sb, Vec3<T>(-v));
    // Separating axis: the lower bound v.w/|v| of the core distance already exceeds the margins.
    if (v.dot(p.w) > (margins + tolerance) * v.norm()) return false;
    if (s.size > 0) {
      const T vNorm = v.norm();
      // Converged: |v| is the core distance within tolerance.
      if (v.dot(v - p.w) <= tolerance * vNorm || alreadyInSimplex(s, p.w))
        return vNorm <= margins + tolerance && overlapping(s, false, vNorm);
    }
    s.points[s.size++] = p;
    const SimplexClosest<T> c = closestOnSimplex(s);
    if (c.containsOrigin) return overlapping(s, true, T(0));
    if (c.v.norm() <= margins + tolerance) return overlapping(s, false, c.v.norm());
    // No progress: rounding stalls GJK (see gjkDistance), at most kGjkMaxStalls times.
    if (!(c.v.squaredNorm() < bestSquared) && ++stalls > kGjkMaxStalls)
      return std::sqrt(bestSquared) <= margins + tolerance && overlapping(s, false, std::sqrt(bestSquared));
    v = c.v;
    bestSquared = std::min(bestSquared, v.squaredNorm());
  }
  return v.norm() <= margins + tolerance && overlapping(s, false, v.norm());
}

template GjkResult<float> gjkDistance<float>(const ConvexShape<float>&, const ConvexShape<float>&, GjkCache<float>*,
                                             float, const Vec3<float>*, float);
template GjkResult<double> gjkDistance<double>(const ConvexShape<double>&, const ConvexShape<double>&,
                                               GjkCache<double>*, double, const Vec3<double>*, double);
template bool gjkOverlap<float>(const ConvexShape<float>&, const ConvexShape<float>&, GjkOverlapWitness<float>*,
                                const Vec3<float>*);
template bool gjkOverlap<double>(const ConvexShape<double>&, const ConvexShape<double>&, GjkOverlapWitness<double>*,
                                 const Vec3<double>*);

}  // namespace gq::kernels
