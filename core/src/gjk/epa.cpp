// Expanding Polytope Algorithm (van den Bergen 2001) on the Minkowski difference D = A - B of the cores.
// With the origin inside D, translating b by t*n separates the cores iff t > h_D(n) = max_{w in D} n.w, so the
// penetration depth is min over unit n of h_D(n): the distance from the origin to the closest face of D. EPA grows
// a polytope inside D towards that face; the margins are then added in closed form.
//
// The polytope lives in fixed-capacity arrays on the stack (no allocation per query): at most kEpaMaxIterations + 4
// vertices, and a closed triangulated polytope with V vertices has 2V - 4 faces; dead faces' slots are reused.
//
// Bounds: the polytope lies inside D, so its closest face distance L is a lower bound of the core depth; every
// support value h_D(n) = n.s_D(n) along a unit n is an upper bound U (translating by U along n separates). EPA stops
// when the closest face's own gap h_D(n_f) - L, or the best U - L, is within tolerance. On curved support maps
// (cylinders, cones, user shapes) whose closest boundary is a ring or a disk, the polytope only approaches it as
// O(1/N^2) in its vertex count N, so the iterations may run out first: then the best upper bound is reported (a
// translation that separates, never too shallow) when U - L is within kEpaCurvedTolerance of the shapes' size, and
// NotConverged otherwise. A face whose expansion would make a degenerate face (the new support point collinear with a
// horizon edge: coplanar disks, diameters) is kept as final instead of aborting: it still bounds from below, and a
// converged face is the answer only when no final face lies closer (else the best upper bound is reported).
// The size of D is a.size + b.size (its bounding radius about the centre difference).
#include <algorithm>
#include <cmath>
#include <utility>

#include "gjk/gjk.h"
#include "gjk/pair_scale.h"
#include "gjk/simplex.h"
#include "gjk/support_map.h"
#include "gjk/wide.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers
namespace {

// Plain data (no member initializers: arrays of faces are not zeroed per query; makeFace writes every field).
template <class T> struct EpaFace {
  std::array<std::uint32_t, 3> v;  // outward (counter-clockwise seen from outside)
  Vec3<T> n;                       // outward unit normal
  T dist;                          // n . vertex: signed distance of the plane from the origin
  bool alive;
  bool final;                      // cannot be expanded without degenerating: bounds, but is not refined
};

// Relative certified error accepted when EPA runs out of iterations on a curved support map (see above).
inline constexpr double kEpaCurvedTolerance = 1e-2;

inline constexpr std::uint32_t kEpaMaxPoints = kEpaMaxIterations + 4;
inline constexpr std::uint32_t kEpaMaxFaces = 2 * kEpaMaxPoints;
inline constexpr std::uint32_t kEpaMaxHorizon = kEpaMaxFaces;

template <class T> struct Polytope {
  std::array<SupportPoint<T>, kEpaMaxPoints> points;
  std::uint32_t pointCount = 0;
  std::array<EpaFace<T>, kEpaMaxFaces> faces;
  std::uint32_t faceCount = 0;
};

// Up to 6 candidate directions.
template <class T> struct Directions {
  std::array<Vec3<T>, 6> d;
  std::uint32_t count = 0;
  void add(const Vec3<T>& x) { d[count++] = x; }
};

// The face's unit normal and offset from the widened points (out of line: rare, and wide arithmetic is bulky).
template <class T>
[[gnu::noinline]] void widePlane(const Vec3<T>& p0, const Vec3<T>& p1, const Vec3<T>& p2, EpaFace<T>& f) {
  using W = typename Wider<T>::type;
  const WideVec<W> w0 = p0.template cast<W>();
  const WideVec<W> wn = (p1.template cast<W>() - w0).cross(p2.template cast<W>() - w0);
  const WideVec<W> unit = wn / wideSqrt(wn.squaredNorm());
  f.n = unit.template cast<T>();
  f.dist = T(unit.dot(w0));
}

// Face i-j-k with its outward normal; false when degenerate. A long thin face far from the origin gets its normal
// and offset from the widened points (gjk/wide.h).
template <class T> bool makeFace(const Polytope<T>& poly, std::uint32_t i, std::uint32_t j, std::uint32_t k, EpaFace<T>& f) {
  const Vec3<T>&p0 = poly.points[i].w, &p1 = poly.points[j].w, &p2 = poly.points[k].w;
  const Vec3<T> e1 = p1 - p0, e2 = p2 - p0;
  const Vec3<T> n = e1.cross(e2);
  const T len = n.norm();
  if (!(len > T(0))) return false;
  f.v = {i, j, k};
  f.n = n / len;
  f.dist = f.n.dot(p0);
  if (planeNeedsWider(len * len, e1.squaredNorm() + e2.squaredNorm(), gjkRelativeTolerance<T>(),
                      [&] { return p0.squaredNorm(); }, [&] { return f.dist * f.dist; }))
    widePlane(p0, p1, p2, f);
  f.alive = true;
  f.final = false;
  return true;
}

// Unit vectors orthogonal to a (non-zero) direction.
template <class T> std::array<Vec3<T>, 2> orthonormalPair(const Vec3<T>& d) {
  const Vec3<T> u = d.normalized();
  const Vec3<T> helper = std::abs(u.x()) < T(0.6) ? Vec3<T>(Vec3<T>::UnitX()) : Vec3<T>(Vec3<T>::UnitY());
  const Vec3<T> e1 = u.cross(helper).normalized();
  return {e1, u.cross(e1)};
}

// Candidate directions that lift the simplex by one dimension (the simplex spans a point, a segment or a plane).
template <class T> Directions<T> liftDirections(const GjkSimplex<T>& s) {
  Directions<T> out;
  const Vec3<T> e = s.size >= 2 ? Vec3<T>(s.points[1].w - s.points[0].w) : Vec3<T>::Zero();
  const Vec3<T> n = s.size >= 3 ? Vec3<T>(e.cross(s.points[2].w - s.points[0].w)) : Vec3<T>::Zero();
  if (n.squaredNorm() > T(0)) {
    const Vec3<T> u = n.normalized();
    out.add(u);
    out.add(-u);
  } else if (e.squaredNorm() > T(0)) {
    const auto [e1, e2] = orthonormalPair(e);
    out.add(e1);
    out.add(-e1);
    out.add(e2);
    out.add(-e2);
  } else {
    for (int k = 0; k < 3; ++k) {
      out.add(Vec3<T>::Unit(k));
      out.add(-Vec3<T>::Unit(k));
    }
  }
  return out;
}

// Distance of q from the affine hull of the simplex.
template <class T> T distanceFromHull(const GjkSimplex<T>& s, const Vec3<T>& q) {
  const Vec3<T> r = q - s.points[0].w;
  if (s.size == 1) return r.norm();
  const Vec3<T> e = s.points[1].w - s.points[0].w;
  if (s.size == 2) return e.squaredNorm() > T(0) ? r.cross(e).norm() / e.norm() : r.norm();
  const Vec3<T> n = e.cross(s.points[2].w - s.points[0].w);
  return n.squaredNorm() > T(0) ? std::abs(r.dot(n)) / n.norm() : r.norm();
}

// Grows the GJK simplex to a tetrahedron. When D is flat along some direction (its extent there is within
// tolerance), returns false with `flatNormal` set: the core depth along it is ~0, the minimum.
template <class T>
bool liftToTetrahedron(SupportMap<T>& a, SupportMap<T>& b, T tolerance, GjkSimplex<T>& s, Vec3<T>& flatNormal) {
  while (s.size < 4) {
    T bestLift = T(-1), flattest = std::numeric_limits<T>::infinity();
    std::array<SupportPoint<T>, 6> lifted;
    std::uint32_t best = 0;
    const Directions<T> dirs = liftDirections(s);
    for (std::uint32_t k = 0; k < dirs.count; ++k) {
      const Vec3<T>& d = dirs.d[k];
      lifted[k] = supportOfDifference(a, b, d);
      const T lift = distanceFromHull(s, lifted[k].w);
      if (lift > bestLift) { bestLift = lift; best = k; }
      const T extent = d.dot(lifted[k].w);
      if (extent < flattest) { flattest = extent; flatNormal = d; }
    }
    if (!(bestLift > tolerance)) return false;
    s.points[s.size++] = lifted[best];
  }
  return true;
}

template <class T> bool buildTetrahedron(const GjkSimplex<T>& s, Polytope<T>& poly) {
  std::copy(s.points.begin(), s.points.end(), poly.points.begin());
  poly.pointCount = 4;
  const Vec3<T> centroid = (s.points[0].w + s.points[1].w + s.points[2].w + s.points[3].w) / T(4);
  const std::array<std::array<std::uint32_t, 3>, 4> tris = {{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}};
  for (const auto& t : tris) {
    EpaFace<T> f;
    if (!makeFace(poly, t[0], t[1], t[2], f)) return false;
    if (f.n.dot(poly.points[t[0]].w - centroid) < T(0) && !makeFace(poly, t[0], t[2], t[1], f)) return false;
    poly.faces[poly.faceCount++] = f;
  }
  return true;
}

// Closest face that may still be expanded (faceCount when none), and the lower bound: the closest face of all.
template <class T> std::uint32_t closestFace(const Polytope<T>& poly, T& lowerBound) {
  std::uint32_t best = poly.faceCount;
  T bestDist = std::numeric_limits<T>::infinity();
  lowerBound = std::numeric_limits<T>::infinity();
  for (std::uint32_t i = 0; i < poly.faceCount; ++i) {
    const EpaFace<T>& f = poly.faces[i];
    if (!f.alive) continue;
    lowerBound = std::min(lowerBound, f.dist);
    if (!f.final && f.dist < bestDist) { bestDist = f.dist; best = i; }
  }
  return best;
}

// Directed polytope edge (plain data, so the horizon's buffer is not zeroed per expansion).
struct Edge {
  std::uint32_t first, second;
  bool operator==(const Edge& o) const { return first == o.first && second == o.second; }
};

// Boundary of the removed faces: an edge seen twice (once per orientation) is interior and cancels.
struct Horizon {
  std::array<Edge, kEpaMaxHorizon> edges;
  std::uint32_t count = 0;
  bool overflow = false;

  void toggle(const Edge& e) {
    const Edge twin{e.second, e.first};
    for (std::uint32_t k = 0; k < count; ++k)
      if (edges[k] == twin) {
        edges[k] = edges[--count];
        return;
      }
    if (count == kEpaMaxHorizon) overflow = true;
    else edges[count++] = e;
  }
};

// Running closestFace over the faces an expansion keeps and adds (saves a second pass over all faces).
template <class T> struct ClosestTracker {
  std::uint32_t best = std::numeric_limits<std::uint32_t>::max();
  T bestDist = std::numeric_limits<T>::infinity();
  T lower = std::numeric_limits<T>::infinity();
  void offer(const EpaFace<T>& f, std::uint32_t i) {
    lower = std::min(lower, f.dist);
    if (!f.final && f.dist < bestDist) { bestDist = f.dist; best = i; }
  }
};

// Removes the faces that see `w` (farther than `tolerance` in front of them) and closes the hole with faces fanning
// from w to the horizon edges, reusing the removed faces' slots; `next` receives closestFace of the result.
// Transactional: when a buffer is full, w is already a vertex, or a new face degenerates or comes closer to the
// origin than `lower` (the closest face), returns false and leaves the polytope (and `next`) as it was.
template <class T>
bool expand(Polytope<T>& poly, std::uint32_t best, const SupportPoint<T>& p, T lower, T tolerance, ClosestTracker<T>& next) {
  if (poly.pointCount == kEpaMaxPoints) return false;
  // A support point already in the polytope (a cone's apex, a box corner reached again) would fold the polytope.
  for (std::uint32_t i = 0; i < poly.pointCount; ++i)
    if ((poly.points[i].w - p.w).squaredNorm() <= tolerance * tolerance) return false;
  const std::uint32_t newIndex = poly.pointCount;
  poly.points[newIndex] = p;
  Horizon horizon;
  std::array<std::uint32_t, kEpaMaxFaces> freeSlots;
  std::uint32_t freeCount = 0;
  ClosestTracker<T> kept;
  for (std::uint32_t i = 0; i < poly.faceCount; ++i) {
    const EpaFace<T>& f = poly.faces[i];
    if (!f.alive) continue;
    // Faces coplanar with w within tolerance stay (a consistent verdict on flat patches: cylinder caps, cone
    // bases), so the removed region stays a disk and its boundary one loop.
    if (i != best && !(f.n.dot(p.w - poly.points[f.v[0]].w) > tolerance)) {
      kept.offer(f, i);
      continue;
    }
    freeSlots[freeCount++] = i;
    for (int e = 0; e < 3; ++e) horizon.toggle(Edge{f.v[e], f.v[(e + 1) % 3]});
  }
  if (horizon.overflow || poly.faceCount + horizon.count > kEpaMaxFaces + freeCount) return false;
  std::array<EpaFace<T>, kEpaMaxHorizon> added;
  // The polytope only grows, so no plane may come closer to the origin than the closest face did: a new face that
  // does is a rounding-flipped sliver (w nearly on a horizon edge, e.g. between two close rim points in float).
  for (std::uint32_t k = 0; k < horizon.count; ++k)
    if (!makeFace(poly, horizon.edges[k].first, horizon.edges[k].second, newIndex, added[k]) ||
        added[k].dist < lower - tolerance)
      return false;
  ++poly.pointCount;
  for (std::uint32_t k = 0; k < freeCount; ++k) poly.faces[freeSlots[k]].alive = false;
  for (std::uint32_t k = 0; k < horizon.count; ++k) {
    const std::uint32_t slot = k < freeCount ? freeSlots[k] : poly.faceCount++;
    poly.faces[slot] = added[k];
    kept.offer(added[k], slot);
  }
  if (kept.best == std::numeric_limits<std::uint32_t>::max()) kept.best = poly.faceCount;
  next = kept;
  return true;
}

// Core witnesses of the origin's projection q on face f (barycentric in the face).
template <class T> void faceWitnesses(const Polytope<T>& poly, const EpaFace<T>& f, Vec3<T>& coreA, Vec3<T>& coreB) {
  GjkSimplex<T> tri;
  tri.size = 3;
  for (int k = 0; k < 3; ++k) tri.points[k] = poly.points[f.v[k]];
  const Vec3<T>&p0 = tri.points[0].w, &p1 = tri.points[1].w, &p2 = tri.points[2].w;
  const Vec3<T> q = f.n * f.dist;
  const Vec3<T> n = (p1 - p0).cross(p2 - p0);
  const T nn = n.squaredNorm();
  const T l0 = n.dot((p1 - q).cross(p2 - q)) / nn;
  const T l1 = n.dot((p2 - q).cross(p0 - q)) / nn;
  simplexWitnesses(tri, {l0, l1, T(1) - l0 - l1, T(0)}, coreA, coreB);
}

template <class T>
void finishPenetration(const ConvexShape<T>& a, const ConvexShape<T>& b, const Vec3<T>& coreA, const Vec3<T>& coreB,
                       const Vec3<T>& n, T coreDepth, EpaResult<T>& r) {
  r.normal = n;
  r.depth = std::max(T(0), coreDepth) + a.margin + b.margin;
  r.point0 = coreA + a.margin * n;
  r.point1 = coreB - b.margin * n;
}

// Upper bound refinement for curved support maps: around a direction n, three support points at directions tilted
// by `tilt` span a plane whose normal m is the boundary's normal there when the support region is flat or ruled
// (cylinder caps and sides, cone sides): h_D(m) then drops to the exact depth. Keeps m when it lowers the bound.
inline constexpr std::array<double, 4> kRefineTilts = {1e-1, 1e-2, 1e-4, 1e-6};

template <class T>
void refineUpperBound(SupportMap<T>& sa, SupportMap<T>& sb, Vec3<T> n, T& upper, SupportPoint<T>& upperPoint) {
  for (const double tilt : kRefineTilts) {
    const auto [e1, e2] = orthonormalPair(n);
    const T t(tilt), c = T(0.5), s = T(0.8660254037844386);
    const Vec3<T> p0 = supportOfDifference(sa, sb, Vec3<T>(n + t * e1)).w;
    const Vec3<T> p1 = supportOfDifference(sa, sb, Vec3<T>(n + t * (-c * e1 + s * e2))).w;
    const Vec3<T> p2 = supportOfDifference(sa, sb, Vec3<T>(n + t * (-c * e1 - s * e2))).w;
    Vec3<T> m = (p1 - p0).cross(p2 - p0);
    if (!(m.squaredNorm() > T(0)) || !isFinite(m)) continue;
    m.normalize();
    if (m.dot(n) < T(0)) m = -m;
    const SupportPoint<T> p = supportOfDifference(sa, sb, m);
    const T h = m.dot(p.w);
    if (h < upper) {
      upper = h;
      upperPoint = p;
      n = m;
    }
  }
}

// Upper bound refinement for smooth support maps (balls, rounded user shapes): fits the osculating sphere of D's
// boundary at the support point s(n) (radius from the support's derivative along two tangents: s(n + t e) - s(n) is
// about R t e) and moves n to the normal of that sphere's point nearest to the origin, -C/|C| with C = s(n) - R n:
// Newton's step on the depth, exact on a ball. Stops when a step no longer lowers the bound.
inline constexpr double kOsculatingTilt = 1e-3;
inline constexpr std::uint32_t kOsculatingSteps = 6;

template <class T>
void osculatingSteps(SupportMap<T>& sa, SupportMap<T>& sb, Vec3<T> n, T& upper, SupportPoint<T>& upperPoint) {
  const T tilt(kOsculatingTilt);
  for (std::uint32_t step = 0; step < kOsculatingSteps; ++step) {
    const auto [e1, e2] = orthonormalPair(n);
    const Vec3<T> s0 = supportOfDifference(sa, sb, n).w;
    const T r1 = (supportOfDifference(sa, sb, Vec3<T>(n + tilt * e1)).w - s0).dot(e1) / tilt;
    const T r2 = (supportOfDifference(sa, sb, Vec3<T>(n + tilt * e2)).w - s0).dot(e2) / tilt;
    if (!(r1 > T(0) && r2 > T(0))) return;  // flat or ruled there: the plane fit's case
    const Vec3<T> centre = s0 - T(0.5) * (r1 + r2) * n;
    if (!(centre.squaredNorm() > T(0))) return;
    const Vec3<T> m = -centre.normalized();
    const SupportPoint<T> p = supportOfDifference(sa, sb, m);
    const T h = m.dot(p.w);
    if (!(h < upper)) return;
    upper = h;
    upperPoint = p;
    n = m;
  }
}

// Refines from the normal of every face that could still hide a lower bound (f.dist < upper: the minimum's basin may
// be any of them, e.g. a cylinder's cap while the side's ring took the iterations) and from the best direction.
template <class T>
void refineFromFaces(const Polytope<T>& poly, SupportMap<T>& sa, SupportMap<T>& sb, T tolerance, T& upper,
                     SupportPoint<T>& upperPoint) {
  refineUpperBound(sa, sb, Vec3<T>(upperPoint.d.normalized()), upper, upperPoint);
  for (std::uint32_t i = 0; i < poly.faceCount; ++i)
    if (poly.faces[i].alive && poly.faces[i].dist < upper - tolerance)
      refineUpperBound(sa, sb, poly.faces[i].n, upper, upperPoint);
  osculatingSteps(sa, sb, Vec3<T>(upperPoint.d.normalized()), upper, upperPoint);
}

// A pair outside the scales GJK/EPA square safely runs rescaled (pair_scale.h), its start simplex with it.
template <class T>
[[gnu::noinline]] void penetrationRescaled(const ConvexShape<T>& a, const ConvexShape<T>& b, const GjkSimplex<T>* start,
                                           T factor, EpaResult<T>& r) {
  GjkSimplex<T> scaledStart;
  if (start) {
    scaledStart = *start;
    scaleSimplex(scaledStart, factor);
  }
  const ConvexShape<T> sa = scaledShape(a, factor), sb = scaledShape(b, factor);
  r = epaPenetration(sa, sb, start ? &scaledStart : nullptr);
  const T back = T(1) / factor;
  r.depth *= back;
  r.point0 *= back;
  r.point1 *= back;
  keepHints(sa, a), keepHints(sb, b);
}

}  // namespace

template <class T>
EpaResult<T> epaPenetration(const ConvexShape<T>& a, const ConvexShape<T>& b, const GjkSimplex<T>* start) {
  const T length = gjkPairLength(a, b);
  EpaResult<T> r;
  if (needsRescale(length)) {
    penetrationRescaled(a, b, start, rescaleFactor(length), r);
    return r;
  }
  GjkSimplex<T> s;
  if (start && start->size > 0) {
    s = *start;
  } else {
    const GjkResult<T> g = gjkDistance(a, b);
    if (!g.coresOverlap) {
      r.status = g.status;
      r.depth = std::max(T(0), -g.distance);
      r.normal = g.normal;
      r.point0 = g.point0;
      r.point1 = g.point1;
      r.iterations = g.iterations;
      return r;
    }
    s = g.simplex;
  }
  const T tolerance = gjkToleranceFor(length);
  SupportMap<T> sa(a), sb(b);
  Vec3<T> flatNormal = Vec3<T>::UnitX();
  Polytope<T> poly;
  if (!liftToTetrahedron(sa, sb, tolerance, s, flatNormal) || !buildTetrahedron(s, poly)) {
    // D is flat (e.g. two segments): the origin lies on its boundary, the core depth is 0 along flatNormal.
    const SimplexClosest<T> c = closestOnSimplex(s);
    Vec3<T> coreA, coreB;
    simplexWitnesses(s, c.lambda, coreA, coreB);
    finishPenetration(a, b, coreA, coreB, flatNormal, T(0), r);
    return r;
  }
  // Best face (a copy: expand may reuse its slot) and best upper bound with its support point.
  EpaFace<T> f;
  T gap = std::numeric_limits<T>::infinity(), lower = T(0), upper = std::numeric_limits<T>::infinity();
  SupportPoint<T> upperPoint{};
  std::uint32_t it = 0;
  std::uint32_t best = closestFace(poly, lower);
  while (it < kEpaMaxIterations) {
    if (best == poly.faceCount) break;  // every face is final
    ++it;
    f = poly.faces[best];
    const SupportPoint<T> p = supportOfDifference(sa, sb, f.n);
    const T h = f.n.dot(p.w);
    gap = h - f.dist;  // h_D(n) - face distance >= 0: the error bound of this face
    if (h < upper) { upper = h; upperPoint = p; }
    if (gap <= tolerance || upper - lower <= tolerance) break;
    ClosestTracker<T> next;
    if (expand(poly, best, p, lower, tolerance, next)) {
      best = next.best;
      lower = next.lower;
    } else {
      poly.faces[best].final = true;
      best = closestFace(poly, lower);
    }
  }
  r.iterations = it;
  // The face converged and is the closest of all: a closer final face (kept when its expansion failed) would make
  // it no minimum (a float hull pair: a face 2.125 deep converged beside a final one 1.64, the depth being 1.71).
  if (gap <= tolerance && f.dist <= lower + tolerance) {
    Vec3<T> coreA, coreB;
    faceWitnesses(poly, f, coreA, coreB);
    finishPenetration(a, b, coreA, coreB, f.n, f.dist, r);
    return r;
  }
  if (!std::isfinite(upper)) {
    r.status = Status::notConverged("EPA found no face to expand");
    return r;
  }
  refineFromFaces(poly, sa, sb, tolerance, upper, upperPoint);
  // The best upper bound: its support point touches along its direction once translated by it.
  const Vec3<T> n = upperPoint.d.normalized();
  finishPenetration(a, b, upperPoint.a, upperPoint.b, n, upper, r);
  const T curved = T(kEpaCurvedTolerance) * (a.size + b.size);  // the size of D = A - B
  if (!(upper - lower <= std::max(tolerance, curved)))
    r.status = Status::notConverged("EPA stopped without a certified depth").withIterations(it, float(upper - lower));
  return r;
}

template EpaResult<float> epaPenetration<float>(const ConvexShape<float>&, const ConvexShape<float>&, const GjkSimplex<float>*);
template EpaResult<double> epaPenetration<double>(const ConvexShape<double>&, const ConvexShape<double>&, const GjkSimplex<double>*);

}  // namespace gq::kernels
