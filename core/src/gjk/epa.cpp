// Expanding Polytope Algorithm (van den Bergen 2001) on the Minkowski difference D = A - B of the cores.
// With the origin inside D, translating b by t*n separates the cores iff t > h_D(n) = max_{w in D} n.w, so the
// penetration depth is min over unit n of h_D(n): the distance from the origin to the closest face of D. EPA grows
// a polytope inside D towards that face; the margins are then added in closed form.
#include <cmath>
#include <utility>
#include <vector>

#include "gjk/gjk.h"
#include "gjk/simplex.h"

namespace gq::detail {
namespace {

template <class T> struct EpaFace {
  std::array<std::uint32_t, 3> v;  // outward (counter-clockwise seen from outside)
  Vec3<T> n;                       // outward unit normal
  T dist;                          // n . vertex: signed distance of the plane from the origin
  bool alive = true;
};

template <class T> struct Polytope {
  std::vector<SupportPoint<T>> points;
  std::vector<EpaFace<T>> faces;
};

template <class T> SupportPoint<T> supportOfDifference(const ConvexShape<T>& a, const ConvexShape<T>& b, const Vec3<T>& d) {
  SupportPoint<T> p;
  p.a = a.support(d);
  p.b = b.support(-d);
  p.w = p.a - p.b;
  return p;
}

// Face i-j-k with its outward normal; false when degenerate.
template <class T> bool makeFace(const Polytope<T>& poly, std::uint32_t i, std::uint32_t j, std::uint32_t k, EpaFace<T>& f) {
  const Vec3<T>&p0 = poly.points[i].w, &p1 = poly.points[j].w, &p2 = poly.points[k].w;
  const Vec3<T> n = (p1 - p0).cross(p2 - p0);
  const T len = n.norm();
  if (!(len > T(0))) return false;
  f.v = {i, j, k};
  f.n = n / len;
  f.dist = f.n.dot(p0);
  f.alive = true;
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
template <class T> std::vector<Vec3<T>> liftDirections(const GjkSimplex<T>& s) {
  if (s.size == 1) return {Vec3<T>::UnitX(), -Vec3<T>::UnitX(), Vec3<T>::UnitY(), -Vec3<T>::UnitY(), Vec3<T>::UnitZ(), -Vec3<T>::UnitZ()};
  if (s.size == 2) {
    const Vec3<T> e = s.points[1].w - s.points[0].w;
    if (!(e.squaredNorm() > T(0))) return liftDirections(GjkSimplex<T>{s.points, 1});
    const auto [e1, e2] = orthonormalPair(e);
    return {e1, -e1, e2, -e2};
  }
  const Vec3<T> n = (s.points[1].w - s.points[0].w).cross(s.points[2].w - s.points[0].w);
  if (!(n.squaredNorm() > T(0))) return liftDirections(GjkSimplex<T>{s.points, 2});
  const Vec3<T> u = n.normalized();
  return {u, -u};
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
bool liftToTetrahedron(const ConvexShape<T>& a, const ConvexShape<T>& b, T tolerance, GjkSimplex<T>& s, Vec3<T>& flatNormal) {
  while (s.size < 4) {
    T bestLift = T(-1), flattest = std::numeric_limits<T>::infinity();
    SupportPoint<T> best{};
    for (const Vec3<T>& d : liftDirections(s)) {
      const SupportPoint<T> p = supportOfDifference(a, b, d);
      const T lift = distanceFromHull(s, p.w);
      if (lift > bestLift) { bestLift = lift; best = p; }
      const T extent = d.dot(p.w);
      if (extent < flattest) { flattest = extent; flatNormal = d; }
    }
    if (!(bestLift > tolerance)) return false;
    s.points[s.size++] = best;
  }
  return true;
}

template <class T> bool buildTetrahedron(const GjkSimplex<T>& s, Polytope<T>& poly) {
  poly.points.assign(s.points.begin(), s.points.end());
  const Vec3<T> centroid = (s.points[0].w + s.points[1].w + s.points[2].w + s.points[3].w) / T(4);
  const std::array<std::array<std::uint32_t, 3>, 4> tris = {{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}};
  for (const auto& t : tris) {
    EpaFace<T> f;
    if (!makeFace(poly, t[0], t[1], t[2], f)) return false;
    if (f.n.dot(poly.points[t[0]].w - centroid) < T(0) && !makeFace(poly, t[0], t[2], t[1], f)) return false;
    poly.faces.push_back(f);
  }
  return true;
}

template <class T> std::uint32_t closestFace(const Polytope<T>& poly) {
  std::uint32_t best = 0;
  T bestDist = std::numeric_limits<T>::infinity();
  for (std::uint32_t i = 0; i < poly.faces.size(); ++i)
    if (poly.faces[i].alive && poly.faces[i].dist < bestDist) { bestDist = poly.faces[i].dist; best = i; }
  return best;
}

// Removes the faces that see `w` and closes the hole with faces fanning from w to the horizon edges.
template <class T> bool expand(Polytope<T>& poly, std::uint32_t best, const SupportPoint<T>& p) {
  const std::uint32_t newIndex = static_cast<std::uint32_t>(poly.points.size());
  poly.points.push_back(p);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> horizon;
  for (std::uint32_t i = 0; i < poly.faces.size(); ++i) {
    EpaFace<T>& f = poly.faces[i];
    if (!f.alive || (i != best && !(f.n.dot(p.w - poly.points[f.v[0]].w) > T(0)))) continue;
    f.alive = false;
    for (int e = 0; e < 3; ++e) {
      const std::pair<std::uint32_t, std::uint32_t> edge(f.v[e], f.v[(e + 1) % 3]);
      auto twin = std::find(horizon.begin(), horizon.end(), std::make_pair(edge.second, edge.first));
      if (twin != horizon.end()) horizon.erase(twin);
      else horizon.push_back(edge);
    }
  }
  for (const auto& [i, j] : horizon) {
    EpaFace<T> f;
    if (!makeFace(poly, i, j, newIndex, f)) return false;
    poly.faces.push_back(f);
  }
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

}  // namespace

template <class T>
EpaResult<T> epaPenetration(const ConvexShape<T>& a, const ConvexShape<T>& b, const GjkSimplex<T>* start) {
  EpaResult<T> r;
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
  const T tolerance = gjkTolerance(a, b);
  Vec3<T> flatNormal = Vec3<T>::UnitX();
  Polytope<T> poly;
  if (!liftToTetrahedron(a, b, tolerance, s, flatNormal) || !buildTetrahedron(s, poly)) {
    // D is flat (e.g. two segments): the origin lies on its boundary, the core depth is 0 along flatNormal.
    const SimplexClosest<T> c = closestOnSimplex(s);
    Vec3<T> coreA, coreB;
    simplexWitnesses(s, c.lambda, coreA, coreB);
    finishPenetration(a, b, coreA, coreB, flatNormal, T(0), r);
    return r;
  }
  std::uint32_t best = 0;
  T gap = std::numeric_limits<T>::infinity();
  std::uint32_t it = 0;
  while (it < kEpaMaxIterations) {
    ++it;
    best = closestFace(poly);
    const EpaFace<T> f = poly.faces[best];
    const SupportPoint<T> p = supportOfDifference(a, b, f.n);
    gap = f.n.dot(p.w) - f.dist;  // h_D(n) - face distance >= 0: the error bound of this face
    if (gap <= tolerance || !expand(poly, best, p)) break;
  }
  const EpaFace<T>& f = poly.faces[best];
  if (!(gap <= tolerance))
    r.status = Status::notConverged("EPA stopped after " + std::to_string(it) + " iterations with error bound " +
                                    std::to_string(double(gap)));
  Vec3<T> coreA, coreB;
  faceWitnesses(poly, f, coreA, coreB);
  finishPenetration(a, b, coreA, coreB, f.n, f.dist, r);
  r.iterations = it;
  return r;
}

template EpaResult<float> epaPenetration<float>(const ConvexShape<float>&, const ConvexShape<float>&, const GjkSimplex<float>*);
template EpaResult<double> epaPenetration<double>(const ConvexShape<double>&, const ConvexShape<double>&, const GjkSimplex<double>*);

}  // namespace gq::detail
