// Sphere/capsule against an unscaled cooked hull in the hull's frame (see rounded_hull.h).
#include "penetration/rounded_hull.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "gq/tolerances.h"
#include "shapes/segment.h"

namespace gq::detail {
namespace {

template <class T> struct RoundedHullScratch {
  std::vector<T> s0, s1;  // per polygon: the signed plane distances of the core's endpoints
  std::vector<T> along;   // per polygon: normal . (unit core direction)
};
template <class T> RoundedHullScratch<T>& roundedHullScratch() {
  thread_local RoundedHullScratch<T> s;
  return s;
}

// Whether q (on the polygon's plane) lies inside the polygon (counter-clockwise seen from outside).
template <class T> bool insidePolygon(const ConvexMesh<T>& mesh, const HullPolygon<T>& f, const Vec3<T>& q) {
  const std::uint32_t* loop = mesh.polygonVertices.data() + f.indexBase;
  for (std::uint32_t i = 0; i < f.indexCount; ++i) {
    const Vec3<T>& v0 = mesh.vertices[loop[i]];
    const Vec3<T>& v1 = mesh.vertices[loop[i + 1 < f.indexCount ? i + 1 : 0]];
    if ((v1 - v0).cross(q - v0).dot(f.normal) < T(0)) return false;
  }
  return true;
}

// Push-outs of the core (c0, c1) along both signs of a unit axis, from all hull vertices; keeps the smaller.
template <class T>
void axisBothSigns(const ConvexMesh<T>& mesh, const Vec3<T>& c0, const Vec3<T>& c1, const Vec3<T>& axis, T& best,
                   Vec3<T>& bestAxis) {
  T lo = std::numeric_limits<T>::max(), hi = -std::numeric_limits<T>::max();
  for (const Vec3<T>& v : mesh.vertices) {
    const T d = v.dot(axis);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  const T a = c0.dot(axis), b = c1.dot(axis);
  const T positive = hi - std::min(a, b), negative = std::max(a, b) - lo;
  if (positive < best) best = positive, bestAxis = axis;
  if (negative < best) best = negative, bestAxis = -axis;
}

}  // namespace

template <class T>
bool penetrationRoundedHull(const RoundedCore<T>& core, const ConvexMeshGeometry<T>& hull, const Transform<T>& pose,
                            bool& penetrating, Vec3<T>& direction, T& depth) {
  if (!hull.scale.isIdentity() || !hull.mesh) return false;
  const ConvexMesh<T>& mesh = *hull.mesh;
  const std::size_t faces = mesh.polygons.size();
  if (faces == 0) return false;
  const T eps = T(tol::Rel<T>::kEpsilon);
  const bool point = !((core.segment.b - core.segment.a).squaredNorm() > T(0));
  const Vec3<T> c0 = pose.transformInv(core.segment.a);
  const Vec3<T> c1 = point ? c0 : pose.transformInv(core.segment.b);
  RoundedHullScratch<T>& s = roundedHullScratch<T>();
  s.s0.resize(faces);
  s.s1.resize(faces);
  // Face planes: the separating gap (largest min(s0, s1)) and the clipping of the core by every plane.
  T gap = -std::numeric_limits<T>::max();
  std::size_t gapFace = 0;
  T tIn = T(0), tOut = T(1);
  bool meets = true;
  for (std::size_t f = 0; f < faces; ++f) {
    const HullPolygon<T>& p = mesh.polygons[f];
    if (p.indexCount < 3) return false;
    const T a = p.normal.dot(c0) + p.d;
    const T b = point ? a : p.normal.dot(c1) + p.d;
    s.s0[f] = a;
    s.s1[f] = b;
    const T low = std::min(a, b);
    if (low > gap) gap = low, gapFace = f;
    if (a > T(0) && b > T(0))
      meets = false;
    else if (a > T(0))
      tIn = std::max(tIn, a / (a - b));
    else if (b > T(0))
      tOut = std::min(tOut, a / (a - b));
  }
  if (gap > core.radius) return penetrating = false, true;

  if (meets && tIn <= tOut && !(gap > T(0))) {
    // The core meets the hull: the minimum over the facets of hull - core (faces, then segment-edge crossings).
    T push = -gap;
    Vec3<T> axis = mesh.polygons[gapFace].normal;
    if (!point) {
      const std::shared_ptr<const PolytopeTopology> topology = hullTopology(hull.mesh);
      const PolytopeTopology& topo = *topology;
      if (!topo.edgeFacesKnown || topo.facePolygon.size() != faces) return false;
      const Vec3<T> u = (c1 - c0).normalized();
      s.along.resize(faces);
      for (std::size_t f = 0; f < faces; ++f) s.along[f] = mesh.polygons[f].normal.dot(u);
      for (std::size_t e = 0; e < topo.edges.size(); ++e) {
        const std::uint32_t f1 = topo.edgeFaces[e][0], f2 = topo.edgeFaces[e][1];
        const T a1 = s.along[f1], a2 = s.along[f2];
        const Vec3<T>& n1 = mesh.polygons[f1].normal;
        const Vec3<T>& n2 = mesh.polygons[f2].normal;
        const T product = a1 * a2;
        // The arc misses the great circle perpendicular to u, unless it is flat (|n1 x n2|^2 = 1 - (n1.n2)^2 below
        // kEpsilon: its faces (nearly) coplanar or opposite, the arc undecided).
        const auto flatArc = [&] {
          const T cosine = n1.dot(n2);
          return !(T(1) - cosine * cosine > eps);
        };
        if (product > eps * eps && !flatArc()) continue;
        const bool flat = flatArc();
        const Vec3<T>& v0 = mesh.vertices[topo.edges[e][0]];
        const Vec3<T> c = u.cross((mesh.vertices[topo.edges[e][1]] - v0).normalized());
        const T len2 = c.squaredNorm();
        if (len2 <= eps * eps) continue;  // parallel to the core: no facet of their own
        Vec3<T> k = c / std::sqrt(len2);
        // The O(1) push-out needs the crossing inside the arc for certain: both faces' signs clear of their rounding
        // (a normal's direction is good to about sqrt(kEpsilon) in float); otherwise both signs in full.
        const T clear = std::sqrt(eps);
        if (!flat && ((a1 > clear && a2 < -clear) || (a1 < -clear && a2 > clear))) {
          if (k.dot(n1 + n2) < T(0)) k = -k;  // the crossing inside the edge's arc
          const T value = k.dot(v0 - c0);
          if (value < push) push = value, axis = k;
        } else {
          axisBothSigns(mesh, c0, c1, k, push, axis);
        }
      }
    }
    if (push >= T(0)) {
      penetrating = true;
      direction = pose.rotate(axis);
      depth = push + core.radius;
      return true;
    }
  }

  // The core outside (or touching): its distance to the faces it sees. The gap's face first: the distance is at
  // least the gap, so once a face gives that, no other can give less.
  T best = std::numeric_limits<T>::max();
  Vec3<T> onCore = c0, onHull = c0;
  bool faceInterior = false;
  std::size_t bestFace = gapFace;
  Vec3<T> bestEdge = Vec3<T>::Zero();  // the hull edge (v1 - v0) of a segment-edge closest pair
  const auto visit = [&](std::size_t f) {
    const T a = s.s0[f], b = s.s1[f];
    if (!(a > T(0)) && !(b > T(0))) return;
    const T lower = (a > T(0) && b > T(0)) ? std::min(a, b) : T(0);
    if (lower >= best) return;
    const HullPolygon<T>& p = mesh.polygons[f];
    if (a > T(0) && a < best) {
      const Vec3<T> q = c0 - p.normal * a;
      if (insidePolygon(mesh, p, q)) best = a, onCore = c0, onHull = q, faceInterior = true, bestFace = f;
    }
    if (!point && b > T(0) && b < best) {
      const Vec3<T> q = c1 - p.normal * b;
      if (insidePolygon(mesh, p, q)) best = b, onCore = c1, onHull = q, faceInterior = true, bestFace = f;
    }
    const std::uint32_t* loop = mesh.polygonVertices.data() + p.indexBase;
    for (std::uint32_t i = 0; i < p.indexCount; ++i) {
      const Vec3<T>& v0 = mesh.vertices[loop[i]];
      const Vec3<T>& v1 = mesh.vertices[loop[i + 1 < p.indexCount ? i + 1 : 0]];
      Vec3<T> x = c0, y;
      if (point) {
        y = closestPointOnSegment(v0, v1, c0);
      } else {
        const SegmentClosest<T> cp = closestSegmentSegment(c0, c1, v0, v1);
        x = cp.c0;
        y = cp.c1;
      }
      const T d = (x - y).norm();
      if (d < best) best = d, onCore = x, onHull = y, faceInterior = false, bestEdge = point ? Vec3<T>::Zero() : Vec3<T>(v1 - v0);
    }
  };
  visit(gapFace);
  for (std::size_t f = 0; f < faces && best > gap; ++f)
    if (f != gapFace) visit(f);
  if (best == std::numeric_limits<T>::max()) best = T(0);  // no face sees the core: it touches the boundary
  if (best > core.radius) return penetrating = false, true;
  // A face's normal where the closest points lie on that face's facet (the difference of nearly coincident closest
  // points is not a direction: its angle error is about eps * size / distance, first order in the push-out along a
  // face contact); elsewhere the offset between them.
  const T scale = core.radius + (c1 - c0).norm() + onHull.cwiseAbs().maxCoeff() + pose.p.cwiseAbs().maxCoeff();
  Vec3<T> axis;
  if (faceInterior)
    axis = mesh.polygons[bestFace].normal;
  else if (std::abs(gap - best) <= eps * scale || !(best > T(0)))
    axis = mesh.polygons[gapFace].normal;
  else {
    axis = (onCore - onHull) / best;
    // Between the core's interior and a hull edge's interior the offset is perpendicular to both: their normalised
    // cross product is the same direction without the closest points' rounding (in float, nearly parallel segments
    // place them ~1e-3 off along the segments, which tilts the offset).
    const Vec3<T> cross = (c1 - c0).cross(bestEdge);
    const T len = cross.norm(), lengths = (c1 - c0).norm() * bestEdge.norm();
    if (len > std::sqrt(eps) * lengths) {
      const Vec3<T> normal = cross / len;
      const T agree = normal.dot(axis);
      if (std::abs(agree) >= T(1) - eps) axis = agree > T(0) ? normal : Vec3<T>(-normal);
    }
  }
  penetrating = true;
  direction = pose.rotate(axis);
  depth = core.radius - best;
  return true;
}

template bool penetrationRoundedHull<float>(const RoundedCore<float>&, const ConvexMeshGeometry<float>&,
                                            const Transform<float>&, bool&, Vec3<float>&, float&);
template bool penetrationRoundedHull<double>(const RoundedCore<double>&, const ConvexMeshGeometry<double>&,
                                             const Transform<double>&, bool&, Vec3<double>&, double&);

}  // namespace gq::detail
