#pragma once
// Convex polytopes in one frame, and the exact queries every polytope pair uses:
//  - SAT over all face normals of both shapes and all edge-edge cross products. For two convex polytopes A, B the
//    facets of the Minkowski difference A - B have exactly these normals, so the minimum overlap over the axes is
//    the exact penetration depth (MTD), and a negative overlap on any axis proves separation.
//  - Exact distance from a point or a segment to a polytope (for rounded shapes: sphere = point + radius,
//    capsule = segment + radius).
// A point or a segment is a degenerate polytope (no faces; a segment has one edge), so the same SAT serves
// sphere/capsule cores against boxes and hulls.
#include <array>
#include <cstdint>
#include <vector>

#include "gq/cooking.h"
#include "gq/geometry.h"
#include "gq/transform.h"
#include "overlap/closest_points.h"

namespace gq::detail {

template <class T> struct Polytope {
  std::vector<Vec3<T>> vertices;
  // Faces: outward unit normal, offset (inside: n.x + d <= 0) and vertex loop (counter-clockwise from outside).
  std::vector<Vec3<T>> faceNormals;
  std::vector<T> faceOffsets;
  std::vector<std::uint32_t> faceBegin;  // size faces + 1, into faceVertices
  std::vector<std::uint32_t> faceVertices;
  std::vector<std::array<std::uint32_t, 2>> edges;  // each hull edge once
  // The two faces beside each edge (boxes, hulls). Without them (points, segments, non-manifold input) every
  // edge pair is tried as a SAT axis.
  std::vector<std::array<std::uint32_t, 2>> edgeFaces;
  bool edgeFacesKnown = false;
  // Candidate SAT axes contributed by this shape: face normals (one per parallel pair suffices) and edge directions.
  std::vector<Vec3<T>> satNormals;
  std::vector<Vec3<T>> edgeDirections;

  std::size_t faceCount() const { return faceNormals.size(); }
};

template <class T> Polytope<T> makePointPolytope(const Vec3<T>& p);
template <class T> Polytope<T> makeSegmentPolytope(const Segment<T>& s);
template <class T> Polytope<T> makeBoxPolytope(const BoxGeometry<T>& box, const Transform<T>& pose);
template <class T> Polytope<T> makeConvexPolytope(const ConvexMeshGeometry<T>& convex, const Transform<T>& pose);

// Edge-pair axes are tried directly (all pairs of distinct edge directions) when there are at most this many
// pairs; above it only pairs whose Gauss-map arcs may cross (those that can form a face of the Minkowski
// difference) are projected.
inline constexpr std::size_t kDirectEdgePairLimit = 64;

template <class T> struct SatResult {
  T depth;            // min overlap over the axes; < 0 means separated (then a lower bound of -distance)
  Vec3<T> direction;  // unit: translating shape a by direction * depth separates (when depth >= 0)
};

// Minimum overlap of a and b over all candidate axes. With stopWhenSeparated the search ends at the first
// separating axis (enough for a boolean overlap).
template <class T> SatResult<T> satMinimumOverlap(const Polytope<T>& a, const Polytope<T>& b, bool stopWhenSeparated);

template <class T> struct ClosestResult {
  T distance;
  Vec3<T> onCore;  // closest point on the point/segment
  Vec3<T> onPoly;  // closest point on the polytope
};

// Distance from a point / segment that lies OUTSIDE the polytope to the polytope's boundary.
template <class T> ClosestResult<T> closestPointToPolytope(const Vec3<T>& p, const Polytope<T>& poly);
template <class T> ClosestResult<T> closestSegmentToPolytope(const Segment<T>& s, const Polytope<T>& poly);

// A sphere (point core) or capsule (segment core) of `radius` against a polytope, core = geom0.
template <class T> struct RoundedCore {
  Polytope<T> core;  // point or segment
  Segment<T> segment;  // the core as a segment (a == b for a point)
  T radius;
};
template <class T> RoundedCore<T> sphereCore(const SphereGeometry<T>& g, const Transform<T>& pose);
template <class T> RoundedCore<T> capsuleCore(const CapsuleGeometry<T>& g, const Transform<T>& pose);

template <class T> bool overlapRoundedPolytope(const RoundedCore<T>& r, const Polytope<T>& poly);
// Exact MTD of the rounded core (geom0) against the polytope: r + PD(core) when the core intersects the polytope,
// r - distance otherwise. Returns false when separated.
template <class T> bool penetrationRoundedPolytope(const RoundedCore<T>& r, const Polytope<T>& poly, Vec3<T>& direction,
                                                   T& depth);

// Overlap / MTD of two polytopes (a = geom0).
template <class T> bool overlapPolytopes(const Polytope<T>& a, const Polytope<T>& b);
template <class T> bool penetrationPolytopes(const Polytope<T>& a, const Polytope<T>& b, Vec3<T>& direction, T& depth);

}  // namespace gq::detail
