// Sphere/capsule against an unscaled cooked hull in the hull's frame (see rounded_hull.h).
#include "penetration/rounded_hull.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "gjk/support_map.h"
#include "gjk/support_table.h"
#include "gq/tolerances.h"
#include "penetration/gauss_tree.h"
#include "shapes/segment.h"

namespace gq::detail {
namespace {

template <class T> struct RoundedHullScratch {
  std::vector<std::pair<T, std::uint32_t>> heap;  // (lower bound, node) of the branch and bound
  std::vector<std::uint32_t> stack;                // nodes of the closest-point search
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

}  // namespace

template <class T>
bool penetrationRoundedHull(const RoundedCore<T>& core, const ConvexMeshGeometry<T>& hull, const Transform<T>& pose,
                            bool& penetrating, Vec3<T>& direction, T& depth) {
  if (!hull.scale.isIdentity() || !hull.mesh) return false;
  const GaussTree<T>* treePtr = hullGaussTree(hull.mesh);
  if (!treePtr || !treePtr->usable) return false;
  const GaussTree<T>& tree = *treePtr;
  const ConvexMesh<T>& mesh = *hull.mesh;
  const T eps = T(tol::Rel<T>::kEpsilon);
  const bool point = !((core.segment.b - core.segment.a).squaredNorm() > T(0));
  const Vec3<T> c0 = pose.transformInv(core.segment.a);
  const Vec3<T> c1 = point ? c0 : pose.transformInv(core.segment.b);
  const Vec3<T> u = point ? Vec3<T>::Zero() : Vec3<T>((c1 - c0).normalized());
  const SupportStartTable<T>* table = supportStartTable(hull.mesh);
  const bool climb = mesh.vertices.size() > kHillClimbMinVertices && hasAdjacency(mesh);
  std::uint32_t hint = 0;
  bool cold = true;
  const auto hullSupport = [&](const Vec3<T>& d) { return d.dot(mesh.vertices[hullVertex(mesh, table, climb, d, hint, cold)]); };
  // Rounding of the bounds: a few ulps of the coordinates, and the cooking's plane tolerance.
  const T magnitude = std::max(mesh.localBounds.min.cwiseAbs().maxCoeff(), mesh.localBounds.max.cwiseAbs().maxCoeff()) +
                      std::max(c0.cwiseAbs().maxCoeff(), c1.cwiseAbs().maxCoeff());
  const T margin = magnitude * (T(128) * std::numeric_limits<T>::epsilon() + T(4e-9));

  // Branch and bound for the minimum push-out over the facets of hull - core: the faces' -min(s(c0), s(c1)) and,
  // for a segment, the hull edges whose arc crosses the great circle perpendicular to it.
  RoundedHullScratch<T>& s = roundedHullScratch<T>();
  T best = std::numeric_limits<T>::max();
  Vec3<T> bestAxis = Vec3<T>::UnitX();
  std::uint32_t bestFace = 0;  // the face of the best facet, or a face beside its edge
  bool bestHasFace = false;
  const auto reachOf = [&](const typename GaussTree<T>::Node& node, const Vec3<T>& x) {
    const Vec3<T> z = x - node.centre;
    const T zc = node.axis.dot(z), z2 = z.squaredNorm();
    const T zp = std::sqrt(std::max(z2 - zc * zc, T(0)));
    return (zc > T(0) && zp * node.cosAngle <= zc * node.sinAngle) ? std::sqrt(z2) : zc * node.cosAngle + zp * node.sinAngle;
  };
  const auto nodeBound = [&](const typename GaussTree<T>::Node& node) {
    if (!node.bounded) return -std::numeric_limits<T>::max();
    const T r0 = reachOf(node, c0);
    return node.radius - (point ? r0 : std::min(r0, reachOf(node, c1)));
  };
  const auto axisBothSigns = [&](const Vec3<T>& k) {
    const T a = c0.dot(k), b = c1.dot(k);
    const T positive = hullSupport(k) - std::min(a, b), negative = std::max(a, b) + hullSupport(Vec3<T>(-k));
    if (positive < best) best = positive, bestAxis = k;
    if (negative < best) best = negative, bestAxis = -k;
  };
  const auto evaluateLeaf = [&](const typename GaussTree<T>::Node& node) {
    for (std::uint32_t f = node.faceBegin; f < node.faceEnd; ++f) {
      const Vec3<T>& n = tree.faceNormal[f];
      const T a = n.dot(c0) + tree.faceOffset[f];
      const T b = point ? a : n.dot(c1) + tree.faceOffset[f];
      const T push = -std::min(a, b);
      if (push < best) best = push, bestAxis = n, bestFace = f, bestHasFace = true;
    }
    if (point) return;
    for (std::uint32_t e = node.edgeBegin; e < node.edgeEnd; ++e) {
      const typename GaussTree<T>::Edge& edge = tree.edges[e];
      const Vec3<T>& n1 = tree.faceNormal[edge.face1];
      const Vec3<T>& n2 = tree.faceNormal[edge.face2];
      const T a1 = n1.dot(u), a2 = n2.dot(u);
      // The arc misses the great circle perpendicular to u, unless it is flat (|n1 x n2|^2 = 1 - (n1.n2)^2 below
      // kEpsilon: its faces (nearly) coplanar or opposite, the arc undecided).
      const T cosine = n1.dot(n2);
      const bool flat = !(T(1) - cosine * cosine > eps);
      if (a1 * a2 > eps * eps && !flat) continue;
      const Vec3<T>& v0 = mesh.vertices[edge.vertex0];
      const Vec3<T> c = u.cross((mesh.vertices[edge.vertex1] - v0).normalized());
      const T len2 = c.squaredNorm();
      if (len2 <= eps * eps) continue;  // parallel to the core: no facet of their own
      Vec3<T> k = c / std::sqrt(len2);
      // The O(1) push-out needs the crossing inside the arc for certain: both faces' signs clear of their rounding
      // (a normal's direction is good to about sqrt(kEpsilon) in float); otherwise both signs from support calls.
      const T clear = std::sqrt(eps);
      if (!flat && ((a1 > clear && a2 < -clear) || (a1 < -clear && a2 > clear))) {
        if (k.dot(n1 + n2) < T(0)) k = -k;  // the crossing inside the edge's arc
        const T value = k.dot(v0 - c0);
        if (value < best) best = value, bestAxis = k, bestFace = edge.face1, bestHasFace = true;
      } else {
        const T before = best;
        axisBothSigns(k);
        if (best < before) bestFace = edge.face1, bestHasFace = true;
      }
    }
  };
  s.heap.clear();
  s.heap.push_back({-std::numeric_limits<T>::max(), 0});
  while (!s.heap.empty()) {
    std::pop_heap(s.heap.begin(), s.heap.end(), std::greater<>());
    const auto entry = s.heap.back();
    s.heap.pop_back();
    if (!(entry.first - margin < best) || best < -core.radius) break;
    const typename GaussTree<T>::Node& node = tree.nodes[entry.second];
    if (node.leaf()) {
      evaluateLeaf(node);
      continue;
    }
    for (const std::uint32_t child : node.child) {
      const T bound = nodeBound(tree.nodes[child]);
      if (!(bound - margin < best)) continue;
      s.heap.push_back({bound, child});
      std::push_heap(s.heap.begin(), s.heap.end(), std::greater<>());
    }
  }
  if (best < -core.radius) return penetrating = false, true;  // a separating gap beyond the radius
  if (best >= T(0)) {  // the core meets the hull: the push-out plus the radius
    penetrating = true;
    direction = pose.rotate(bestAxis);
    depth = best + core.radius;
    return true;
  }
  const T gap = -best;

  // The core outside (or touching): its distance to the faces it sees, those of nodes whose cap may see it and whose
  // planes may pass closer than the best distance found. The gap's face (or a face beside the gap's edge) first: the
  // distance is at least the gap, so once a face gives that, no other can give less.
  T bestDistance = std::numeric_limits<T>::max();
  Vec3<T> onCore = c0, onHull = c0;
  bool faceInterior = false;
  std::uint32_t closestFace = bestFace;
  Vec3<T> bestEdge = Vec3<T>::Zero();  // the hull edge (v1 - v0) of a segment-edge closest pair
  const auto visit = [&](std::uint32_t f) {
    const Vec3<T>& n = tree.faceNormal[f];
    const T a = n.dot(c0) + tree.faceOffset[f];
    const T b = point ? a : n.dot(c1) + tree.faceOffset[f];
    if (!(a > T(0)) && !(b > T(0))) return;
    const T lower = (a > T(0) && b > T(0)) ? std::min(a, b) : T(0);
    if (lower >= bestDistance) return;
    const HullPolygon<T>& p = mesh.polygons[tree.facePolygon[f]];
    const std::uint32_t* loop = mesh.polygonVertices.data() + p.indexBase;
    if (point) {
      // The polygon's point closest to c0 is c0's projection q when q is inside; otherwise it lies on an edge whose
      // line q is outside of (at a vertex, q minus the vertex is in the cone of its two edges' outward normals, so q
      // is outside at least one of their lines), so only those edges are measured.
      const Vec3<T> q = c0 - p.normal * a;
      bool inside = true;
      for (std::uint32_t i = 0; i < p.indexCount; ++i) {
        const Vec3<T>& v0 = mesh.vertices[loop[i]];
        const Vec3<T>& v1 = mesh.vertices[loop[i + 1 < p.indexCount ? i + 1 : 0]];
        if (!((v1 - v0).cross(q - v0).dot(p.normal) < T(0))) continue;
        inside = false;
        const Vec3<T> y = closestPointOnSegment(v0, v1, c0);
        const T d = (c0 - y).norm();
        if (d < bestDistance) bestDistance = d, onCore = c0, onHull = y, faceInterior = false;
      }
      if (inside) bestDistance = a, onCore = c0, onHull = q, faceInterior = true, closestFace = f;
      return;
    }
    if (a > T(0) && a < bestDistance) {
      const Vec3<T> q = c0 - p.normal * a;
      if (insidePolygon(mesh, p, q)) bestDistance = a, onCore = c0, onHull = q, faceInterior = true, closestFace = f;
    }
    if (b > T(0) && b < bestDistance) {
      const Vec3<T> q = c1 - p.normal * b;
      if (insidePolygon(mesh, p, q)) bestDistance = b, onCore = c1, onHull = q, faceInterior = true, closestFace = f;
    }
    for (std::uint32_t i = 0; i < p.indexCount; ++i) {
      const Vec3<T>& v0 = mesh.vertices[loop[i]];
      const Vec3<T>& v1 = mesh.vertices[loop[i + 1 < p.indexCount ? i + 1 : 0]];
      const SegmentClosest<T> cp = closestSegmentSegment(c0, c1, v0, v1);
      const T d = (cp.c0 - cp.c1).norm();
      if (d < bestDistance) bestDistance = d, onCore = cp.c0, onHull = cp.c1, faceInterior = false, bestEdge = v1 - v0;
    }
  };
  // Per node, over its faces: s(x) <= max over the cap of n.(x - centre) - radius (a face seeing x needs > 0), and
  // s(x) >= min over the cap of n.(x - centre) - radiusMax (a face's distance is at least its smaller s when both
  // endpoints see it).
  const auto farOf = [&](const typename GaussTree<T>::Node& node, const Vec3<T>& x) {
    const Vec3<T> z = x - node.centre;
    const T zc = node.axis.dot(z), z2 = z.squaredNorm();
    const T zp = std::sqrt(std::max(z2 - zc * zc, T(0)));
    return (zc < T(0) && zp * node.cosAngle <= -zc * node.sinAngle) ? -std::sqrt(z2)
                                                                      : zc * node.cosAngle - zp * node.sinAngle;
  };
  // A closest pair at distance D is certified by its plane (through the hull point, normal u = the offset over D)
  // when the hull lies below it (u.x <= u.onHull for every hull point x: one support call, exact over the vertices)
  // and the core above (min over its endpoints of u.c >= u.onCore): every other pair is then at least D apart, less
  // the rounding allowance. Otherwise the search below measures every face that may be closer.
  const T roundingAllowance = T(64) * std::numeric_limits<T>::epsilon() * magnitude;
  const auto separatedAlong = [&](const Vec3<T>& onC, const Vec3<T>& onH, T distance) {
    if (!(distance > T(0)) || !(distance < std::numeric_limits<T>::max())) return false;
    const Vec3<T> axis = (onC - onH) / distance;
    const T coreLow = point ? axis.dot(c0) : std::min(axis.dot(c0), axis.dot(c1));
    if (!(coreLow - axis.dot(onC) >= -roundingAllowance)) return false;
    return hullSupport(axis) - axis.dot(onH) <= roundingAllowance;
  };
  if (bestHasFace) visit(bestFace);
  s.stack.clear();
  if (bestDistance > gap && !separatedAlong(onCore, onHull, bestDistance)) s.stack.push_back(0);
  while (!s.stack.empty() && bestDistance > gap) {
    const typename GaussTree<T>::Node& node = tree.nodes[s.stack.back()];
    s.stack.pop_back();
    if (node.bounded) {
      const T sees0 = reachOf(node, c0) - node.radius, sees1 = point ? sees0 : reachOf(node, c1) - node.radius;
      if (!(sees0 + margin > T(0)) && !(sees1 + margin > T(0))) continue;
      const T low0 = farOf(node, c0) - node.radiusMax, low1 = point ? low0 : farOf(node, c1) - node.radiusMax;
      if (std::min(low0, low1) - margin >= bestDistance) continue;
    }
    if (node.leaf()) {
      for (std::uint32_t f = node.faceBegin; f < node.faceEnd && bestDistance > gap; ++f)
        if (!bestHasFace || f != bestFace) visit(f);
    } else {
      s.stack.push_back(node.child[1]);
      s.stack.push_back(node.child[0]);
    }
  }
  if (bestDistance == std::numeric_limits<T>::max()) bestDistance = T(0);  // no face sees the core: it touches
  if (bestDistance > core.radius) return penetrating = false, true;
  // A face's normal where the closest points lie on that face's facet (the difference of nearly coincident closest
  // points is not a direction: its angle error is about eps * size / distance, first order in the push-out along a
  // face contact); the separating axis where it realises the distance; elsewhere the offset between them.
  const T scale = core.radius + (c1 - c0).norm() + onHull.cwiseAbs().maxCoeff() + pose.p.cwiseAbs().maxCoeff();
  Vec3<T> axis;
  if (faceInterior)
    axis = tree.faceNormal[closestFace];
  else if (std::abs(gap - bestDistance) <= eps * scale || !(bestDistance > T(0)))
    axis = bestAxis;
  else {
    axis = (onCore - onHull) / bestDistance;
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
  depth = core.radius - bestDistance;
  return true;
}

template bool penetrationRoundedHull<float>(const RoundedCore<float>&, const ConvexMeshGeometry<float>&,
                                            const Transform<float>&, bool&, Vec3<float>&, float&);
template bool penetrationRoundedHull<double>(const RoundedCore<double>&, const ConvexMeshGeometry<double>&,
                                             const Transform<double>&, bool&, Vec3<double>&, double&);

}  // namespace gq::detail
