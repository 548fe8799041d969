#pragma once
// Convex polytopes in one frame, and the exact queries every polytope pair uses:
//  - SAT over all face normals of both shapes and the edge-edge cross products that are facet normals of the
//    Minkowski difference (Gauss-map arcs that cross). For two convex polytopes A, B the facets of A - B have
//    exactly these normals, so the minimum push-out over them is the exact penetration depth (MTD), and a negative
//    push-out on any of them proves separation.
//  - Exact distance from a point or a segment to a polytope (for rounded shapes: sphere = point + radius,
//    capsule = segment + radius).
// A point or a segment is a degenerate polytope (no faces; a segment has one edge), so the same SAT serves
// sphere/capsule cores against boxes and hulls.
//
// Cost model: the topology (edges, the faces beside each edge, face loops) of a box is static and that of a cooked
// hull is computed once per ConvexMesh and cached; per call only the world-space vertices and face planes are
// written, into per-thread scratch polytopes whose capacity is reused (no heap allocation after warm-up).
#include <array>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <vector>

#include "gjk/gjk.h"
#include "gq/cooking.h"
#include "gq/geometry.h"
#include "gq/transform.h"
#include "overlap/overlap.h"
#include "shapes/segment.h"

namespace gq::detail {

// Pose-independent connectivity of a polytope.
struct PolytopeTopology {
  std::vector<std::uint32_t> faceBegin{0};  // size faces + 1, into faceVertices
  std::vector<std::uint32_t> faceVertices;  // vertex loops, counter-clockwise from outside
  std::vector<std::uint32_t> facePolygon;   // face -> index of the cooked polygon it came from
  std::vector<std::array<std::uint32_t, 2>> edges;      // each edge once
  std::vector<std::array<std::uint32_t, 2>> edgeFaces;  // the two faces beside each edge (when edgeFacesKnown)
  // True for boxes and manifold hulls. Without it (points, segments, non-manifold input) every edge pair is a
  // candidate SAT axis.
  bool edgeFacesKnown = false;
};

// Topology of a cooked hull: computed on first use, then shared through a cache keyed by the mesh (entries of
// destroyed meshes are detected through a weak reference and dropped). Thread-safe.
template <class T> std::shared_ptr<const PolytopeTopology> hullTopology(const std::shared_ptr<const ConvexMesh<T>>& mesh);

template <class T> struct Polytope {
  std::vector<Vec3<T>> vertices;
  std::vector<T> xs, ys, zs;  // the vertices again, one array per coordinate (vectorisable projection loops)
  // Faces: outward unit normal and offset (inside: n.x + d <= 0).
  std::vector<Vec3<T>> faceNormals;
  std::vector<T> faceOffsets;
  const PolytopeTopology* topology = nullptr;
  std::shared_ptr<const PolytopeTopology> ownedTopology;  // keeps a hull's cached topology alive

  std::size_t faceCount() const { return faceNormals.size(); }
  std::size_t edgeCount() const { return topology->edges.size(); }
  bool edgeFacesKnown() const { return topology->edgeFacesKnown; }
};

// Fill `out` (capacity reused) with a point, segment, posed box or posed scaled hull.
template <class T> void buildPointPolytope(const Vec3<T>& p, Polytope<T>& out);
template <class T> void buildSegmentPolytope(const Segment<T>& s, Polytope<T>& out);
template <class T> void buildBoxPolytope(const BoxGeometry<T>& box, const Transform<T>& pose, Polytope<T>& out);
template <class T> void buildConvexPolytope(const ConvexMeshGeometry<T>& convex, const Transform<T>& pose, Polytope<T>& out);

// Per-thread scratch polytopes for the kernels (slot 0 and 1 may be used at the same time).
template <class T> Polytope<T>& scratchPolytope(int slot);

template <class T> struct SatResult {
  T depth;            // min push-out over the axes; < 0 means separated (then a lower bound of -distance)
  Vec3<T> direction;  // unit: translating shape a by direction * depth separates (when depth >= 0)
};

// Minimum push-out of a over the Minkowski-difference facet normals of a and b. With stopWhenSeparated the
// search ends at the first separating axis (enough for a boolean overlap).
template <class T> SatResult<T> satMinimumOverlap(const Polytope<T>& a, const Polytope<T>& b, bool stopWhenSeparated);
// Pieces of it for searches that prove most axes irrelevant first (penetration/polytope_mtd.h): the smallest
// projection of p's vertices on n (a face g of b pushes a out by -b.faceOffsets[g] - minProjection(a, m_g)), and the
// edge-edge facets of the listed edges of a with the listed edges of b, kept in `best` when smaller.
template <class T> T minProjection(const Polytope<T>& p, const Vec3<T>& n);
template <class T>
void satEdgePairs(const Polytope<T>& a, const Polytope<T>& b, const std::vector<std::uint32_t>& edgesA,
                  const std::vector<std::uint32_t>& edgesB, SatResult<T>& best);

template <class T> struct ClosestResult {
  T distance;
  Vec3<T> onCore;  // closest point on the point/segment
  Vec3<T> onPoly;  // closest point on the polytope
};

// Distance from a point / segment that lies OUTSIDE the polytope to the polytope's boundary.
template <class T> ClosestResult<T> closestPointToPolytope(const Vec3<T>& p, const Polytope<T>& poly);
template <class T> ClosestResult<T> closestSegmentToPolytope(const Segment<T>& s, const Polytope<T>& poly);

// A sphere (point core) or capsule (segment core) of `radius`.
template <class T> struct RoundedCore {
  Segment<T> segment;  // the core as a segment (a == b for a point)
  T radius;
};
template <class T> RoundedCore<T> sphereCore(const SphereGeometry<T>& g, const Transform<T>& pose);
template <class T> RoundedCore<T> capsuleCore(const CapsuleGeometry<T>& g, const Transform<T>& pose);

// Exact overlap of the rounded core (geom0) and the polytope.
template <class T> bool overlapRoundedPolytope(const RoundedCore<T>& r, const Polytope<T>& poly);
// Exact MTD of the rounded core (geom0) against the polytope: r + PD(core) when the core intersects the polytope,
// r - distance otherwise. Returns false when separated.
template <class T> bool penetrationRoundedPolytope(const RoundedCore<T>& r, const Polytope<T>& poly, Vec3<T>& direction,
                                                   T& depth);

// Exact overlap / MTD of two polytopes (a = geom0).
template <class T> bool overlapPolytopes(const Polytope<T>& a, const Polytope<T>& b);
template <class T> bool penetrationPolytopes(const Polytope<T>& a, const Polytope<T>& b, Vec3<T>& direction, T& depth);

// kGjkOverlapBand, overlapConvexShapes and overlapByGjk: gq/kernels/overlap.h.

}  // namespace gq::detail
