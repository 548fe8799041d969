// Polytope construction, exact SAT and exact point/segment-to-polytope distance (see polytope.h).
//
// SAT as a search over the facets of the Minkowski difference A - B (a translation t of A makes A + t and B
// disjoint iff t leaves B - A; the push-out along a unit n is h_A(-n)... written below per axis family):
//  - face f of A (normal n, plane offset o): h_A(n) = -o, so A must move by -n a distance -o - min_B(n.x);
//  - face g of B (normal m, offset q): A must move by +m a distance -q - min_A(m.x);
//  - edge pair (ea of A, eb of B) whose Gauss-map arcs cross at p (p in ea's normal cone, -p in eb's): the support
//    points are the edges themselves, so A must move by -p a distance p.(vertex of ea - vertex of eb): O(1).
// Near-degenerate arc configurations are decided conservatively by projecting all vertices on both signs of the
// axis (an extra axis is never wrong, since any axis bounds the depth from above; a missing one would be).
#include "overlap/polytope.h"

#include <algorithm>
#include <limits>
#include <mutex>
#include <shared_mutex>
#include <unordered_map>

#include "gjk/gjk.h"
#include "gq/tolerances.h"
#include "shapes/hull_scale.h"

namespace gq::detail {
namespace {

// ---- projections (structure-of-arrays loops with independent accumulators) ----------------------------------

template <class T> T minDot(const Polytope<T>& p, const Vec3<T>& n) {
  const std::size_t count = p.xs.size();
  const T* x = p.xs.data();
  const T* y = p.ys.data();
  const T* z = p.zs.data();
  T m[4] = {std::numeric_limits<T>::max(), std::numeric_limits<T>::max(), std::numeric_limits<T>::max(),
            std::numeric_limits<T>::max()};
  std::size_t i = 0;
  for (; i + 4 <= count; i += 4)
    for (std::size_t k = 0; k < 4; ++k) {
      const T d = x[i + k] * n.x() + y[i + k] * n.y() + z[i + k] * n.z();
      m[k] = d < m[k] ? d : m[k];
    }
  for (; i < count; ++i) {
    const T d = x[i] * n.x() + y[i] * n.y() + z[i] * n.z();
    m[0] = d < m[0] ? d : m[0];
  }
  return std::min(std::min(m[0], m[1]), std::min(m[2], m[3]));
}

template <class T> T maxDot(const Polytope<T>& p, const Vec3<T>& n) { return -minDot(p, Vec3<T>(-n)); }

// Exact push-outs of a along both signs of a unit axis (from full projections); keeps the smaller in `best`.
template <class T> void testAxisBothSigns(const Polytope<T>& a, const Polytope<T>& b, const Vec3<T>& axis, SatResult<T>& best) {
  const T pushPositive = maxDot(b, axis) - minDot(a, axis), pushNegative = maxDot(a, axis) - minDot(b, axis);
  if (pushPositive < best.depth) best = {pushPositive, axis};
  if (pushNegative < best.depth) best = {pushNegative, Vec3<T>(-axis)};
}

template <class T> void consider(T push, const Vec3<T>& direction, SatResult<T>& best) {
  if (push < best.depth) best = {push, direction};
}

// ---- Gauss-map arcs of edges ------------------------------------------------------------------------------

// An edge's normal cone as a Gauss-map arc from n1 to n2 (negated for B, so that arcs of A and -B cross exactly
// at the facet normals of A - B); `plane` = n2 x n1 is the normal of the arc's great circle.
template <class T> struct EdgeArc {
  Vec3<T> n1, n2, plane;
  std::uint32_t vertex;  // one endpoint of the edge
  // Faces (nearly) coplanar or opposite, as at the rim of a hull scaled flat: `plane` is rounding noise and the arc
  // undecided, so facet normals come from the edge direction `direction` (unit; zero for a zero-length edge).
  bool flat;
  Vec3<T> direction;
};

// An arc with |n1 x n2| below sqrt(kEpsilon) is flat: the direction of `plane` is off by ~(normal rounding) / |plane|.
template <class T> bool isFlatArc(const Vec3<T>& plane) {
  const T flatSine = std::sqrt(T(tol::Rel<T>::kEpsilon));
  return !(plane.squaredNorm() > flatSine * flatSine);
}

template <class T> Vec3<T> edgeDirection(const Polytope<T>& poly, const std::array<std::uint32_t, 2>& edge) {
  return (poly.vertices[edge[1]] - poly.vertices[edge[0]]).stableNormalized();
}

template <class T> EdgeArc<T> edgeArc(const Polytope<T>& poly, std::size_t i, T sign) {
  const PolytopeTopology& topo = *poly.topology;
  const Vec3<T> n1 = poly.faceNormals[topo.edgeFaces[i][0]] * sign, n2 = poly.faceNormals[topo.edgeFaces[i][1]] * sign;
  const Vec3<T> plane = n2.cross(n1);
  const bool flat = isFlatArc(plane);
  const Vec3<T> direction = flat ? edgeDirection(poly, topo.edges[i]) : Vec3<T>::Zero();
  return {n1, n2, plane, topo.edges[i][0], flat, direction};
}

template <class T> void edgeArcs(const Polytope<T>& poly, T sign, std::vector<EdgeArc<T>>& arcs) {
  arcs.clear();
  for (std::size_t i = 0; i < poly.topology->edges.size(); ++i) arcs.push_back(edgeArc(poly, i, sign));
}

template <class T> void edgeArcs(const Polytope<T>& poly, T sign, const std::vector<std::uint32_t>& edges,
                                 std::vector<EdgeArc<T>>& arcs) {
  arcs.clear();
  for (const std::uint32_t i : edges) arcs.push_back(edgeArc(poly, i, sign));
}

enum class Crossing { No, Yes, Maybe };

// Arcs AB (of A) and CD (of -B) cross iff C and D lie on opposite sides of AB's great circle, A and B on
// opposite sides of CD's, and both arcs lie in one hemisphere (Gregorius, GDC 2013). Any sign within `eps` of
// zero is undecided.
template <class T> Crossing arcsCross(const EdgeArc<T>& ab, const EdgeArc<T>& cd, T eps) {
  const T cba = cd.n1.dot(ab.plane), dba = cd.n2.dot(ab.plane);
  const T adc = ab.n1.dot(cd.plane), bdc = ab.n2.dot(cd.plane);
  const bool undecided = std::abs(cba) <= eps || std::abs(dba) <= eps || std::abs(adc) <= eps || std::abs(bdc) <= eps;
  if (undecided) return Crossing::Maybe;
  return (cba * dba < T(0) && adc * bdc < T(0) && cba * bdc > T(0)) ? Crossing::Yes : Crossing::No;
}

template <class T> struct ArcScratch {
  std::vector<EdgeArc<T>> a, b;
};
template <class T> ArcScratch<T>& arcScratch() {
  thread_local ArcScratch<T> s;
  return s;
}

// Every pair of an arc of A (arcsA) and an arc of -B (arcsB): the facets of A - B they make.
template <class T>
void testArcPairs(const Polytope<T>& a, const Polytope<T>& b, const std::vector<EdgeArc<T>>& arcsA,
                  const std::vector<EdgeArc<T>>& arcsB, bool stopWhenSeparated, SatResult<T>& best) {
  const T eps = T(tol::Rel<T>::kEpsilon);
  for (const EdgeArc<T>& ea : arcsA) {
    const Vec3<T> coneMid = ea.n1 + ea.n2;
    const Vec3<T>& va = a.vertices[ea.vertex];
    for (const EdgeArc<T>& eb : arcsB) {
      if (ea.flat || eb.flat) {  // no usable arc: the pair's axis from the edge directions, both signs
        const Vec3<T> da = ea.flat ? ea.direction : Vec3<T>(ea.plane.normalized());
        const Vec3<T> db = eb.flat ? eb.direction : Vec3<T>(eb.plane.normalized());
        const Vec3<T> c = da.cross(db);
        const T len2 = c.squaredNorm();
        if (len2 > eps * eps) testAxisBothSigns(a, b, Vec3<T>(c / std::sqrt(len2)), best);
        if (stopWhenSeparated && best.depth < T(0)) return;
        continue;
      }
      const Crossing crossing = arcsCross(ea, eb, eps);
      if (crossing == Crossing::No) continue;
      // The facet normal is perpendicular to both edges, i.e. to both arc planes.
      const Vec3<T> c = ea.plane.cross(eb.plane);
      const T len2 = c.squaredNorm();
      if (len2 <= eps * eps) continue;  // parallel edges: no facet of their own
      Vec3<T> p = c / std::sqrt(len2);
      if (crossing == Crossing::Maybe) {
        testAxisBothSigns(a, b, p, best);
      } else {
        if (p.dot(coneMid) < T(0)) p = -p;  // the crossing lies inside A's arc
        consider(p.dot(va - b.vertices[eb.vertex]), Vec3<T>(-p), best);
      }
      if (stopWhenSeparated && best.depth < T(0)) return;
    }
  }
}

// Edge-edge facets of A - B for two polytopes with known edge faces.
template <class T>
void testEdgePairsGaussMap(const Polytope<T>& a, const Polytope<T>& b, bool stopWhenSeparated, SatResult<T>& best) {
  ArcScratch<T>& s = arcScratch<T>();
  edgeArcs(a, T(1), s.a);
  edgeArcs(b, T(-1), s.b);
  testArcPairs(a, b, s.a, s.b, stopWhenSeparated, best);
}

// Edge-edge axes when one side has no Gauss map (a segment core, or non-manifold input): every pair of
// non-parallel edges, projected in full. For a segment only hull edges whose arc meets the great circle
// perpendicular to the segment can form a facet ((n1.s)(n2.s) <= 0); the rest are skipped.
template <class T>
void testEdgePairsDirect(const Polytope<T>& a, const Polytope<T>& b, bool stopWhenSeparated, SatResult<T>& best) {
  const T eps = T(tol::Rel<T>::kEpsilon);
  const PolytopeTopology& ta = *a.topology;
  const PolytopeTopology& tb = *b.topology;
  for (const auto& ea : ta.edges) {
    const Vec3<T> da = (a.vertices[ea[1]] - a.vertices[ea[0]]).normalized();
    for (std::size_t j = 0; j < tb.edges.size(); ++j) {
      const auto& eb = tb.edges[j];
      if (tb.edgeFacesKnown && !ta.edgeFacesKnown) {
        const Vec3<T>& n1 = b.faceNormals[tb.edgeFaces[j][0]];
        const Vec3<T>& n2 = b.faceNormals[tb.edgeFaces[j][1]];
        const T s1 = n1.dot(da), s2 = n2.dot(da);
        if (!isFlatArc(Vec3<T>(n2.cross(n1))) && s1 * s2 > eps * eps) continue;  // a flat arc is noise: keep the edge
      }
      const Vec3<T> db = (b.vertices[eb[1]] - b.vertices[eb[0]]).normalized();
      const Vec3<T> c = da.cross(db);
      const T len2 = c.squaredNorm();
      if (len2 <= eps * eps) continue;
      testAxisBothSigns(a, b, Vec3<T>(c / std::sqrt(len2)), best);
      if (stopWhenSeparated && best.depth < T(0)) return;
    }
  }
}

// ---- closest points -----------------------------------------------------------------------------------------

template <class T> bool insidePolygon(const Polytope<T>& poly, std::size_t f, const Vec3<T>& q) {
  const Vec3<T>& n = poly.faceNormals[f];
  const PolytopeTopology& topo = *poly.topology;
  const std::uint32_t begin = topo.faceBegin[f], end = topo.faceBegin[f + 1];
  for (std::uint32_t i = begin; i < end; ++i) {
    const Vec3<T>& v0 = poly.vertices[topo.faceVertices[i]];
    const Vec3<T>& v1 = poly.vertices[topo.faceVertices[i + 1 < end ? i + 1 : begin]];
    if ((v1 - v0).cross(q - v0).dot(n) < T(0)) return false;
  }
  return true;
}

// ---- topology -----------------------------------------------------------------------------------------------

void addFaceLoop(PolytopeTopology& topo, std::initializer_list<std::uint32_t> loop) {
  topo.faceVertices.insert(topo.faceVertices.end(), loop.begin(), loop.end());
  topo.faceBegin.push_back(static_cast<std::uint32_t>(topo.faceVertices.size()));
}

// Box vertex i has coordinate k at +halfExtent when bit k of i is set; faces are ordered +X, -X, +Y, -Y, +Z, -Z.
PolytopeTopology makeBoxTopology() {
  PolytopeTopology topo;
  addFaceLoop(topo, {1, 3, 7, 5});
  addFaceLoop(topo, {0, 4, 6, 2});
  addFaceLoop(topo, {2, 6, 7, 3});
  addFaceLoop(topo, {0, 1, 5, 4});
  addFaceLoop(topo, {4, 5, 7, 6});
  addFaceLoop(topo, {0, 2, 3, 1});
  // The face of axis j on vertex i's side is 2j + (bit j clear).
  const auto faceOf = [](std::uint32_t i, std::uint32_t j) { return 2 * j + ((i & (1u << j)) ? 0u : 1u); };
  for (std::uint32_t i = 0; i < 8; ++i)
    for (std::uint32_t k = 0; k < 3; ++k)
      if (!(i & (1u << k))) {
        topo.edges.push_back({i, i | (1u << k)});
        topo.edgeFaces.push_back({faceOf(i, (k + 1) % 3), faceOf(i, (k + 2) % 3)});
      }
  topo.edgeFacesKnown = true;
  return topo;
}

const PolytopeTopology& boxTopology() {
  static const PolytopeTopology topo = makeBoxTopology();
  return topo;
}

const PolytopeTopology& pointTopology() {
  static const PolytopeTopology topo;
  return topo;
}

const PolytopeTopology& segmentTopology() {
  static const PolytopeTopology topo = [] {
    PolytopeTopology t;
    t.edges.push_back({0u, 1u});
    return t;
  }();
  return topo;
}

// Each polygon side (lower vertex, upper vertex, face); a manifold hull has exactly two per edge.
template <class T> PolytopeTopology makeHullTopology(const ConvexMesh<T>& mesh) {
  PolytopeTopology topo;
  std::vector<std::array<std::uint32_t, 3>> sides;
  for (std::uint32_t p = 0; p < mesh.polygons.size(); ++p) {
    const HullPolygon<T>& f = mesh.polygons[p];
    if (f.indexCount < 3) continue;
    const std::uint32_t face = std::uint32_t(topo.facePolygon.size());
    topo.facePolygon.push_back(p);
    for (std::uint32_t i = 0; i < f.indexCount; ++i) {
      const std::uint32_t v0 = mesh.polygonVertices[f.indexBase + i];
      const std::uint32_t v1 = mesh.polygonVertices[f.indexBase + (i + 1) % f.indexCount];
      topo.faceVertices.push_back(v0);
      sides.push_back({std::min(v0, v1), std::max(v0, v1), face});
    }
    topo.faceBegin.push_back(static_cast<std::uint32_t>(topo.faceVertices.size()));
  }
  std::sort(sides.begin(), sides.end());
  topo.edgeFacesKnown = true;
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j][0] == sides[i][0] && sides[j][1] == sides[i][1]) ++j;
    if (sides[i][0] != sides[i][1]) {
      topo.edges.push_back({sides[i][0], sides[i][1]});
      topo.edgeFaces.push_back({sides[i][2], sides[j - 1][2]});
      if (j - i != 2) topo.edgeFacesKnown = false;
    }
    i = j;
  }
  return topo;
}

template <class T> struct TopologyCache {
  struct Entry {
    std::weak_ptr<const ConvexMesh<T>> mesh;
    std::shared_ptr<const PolytopeTopology> topology;
  };
  std::shared_mutex mutex;
  std::unordered_map<const ConvexMesh<T>*, Entry> entries;
  std::size_t pruneAt = 64;  // drop entries of destroyed meshes when the map grows past this

  static TopologyCache& instance() {
    static TopologyCache cache;
    return cache;
  }
};

template <class T> void fillCoordinates(Polytope<T>& out) {
  const std::size_t n = out.vertices.size();
  out.xs.resize(n);
  out.ys.resize(n);
  out.zs.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.xs[i] = out.vertices[i].x();
    out.ys[i] = out.vertices[i].y();
    out.zs[i] = out.vertices[i].z();
  }
}

template <class T> void clearPolytope(Polytope<T>& out, const PolytopeTopology* topology) {
  out.vertices.clear();
  out.faceNormals.clear();
  out.faceOffsets.clear();
  out.ownedTopology.reset();
  out.topology = topology;
}

}  // namespace

template <class T> std::shared_ptr<const PolytopeTopology> hullTopology(const std::shared_ptr<const ConvexMesh<T>>& mesh) {
  TopologyCache<T>& cache = TopologyCache<T>::instance();
  {
    std::shared_lock<std::shared_mutex> lock(cache.mutex);
    const auto it = cache.entries.find(mesh.get());
    // A live weak reference means the address still belongs to the same mesh (it cannot have been reused).
    if (it != cache.entries.end() && !it->second.mesh.expired()) return it->second.topology;
  }
  auto topology = std::make_shared<const PolytopeTopology>(makeHullTopology(*mesh));
  std::unique_lock<std::shared_mutex> lock(cache.mutex);
  if (cache.entries.size() >= cache.pruneAt) {
    for (auto it = cache.entries.begin(); it != cache.entries.end();)
      it = it->second.mesh.expired() ? cache.entries.erase(it) : std::next(it);
    cache.pruneAt = std::max<std::size_t>(64, 2 * cache.entries.size());
  }
  cache.entries[mesh.get()] = {mesh, topology};
  return topology;
}

template <class T> Polytope<T>& scratchPolytope(int slot) {
  thread_local Polytope<T> scratch[2];
  return scratch[slot];
}

template <class T> void buildPointPolytope(const Vec3<T>& p, Polytope<T>& out) {
  clearPolytope(out, &pointTopology());
  out.vertices.push_back(p);
  fillCoordinates(out);
}

template <class T> void buildSegmentPolytope(const Segment<T>& s, Polytope<T>& out) {
  const bool degenerate = !((s.b - s.a).squaredNorm() > T(0));
  clearPolytope(out, degenerate ? &pointTopology() : &segmentTopology());
  out.vertices.push_back(s.a);
  if (!degenerate) out.vertices.push_back(s.b);
  fillCoordinates(out);
}

template <class T> void buildBoxPolytope(const BoxGeometry<T>& box, const Transform<T>& pose, Polytope<T>& out) {
  clearPolytope(out, &boxTopology());
  const Vec3<T>& h = box.halfExtents;
  for (std::uint32_t i = 0; i < 8; ++i) {
    const Vec3<T> local((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
    out.vertices.push_back(pose.transform(local));
  }
  const Mat3<T> r = pose.q.toRotationMatrix();
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3<T> n = r.col(axis);
    const T c = n.dot(pose.p);
    out.faceNormals.push_back(n);
    out.faceOffsets.push_back(-(c + h[axis]));
    out.faceNormals.push_back(-n);
    out.faceOffsets.push_back(c - h[axis]);
  }
  fillCoordinates(out);
}

// min|s| S^-1: the directions of S^-1 for a scale whose smallest factor's reciprocal overflows.
template <class T> Mat3<T> shrunkInverse(const MeshScale<T>& scale) {
  const Mat3<T> axes = scale.rotation.normalized().toRotationMatrix();
  const Vec3<T> shrink = Vec3<T>::Constant(scale.scale.cwiseAbs().minCoeff()).cwiseQuotient(scale.scale);
  return axes * shrink.asDiagonal() * axes.transpose();
}

// Scaled hull: x = pose(S v) with S symmetric; normals map by S^-T = S^-1 (then renormalised).
template <class T>
void buildConvexPolytope(const ConvexMeshGeometry<T>& convex, const Transform<T>& pose, Polytope<T>& out) {
  std::shared_ptr<const PolytopeTopology> topology = hullTopology(convex.mesh);
  clearPolytope(out, topology.get());
  out.ownedTopology = std::move(topology);
  const ConvexMesh<T>& mesh = *convex.mesh;
  // Normals map by S^-1 = R diag(1/s) R^T, taken from the factors (a general 3x3 inverse of a scale like
  // (1e-18, 7e8, 3.5) is rounding noise in float); where 1/s overflows (a subnormal factor) by the same matrix times
  // the smallest |s| (min|s| / s stays in [-1, 1]), the same directions. Normalized without squaring.
  const HullScale<T> scale(convex.scale);
  const Mat3<T> r = pose.q.toRotationMatrix();
  const Mat3<T> vertexMap = r * scale.toShape;
  const Mat3<T> normalMap = r * (scale.toMesh.allFinite() ? scale.toMesh : shrunkInverse(convex.scale));
  for (const Vec3<T>& v : mesh.vertices) out.vertices.push_back(vertexMap * v + pose.p);
  const PolytopeTopology& topo = *out.topology;
  for (std::size_t f = 0; f < topo.facePolygon.size(); ++f) {
    const Vec3<T> n = (normalMap * mesh.polygons[topo.facePolygon[f]].normal).stableNormalized();
    out.faceNormals.push_back(n);
    out.faceOffsets.push_back(-n.dot(out.vertices[topo.faceVertices[topo.faceBegin[f]]]));
  }
  fillCoordinates(out);
}

template <class T> T minProjection(const Polytope<T>& p, const Vec3<T>& n) { return minDot(p, n); }

template <class T>
void satEdgePairs(const Polytope<T>& a, const Polytope<T>& b, const std::vector<std::uint32_t>& edgesA,
                  const std::vector<std::uint32_t>& edgesB, SatResult<T>& best) {
  ArcScratch<T>& s = arcScratch<T>();
  edgeArcs(a, T(1), edgesA, s.a);
  edgeArcs(b, T(-1), edgesB, s.b);
  testArcPairs(a, b, s.a, s.b, false, best);
}

template <class T> SatResult<T> satMinimumOverlap(const Polytope<T>& a, const Polytope<T>& b, bool stopWhenSeparated) {
  SatResult<T> best{std::numeric_limits<T>::max(), Vec3<T>::UnitX()};
  // Face axes first: they are the most likely to separate, and cost one projection each.
  for (std::size_t f = 0; f < a.faceCount(); ++f) {
    const Vec3<T>& n = a.faceNormals[f];
    consider(-a.faceOffsets[f] - minDot(b, n), Vec3<T>(-n), best);
    if (stopWhenSeparated && best.depth < T(0)) return best;
  }
  for (std::size_t g = 0; g < b.faceCount(); ++g) {
    const Vec3<T>& m = b.faceNormals[g];
    consider(-b.faceOffsets[g] - minDot(a, m), m, best);
    if (stopWhenSeparated && best.depth < T(0)) return best;
  }
  if (a.edgeCount() == 0 || b.edgeCount() == 0) return best;
  if (a.edgeFacesKnown() && b.edgeFacesKnown())
    testEdgePairsGaussMap(a, b, stopWhenSeparated, best);
  else
    testEdgePairsDirect(a, b, stopWhenSeparated, best);
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
  for (const auto& e : poly.topology->edges) {
    const Vec3<T> q = closestPointOnSegment(poly.vertices[e[0]], poly.vertices[e[1]], p);
    const T d = (p - q).norm();
    if (d < best.distance) best = {d, p, q};
  }
  if (poly.topology->edges.empty())
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
  for (const auto& e : poly.topology->edges) {
    const SegmentClosest<T> cp = closestSegmentSegment(s.a, s.b, poly.vertices[e[0]], poly.vertices[e[1]]);
    const T d = (cp.c0 - cp.c1).norm();
    if (d < best.distance) best = {d, cp.c0, cp.c1};
  }
  return best;
}

template <class T> RoundedCore<T> sphereCore(const SphereGeometry<T>& g, const Transform<T>& pose) {
  return {Segment<T>{pose.p, pose.p}, g.radius};
}

template <class T> RoundedCore<T> capsuleCore(const CapsuleGeometry<T>& g, const Transform<T>& pose) {
  const Vec3<T> axis = pose.rotate(Vec3<T>(g.halfHeight, T(0), T(0)));
  return {Segment<T>{pose.p - axis, pose.p + axis}, g.radius};
}

namespace {
// The core as a polytope, in scratch slot 1 (slot 0 holds the other shape).
template <class T> const Polytope<T>& corePolytope(const RoundedCore<T>& r) {
  Polytope<T>& core = scratchPolytope<T>(1);
  buildSegmentPolytope(r.segment, core);
  return core;
}
}  // namespace

template <class T> bool overlapRoundedPolytope(const RoundedCore<T>& r, const Polytope<T>& poly) {
  const SatResult<T> sat = satMinimumOverlap(corePolytope(r), poly, true);
  if (sat.depth >= T(0)) return true;
  if (-sat.depth > r.radius) return false;  // a separating gap bounds the distance from below
  return closestSegmentToPolytope(r.segment, poly).distance <= r.radius;
}

template <class T>
bool penetrationRoundedPolytope(const RoundedCore<T>& r, const Polytope<T>& poly, Vec3<T>& direction, T& depth) {
  const SatResult<T> sat = satMinimumOverlap(corePolytope(r), poly, false);
  if (sat.depth >= T(0)) {  // the core itself penetrates: PD(core) plus the radius
    direction = sat.direction;
    depth = sat.depth + r.radius;
    return true;
  }
  if (-sat.depth > r.radius) return false;
  const ClosestResult<T> c = closestSegmentToPolytope(r.segment, poly);
  if (c.distance > r.radius) return false;
  // When the closest points lie on one facet of the Minkowski difference the SAT axis realises the distance and is
  // exact, whereas the difference of two nearly coincident closest points is not: its angle error is about
  // eps * size / distance, and along a face contact the push-out error is first order in it (float lost ~3e-3 at
  // distance 3e-5). Elsewhere (edge/vertex regions) the push-out is insensitive to that error.
  const T scale = r.radius + (r.segment.b - r.segment.a).norm() + c.onPoly.cwiseAbs().maxCoeff();
  const bool onSatFacet = std::abs(-sat.depth - c.distance) <= T(tol::Rel<T>::kEpsilon) * scale;
  direction = (onSatFacet || !(c.distance > T(0))) ? sat.direction : Vec3<T>((c.onCore - c.onPoly) / c.distance);
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

namespace {

// Whether the origin lies inside the tetrahedron `s` deeper than `depth` below each of its faces. The tetrahedron
// lies in the cores' Minkowski difference, so its clearance bounds their penetration depth from below; a clearance
// is never negative, so any depth < 0 is exceeded. Not a tetrahedron, or the origin not strictly inside: false.
// Division-free: |n.p0| > depth |n| for each face normal n.
template <class T> bool originDeeperThan(const GjkSimplex<T>& s, T depth) {
  if (depth < T(0)) return true;
  if (s.size != 4) return false;
  for (int skip = 0; skip < 4; ++skip) {
    const Vec3<T>& p0 = s.points[(skip + 1) % 4].w;
    const Vec3<T>& p1 = s.points[(skip + 2) % 4].w;
    const Vec3<T>& p2 = s.points[(skip + 3) % 4].w;
    const Vec3<T>& opposite = s.points[skip].w;
    const Vec3<T> n = (p1 - p0).cross(p2 - p0);
    const T originSide = -n.dot(p0), oppositeSide = n.dot(opposite - p0);
    // The origin must be on the same side as the opposite vertex, farther than depth from this face's plane.
    if (!(originSide * oppositeSide > T(0)) || !(std::abs(originSide) > depth * n.norm())) return false;
  }
  return true;
}

template <class T> bool isRounded(GeometryType t) { return t == GeometryType::Sphere || t == GeometryType::Capsule; }

template <class T> RoundedCore<T> roundedCore(const Geometry<T>& g, const Transform<T>& pose) {
  if (g.type() == GeometryType::Sphere) return sphereCore(g.template get<SphereGeometry<T>>(), pose);
  return capsuleCore(g.template get<CapsuleGeometry<T>>(), pose);
}

template <class T> void buildPolytope(const Geometry<T>& g, const Transform<T>& pose, Polytope<T>& out) {
  if (g.type() == GeometryType::Box)
    buildBoxPolytope(g.template get<BoxGeometry<T>>(), pose, out);
  else
    buildConvexPolytope(g.template get<ConvexMeshGeometry<T>>(), pose, out);
}

// The exact kernels, for answers within the band of touching.
template <class T>
bool overlapConvexShapesExact(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1) {
  Polytope<T>& poly = scratchPolytope<T>(0);
  if (isRounded<T>(g0.type())) {
    buildPolytope(g1, p1, poly);
    return overlapRoundedPolytope(roundedCore(g0, p0), poly);
  }
  if (isRounded<T>(g1.type())) {
    buildPolytope(g0, p0, poly);
    return overlapRoundedPolytope(roundedCore(g1, p1), poly);
  }
  Polytope<T>& other = scratchPolytope<T>(1);
  buildPolytope(g0, p0, poly);
  buildPolytope(g1, p1, other);
  return overlapPolytopes(poly, other);
}

}  // namespace

}  // namespace gq::detail

// The public GJK overlap kernels (gq/kernels/overlap.h).
namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T> OverlapCertificate overlapByGjk(ConvexShape<T> a, const ConvexShape<T>& b) {
  const T band = kGjkOverlapBand<T> * std::max(a.size, b.size);
  // Separated by more than the band: GJK's separating axis is conclusive (a's own copy grown by the band).
  const T margin = a.margin;
  a.margin += band;
  GjkOverlapWitness<T> witness;
  const bool grownOverlap = gjkOverlap(a, b, &witness);
  a.margin = margin;
  if (!grownOverlap) return OverlapCertificate::Apart;
  // Overlapping by more than the band: the cores' distance (rounded shells) or the origin's clearance inside
  // GJK's final tetrahedron (cores overlapping) proves it. The boolean run's own evidence usually suffices
  // (|v| bounds the cores' distance from above); otherwise a full distance query decides.
  const T margins = a.margin + b.margin;
  if (!witness.coresOverlap && witness.coreDistanceUpper - margins < -band) return OverlapCertificate::Overlapping;
  if (witness.coresOverlap && originDeeperThan(witness.simplex, band - margins)) return OverlapCertificate::Overlapping;
  const GjkResult<T> g = gjkDistance(a, b);
  if (g.status.ok()) {
    if (!g.coresOverlap && g.distance + g.errorBound < -band) return OverlapCertificate::Overlapping;
    if (g.coresOverlap && originDeeperThan(g.simplex, band - margins)) return OverlapCertificate::Overlapping;
  }
  return OverlapCertificate::Unknown;
}

template <class T>
bool overlapConvexShapes(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1) {
  const OverlapCertificate gjk = overlapByGjk(makeConvexShape(g0, p0), makeConvexShape(g1, p1));
  if (gjk != OverlapCertificate::Unknown) return gjk == OverlapCertificate::Overlapping;
  return overlapConvexShapesExact(g0, p0, g1, p1);
}

template OverlapCertificate overlapByGjk<float>(ConvexShape<float>, const ConvexShape<float>&);
template bool overlapConvexShapes<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&, const Transform<float>&);
template OverlapCertificate overlapByGjk<double>(ConvexShape<double>, const ConvexShape<double>&);
template bool overlapConvexShapes<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&, const Transform<double>&);

}  // namespace gq::kernels

namespace gq::detail {

template std::shared_ptr<const PolytopeTopology> hullTopology<float>(const std::shared_ptr<const ConvexMesh<float>>&);
template Polytope<float>& scratchPolytope<float>(int);
template void buildPointPolytope<float>(const Vec3<float>&, Polytope<float>&);
template void buildSegmentPolytope<float>(const Segment<float>&, Polytope<float>&);
template void buildBoxPolytope<float>(const BoxGeometry<float>&, const Transform<float>&, Polytope<float>&);
template void buildConvexPolytope<float>(const ConvexMeshGeometry<float>&, const Transform<float>&, Polytope<float>&);
template SatResult<float> satMinimumOverlap<float>(const Polytope<float>&, const Polytope<float>&, bool);
template float minProjection<float>(const Polytope<float>&, const Vec3<float>&);
template void satEdgePairs<float>(const Polytope<float>&, const Polytope<float>&, const std::vector<std::uint32_t>&,
                                 const std::vector<std::uint32_t>&, SatResult<float>&);
template ClosestResult<float> closestPointToPolytope<float>(const Vec3<float>&, const Polytope<float>&);
template ClosestResult<float> closestSegmentToPolytope<float>(const Segment<float>&, const Polytope<float>&);
template RoundedCore<float> sphereCore<float>(const SphereGeometry<float>&, const Transform<float>&);
template RoundedCore<float> capsuleCore<float>(const CapsuleGeometry<float>&, const Transform<float>&);
template bool overlapRoundedPolytope<float>(const RoundedCore<float>&, const Polytope<float>&);
template bool penetrationRoundedPolytope<float>(const RoundedCore<float>&, const Polytope<float>&, Vec3<float>&, float&);
template bool overlapPolytopes<float>(const Polytope<float>&, const Polytope<float>&);
template bool penetrationPolytopes<float>(const Polytope<float>&, const Polytope<float>&, Vec3<float>&, float&);
template std::shared_ptr<const PolytopeTopology> hullTopology<double>(const std::shared_ptr<const ConvexMesh<double>>&);
template Polytope<double>& scratchPolytope<double>(int);
template void buildPointPolytope<double>(const Vec3<double>&, Polytope<double>&);
template void buildSegmentPolytope<double>(const Segment<double>&, Polytope<double>&);
template void buildBoxPolytope<double>(const BoxGeometry<double>&, const Transform<double>&, Polytope<double>&);
template void buildConvexPolytope<double>(const ConvexMeshGeometry<double>&, const Transform<double>&, Polytope<double>&);
template SatResult<double> satMinimumOverlap<double>(const Polytope<double>&, const Polytope<double>&, bool);
template double minProjection<double>(const Polytope<double>&, const Vec3<double>&);
template void satEdgePairs<double>(const Polytope<double>&, const Polytope<double>&, const std::vector<std::uint32_t>&,
                                 const std::vector<std::uint32_t>&, SatResult<double>&);
template ClosestResult<double> closestPointToPolytope<double>(const Vec3<double>&, const Polytope<double>&);
template ClosestResult<double> closestSegmentToPolytope<double>(const Segment<double>&, const Polytope<double>&);
template RoundedCore<double> sphereCore<double>(const SphereGeometry<double>&, const Transform<double>&);
template RoundedCore<double> capsuleCore<double>(const CapsuleGeometry<double>&, const Transform<double>&);
template bool overlapRoundedPolytope<double>(const RoundedCore<double>&, const Polytope<double>&);
template bool penetrationRoundedPolytope<double>(const RoundedCore<double>&, const Polytope<double>&, Vec3<double>&, double&);
template bool overlapPolytopes<double>(const Polytope<double>&, const Polytope<double>&);
template bool penetrationPolytopes<double>(const Polytope<double>&, const Polytope<double>&, Vec3<double>&, double&);

}  // namespace gq::detail
