// Polytope construction, exact SAT and exact point/segment-to-polytope distance (see polytope.h).
#include "overlap/polytope.h"

#include <algorithm>
#include <limits>

#include "gq/tolerances.h"

namespace gq::detail {
namespace {

template <class T> void addFace(Polytope<T>& poly, const Vec3<T>& normal, std::initializer_list<std::uint32_t> loop) {
  poly.faceNormals.push_back(normal);
  poly.faceOffsets.push_back(-normal.dot(poly.vertices[*loop.begin()]));
  poly.faceVertices.insert(poly.faceVertices.end(), loop.begin(), loop.end());
  poly.faceBegin.push_back(static_cast<std::uint32_t>(poly.faceVertices.size()));
}

template <class T> struct Interval {
  T lo, hi;
};
template <class T> Interval<T> project(const std::vector<Vec3<T>>& pts, const Vec3<T>& axis) {
  Interval<T> r{std::numeric_limits<T>::max(), std::numeric_limits<T>::lowest()};
  for (const Vec3<T>& p : pts) {
    const T x = p.dot(axis);
    r.lo = std::min(r.lo, x);
    r.hi = std::max(r.hi, x);
  }
  return r;
}

// Overlap of the projections on a unit axis, as the smaller of the two push-outs of shape a:
// along +axis a must move hi_b - lo_a, along -axis hi_a - lo_b.
template <class T> void testAxis(const Polytope<T>& a, const Polytope<T>& b, const Vec3<T>& axis, SatResult<T>& best) {
  const Interval<T> ia = project(a.vertices, axis), ib = project(b.vertices, axis);
  const T pushPositive = ib.hi - ia.lo, pushNegative = ia.hi - ib.lo;
  const T overlap = std::min(pushPositive, pushNegative);
  if (overlap < best.depth) {
    best.depth = overlap;
    best.direction = pushPositive <= pushNegative ? axis : Vec3<T>(-axis);
  }
}

template <class T> bool insidePolygon(const Polytope<T>& poly, std::size_t f, const Vec3<T>& q) {
  const Vec3<T>& n = poly.faceNormals[f];
  const std::uint32_t begin = poly.faceBegin[f], end = poly.faceBegin[f + 1];
  for (std::uint32_t i = begin; i < end; ++i) {
    const Vec3<T>& v0 = poly.vertices[poly.faceVertices[i]];
    const Vec3<T>& v1 = poly.vertices[poly.faceVertices[i + 1 < end ? i + 1 : begin]];
    if ((v1 - v0).cross(q - v0).dot(n) < T(0)) return false;
  }
  return true;
}

// An edge's Gauss-map arc: the normals n1, n2 of its two faces (negated for the subtracted shape), the arc's
// plane normal n1 x n2 and the unit edge direction.
template <class T> struct EdgeArc {
  Vec3<T> n1, n2, plane, dir;
};

template <class T> std::vector<EdgeArc<T>> edgeArcs(const Polytope<T>& poly, T sign) {
  std::vector<EdgeArc<T>> arcs;
  arcs.reserve(poly.edges.size());
  for (std::size_t i = 0; i < poly.edges.size(); ++i) {
    const Vec3<T> n1 = poly.faceNormals[poly.edgeFaces[i][0]] * sign, n2 = poly.faceNormals[poly.edgeFaces[i][1]] * sign;
    const Vec3<T> d = poly.vertices[poly.edges[i][1]] - poly.vertices[poly.edges[i][0]];
    arcs.push_back({n1, n2, n1.cross(n2), d.normalized()});
  }
  return arcs;
}

// Whether q (on the arc's great circle) lies between the arc's ends, with slack `slack`.
template <class T> bool onArc(const EdgeArc<T>& arc, const Vec3<T>& q, T slack) {
  return arc.n1.cross(q).dot(arc.plane) >= -slack && q.cross(arc.n2).dot(arc.plane) >= -slack;
}

// Whether two Gauss-map arcs (each shorter than a half circle) may cross. Conservative: near-degenerate
// configurations answer true, since an extra axis never makes SAT wrong, a missing one would.
template <class T> bool arcsMayCross(const EdgeArc<T>& a, const EdgeArc<T>& c) {
  const T tol = T(tol::Rel<T>::kEpsilon);
  const Vec3<T> p = a.plane.cross(c.plane);  // the great circles meet at +-p
  const T len = p.norm();
  if (len <= tol) return true;
  const T slack = tol * len;
  return (onArc(a, p, slack) && onArc(c, p, slack)) || (onArc(a, Vec3<T>(-p), slack) && onArc(c, Vec3<T>(-p), slack));
}

// Edge-edge axes of a and b whose edges can form a face of the Minkowski difference a - b: the normal cone of
// a's edge (arc between its face normals) must cross the negated normal cone of b's edge.
template <class T> void testPrunedEdgeAxes(const Polytope<T>& a, const Polytope<T>& b, bool stopWhenSeparated,
                                           SatResult<T>& best) {
  const T eps = T(tol::Rel<T>::kEpsilon);
  const std::vector<EdgeArc<T>> arcsA = edgeArcs(a, T(1)), arcsB = edgeArcs(b, T(-1));
  for (const EdgeArc<T>& ea : arcsA) {
    for (const EdgeArc<T>& eb : arcsB) {
      if (!arcsMayCross(ea, eb)) continue;
      const Vec3<T> c = ea.dir.cross(eb.dir);
      const T len2 = c.squaredNorm();
      if (len2 <= eps * eps) continue;
      testAxis(a, b, Vec3<T>(c / std::sqrt(len2)), best);
      if (stopWhenSeparated && best.depth < T(0)) return;
    }
  }
}

}  // namespace

template <class T> Polytope<T> makePointPolytope(const Vec3<T>& p) {
  Polytope<T> poly;
  poly.vertices = {p};
  poly.faceBegin = {0};
  return poly;
}

template <class T> Polytope<T> makeSegmentPolytope(const Segment<T>& s) {
  Polytope<T> poly;
  poly.vertices = {s.a, s.b};
  poly.faceBegin = {0};
  const Vec3<T> d = s.b - s.a;
  if (d.squaredNorm() > T(0)) {
    poly.edges.push_back({0u, 1u});
    poly.edgeFaces.push_back({0u, 0u});  // none: edgeFacesKnown stays false
    poly.edgeDirections.push_back(d.normalized());
  }
  return poly;
}

// Vertex i has coordinate k at +halfExtent when bit k of i is set.
template <class T> Polytope<T> makeBoxPolytope(const BoxGeometry<T>& box, const Transform<T>& pose) {
  Polytope<T> poly;
  const Vec3<T>& h = box.halfExtents;
  for (std::uint32_t i = 0; i < 8; ++i) {
    const Vec3<T> local((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
    poly.vertices.push_back(pose.transform(local));
  }
  const Mat3<T> r = pose.q.toRotationMatrix();
  poly.faceBegin = {0};
  addFace<T>(poly, r.col(0), {1, 3, 7, 5});
  addFace<T>(poly, -r.col(0), {0, 4, 6, 2});
  addFace<T>(poly, r.col(1), {2, 6, 7, 3});
  addFace<T>(poly, -r.col(1), {0, 1, 5, 4});
  addFace<T>(poly, r.col(2), {4, 5, 7, 6});
  addFace<T>(poly, -r.col(2), {0, 2, 3, 1});
  // Faces are ordered +X, -X, +Y, -Y, +Z, -Z: the face of axis j on vertex i's side is 2j + (bit j clear).
  const auto faceOf = [](std::uint32_t i, std::uint32_t j) { return 2 * j + ((i & (1u << j)) ? 0u : 1u); };
  for (std::uint32_t i = 0; i < 8; ++i)
    for (std::uint32_t k = 0; k < 3; ++k)
      if (!(i & (1u << k))) {
        poly.edges.push_back({i, i | (1u << k)});
        poly.edgeFaces.push_back({faceOf(i, (k + 1) % 3), faceOf(i, (k + 2) % 3)});
      }
  poly.edgeFacesKnown = true;
  poly.satNormals = {r.col(0), r.col(1), r.col(2)};
  poly.edgeDirections = poly.satNormals;
  return poly;
}

// Scaled hull: x = pose(S v) with S symmetric; normals map by S^-T = S^-1 (then renormalised).
template <class T> Polytope<T> makeConvexPolytope(const ConvexMeshGeometry<T>& convex, const Transform<T>& pose) {
  const ConvexMesh<T>& mesh = *convex.mesh;
  const Mat3<T> s = convex.scale.toMatrix();
  const Mat3<T> r = pose.q.toRotationMatrix();
  const Mat3<T> normalMap = r * s.inverse();
  Polytope<T> poly;
  std::vector<std::array<std::uint32_t, 3>> sides;  // (lower vertex, upper vertex, face) per polygon side
  poly.vertices.reserve(mesh.vertices.size());
  for (const Vec3<T>& v : mesh.vertices) poly.vertices.push_back(pose.transform(s * v));
  poly.faceBegin = {0};
  for (const HullPolygon<T>& f : mesh.polygons) {
    if (f.indexCount < 3) continue;
    const Vec3<T> n = (normalMap * f.normal).normalized();
    poly.faceNormals.push_back(n);
    poly.faceOffsets.push_back(-n.dot(poly.vertices[mesh.polygonVertices[f.indexBase]]));
    const std::uint32_t face = std::uint32_t(poly.faceNormals.size() - 1);
    for (std::uint32_t i = 0; i < f.indexCount; ++i) {
      const std::uint32_t v0 = mesh.polygonVertices[f.indexBase + i];
      const std::uint32_t v1 = mesh.polygonVertices[f.indexBase + (i + 1) % f.indexCount];
      poly.faceVertices.push_back(v0);
      sides.push_back({std::min(v0, v1), std::max(v0, v1), face});
    }
    poly.faceBegin.push_back(static_cast<std::uint32_t>(poly.faceVertices.size()));
  }
  // Parallel faces repeat an axis; skipping them would cost more (O(F^2)) than the extra projection.
  poly.satNormals = poly.faceNormals;
  // Each edge appears once per adjacent face; pair them up (a manifold hull has exactly two per edge).
  std::sort(sides.begin(), sides.end());
  poly.edgeFacesKnown = true;
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j][0] == sides[i][0] && sides[j][1] == sides[i][1]) ++j;
    poly.edges.push_back({sides[i][0], sides[i][1]});
    poly.edgeFaces.push_back({sides[i][2], sides[j - 1][2]});
    if (j - i != 2) poly.edgeFacesKnown = false;
    i = j;
  }
  // Duplicated directions only matter on the direct edge-pair path, which runs for small products only.
  for (const auto& e : poly.edges) {
    const Vec3<T> d = poly.vertices[e[1]] - poly.vertices[e[0]];
    if (d.squaredNorm() > T(0)) poly.edgeDirections.push_back(d.normalized());
  }
  return poly;
}

template <class T> SatResult<T> satMinimumOverlap(const Polytope<T>& a, const Polytope<T>& b, bool stopWhenSeparated) {
  SatResult<T> best{std::numeric_limits<T>::max(), Vec3<T>::UnitX()};
  for (const Vec3<T>& n : a.satNormals) {
    testAxis(a, b, n, best);
    if (stopWhenSeparated && best.depth < T(0)) return best;
  }
  for (const Vec3<T>& n : b.satNormals) {
    testAxis(a, b, n, best);
    if (stopWhenSeparated && best.depth < T(0)) return best;
  }
  // Edge-edge axes; (nearly) parallel edges give no facet of the Minkowski difference and are skipped. Any unit
  // axis bounds the depth from above, so a slightly noisy axis never makes the answer wrong, only a zero one would.
  if (a.edgeFacesKnown && b.edgeFacesKnown &&
      a.edgeDirections.size() * b.edgeDirections.size() > kDirectEdgePairLimit) {
    testPrunedEdgeAxes(a, b, stopWhenSeparated, best);
    return best;
  }
  const T eps = T(tol::Rel<T>::kEpsilon);
  for (const Vec3<T>& ea : a.edgeDirections) {
    for (const Vec3<T>& eb : b.edgeDirections) {
      const Vec3<T> c = ea.cross(eb);
      const T len2 = c.squaredNorm();
      if (len2 <= eps * eps) continue;
      testAxis(a, b, Vec3<T>(c / std::sqrt(len2)), best);
      if (stopWhenSeparated && best.depth < T(0)) return best;
    }
  }
  return best;
}

// The closest boundary point to an outside point lies in the interior of a face that faces it (then it is the
// plane projection) or on an edge.
template <class T> ClosestResult<T> closestPointToPolytope(const Vec3<T>& p, const Polytope<T>& poly) {
  ClosestResult<T> best{std::numeric_limits<T>::max(), p, poly.vertices.front()};
  for (std::size_t f = 0; f < poly.faceCount(); ++f) {
    const T s = poly.faceNormals[f].dot(p) + poly.faceOffsets[f];
    if (!(s > T(0)) || s >= best.distance) continue;
    const Vec3<T> q = p - poly.faceNormals[f] * s;
    if (insidePolygon(poly, f, q)) best = {s, p, q};
  }
  for (const auto& e : poly.edges) {
    const Vec3<T> q = closestPointOnSegment(Segment<T>{poly.vertices[e[0]], poly.vertices[e[1]]}, p);
    const T d = (p - q).norm();
    if (d < best.distance) best = {d, p, q};
  }
  if (poly.edges.empty())
    for (const Vec3<T>& v : poly.vertices) {
      const T d = (p - v).norm();
      if (d < best.distance) best = {d, p, v};
    }
  return best;
}

// For a segment outside the polytope the minimum is attained at an endpoint or between the segment and a hull
// edge (an interior segment point facing a face interior means the segment is parallel to it: slide to either).
template <class T> ClosestResult<T> closestSegmentToPolytope(const Segment<T>& s, const Polytope<T>& poly) {
  ClosestResult<T> best = closestPointToPolytope(s.a, poly);
  const ClosestResult<T> atB = closestPointToPolytope(s.b, poly);
  if (atB.distance < best.distance) best = atB;
  for (const auto& e : poly.edges) {
    const SegmentPair<T> cp = closestPointsSegmentSegment(s, Segment<T>{poly.vertices[e[0]], poly.vertices[e[1]]});
    const T d = (cp.p0 - cp.p1).norm();
    if (d < best.distance) best = {d, cp.p0, cp.p1};
  }
  return best;
}

template <class T> RoundedCore<T> sphereCore(const SphereGeometry<T>& g, const Transform<T>& pose) {
  return {makePointPolytope(pose.p), Segment<T>{pose.p, pose.p}, g.radius};
}

template <class T> RoundedCore<T> capsuleCore(const CapsuleGeometry<T>& g, const Transform<T>& pose) {
  const Vec3<T> axis = pose.rotate(Vec3<T>(g.halfHeight, T(0), T(0)));
  const Segment<T> s{pose.p - axis, pose.p + axis};
  return {makeSegmentPolytope(s), s, g.radius};
}

template <class T> bool overlapRoundedPolytope(const RoundedCore<T>& r, const Polytope<T>& poly) {
  const SatResult<T> sat = satMinimumOverlap(r.core, poly, true);
  if (sat.depth >= T(0)) return true;
  if (-sat.depth > r.radius) return false;  // a separating gap bounds the distance from below
  return closestSegmentToPolytope(r.segment, poly).distance <= r.radius;
}

template <class T>
bool penetrationRoundedPolytope(const RoundedCore<T>& r, const Polytope<T>& poly, Vec3<T>& direction, T& depth) {
  const SatResult<T> sat = satMinimumOverlap(r.core, poly, false);
  if (sat.depth >= T(0)) {  // the core itself penetrates: PD(core) plus the radius
    direction = sat.direction;
    depth = sat.depth + r.radius;
    return true;
  }
  if (-sat.depth > r.radius) return false;
  const ClosestResult<T> c = closestSegmentToPolytope(r.segment, poly);
  if (c.distance > r.radius) return false;
  const Vec3<T> gap = c.onCore - c.onPoly;
  direction = c.distance > T(0) ? Vec3<T>(gap / c.distance) : sat.direction;
  depth = r.radius - c.distance;
  return true;
}

template <class T> bool overlapPolytopes(const Polytope<T>& a, const Polytope<T>& b) {
  return satMinimumOverlap(a, b, true).depth >= T(0);
}

template <class T> bool penetrationPolytopes(const Polytope<T>& a, const Polytope<T>& b, Vec3<T>& direction, T& depth) {
  const SatResult<T> sat = satMinimumOverlap(a, b, false);
  if (!(sat.depth >= T(0))) return false;
  direction = sat.direction;
  depth = sat.depth;
  return true;
}

template Polytope<float> makePointPolytope<float>(const Vec3<float>&);
template Polytope<float> makeSegmentPolytope<float>(const Segment<float>&);
template Polytope<float> makeBoxPolytope<float>(const BoxGeometry<float>&, const Transform<float>&);
template Polytope<float> makeConvexPolytope<float>(const ConvexMeshGeometry<float>&, const Transform<float>&);
template SatResult<float> satMinimumOverlap<float>(const Polytope<float>&, const Polytope<float>&, bool);
template ClosestResult<float> closestPointToPolytope<float>(const Vec3<float>&, const Polytope<float>&);
template ClosestResult<float> closestSegmentToPolytope<float>(const Segment<float>&, const Polytope<float>&);
template RoundedCore<float> sphereCore<float>(const SphereGeometry<float>&, const Transform<float>&);
template RoundedCore<float> capsuleCore<float>(const CapsuleGeometry<float>&, const Transform<float>&);
template bool overlapRoundedPolytope<float>(const RoundedCore<float>&, const Polytope<float>&);
template bool penetrationRoundedPolytope<float>(const RoundedCore<float>&, const Polytope<float>&, Vec3<float>&, float&);
template bool overlapPolytopes<float>(const Polytope<float>&, const Polytope<float>&);
template bool penetrationPolytopes<float>(const Polytope<float>&, const Polytope<float>&, Vec3<float>&, float&);
template Polytope<double> makePointPolytope<double>(const Vec3<double>&);
template Polytope<double> makeSegmentPolytope<double>(const Segment<double>&);
template Polytope<double> makeBoxPolytope<double>(const BoxGeometry<double>&, const Transform<double>&);
template Polytope<double> makeConvexPolytope<double>(const ConvexMeshGeometry<double>&, const Transform<double>&);
template SatResult<double> satMinimumOverlap<double>(const Polytope<double>&, const Polytope<double>&, bool);
template ClosestResult<double> closestPointToPolytope<double>(const Vec3<double>&, const Polytope<double>&);
template ClosestResult<double> closestSegmentToPolytope<double>(const Segment<double>&, const Polytope<double>&);
template RoundedCore<double> sphereCore<double>(const SphereGeometry<double>&, const Transform<double>&);
template RoundedCore<double> capsuleCore<double>(const CapsuleGeometry<double>&, const Transform<double>&);
template bool overlapRoundedPolytope<double>(const RoundedCore<double>&, const Polytope<double>&);
template bool penetrationRoundedPolytope<double>(const RoundedCore<double>&, const Polytope<double>&, Vec3<double>&, double&);
template bool overlapPolytopes<double>(const Polytope<double>&, const Polytope<double>&);
template bool penetrationPolytopes<double>(const Polytope<double>&, const Polytope<double>&, Vec3<double>&, double&);

}  // namespace gq::detail
