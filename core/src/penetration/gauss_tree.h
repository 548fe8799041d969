#pragma once
// A hierarchy over a convex polytope's Gauss map, for lower bounds of its push-out over whole groups of faces and
// edges at once (penetration/hull_pair_mtd.h).
//
// Faces are split recursively by normal direction (at the median along the normals' widest spread) into leaves of at
// most kGaussLeafFaces (small hulls: kGaussSmallLeafFaces) faces; every edge belongs to the leaf of its first face. A
// node covers the faces and edges of its subtree, and keeps
//  - a cap (unit `axis`, half-angle below 90 degrees) holding every normal of its faces and every Gauss-map arc of
//    its edges (a cap under a hemisphere holds the arc between two of its points);
//  - a ball (`centre`, `radius` >= 0) under the support function there: for every normal n of its faces and arcs,
//    h(n) >= n.centre + radius (the faces' planes pass at least `radius` from the centre; along an arc from n1 to n2
//    through edge vertex v, n.(v - centre) is a positive combination of n1.(v - centre) and n2.(v - centre) with
//    weights summing to at least 1). The centre is the one of a few candidates (the hull's interior point and
//    least-squares spheres touching the node's planes, which follow the surface's curvature) with the tightest bound.
// Then for a point w of another shape B and every facet normal n of (this - B) from the node,
// h(n) + h_B(-n) >= radius - max over the cap of n.(w - centre): one support call and a closed form per node.
//
// Cooked once per hull, lazily, and shared (like the hull's topology): immutable after construction.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "gq/cooking.h"
#include "gq/geometry.h"

namespace gq::detail {

// Leaves hold at most kGaussLeafFaces faces, or kGaussSmallLeafFaces on a hull of fewer than kGaussSmallHullFaces
// faces (whose 16-face leaves would span caps too wide to bound, so that every face of them took a support call).
inline constexpr std::uint32_t kGaussLeafFaces = 16;
inline constexpr std::uint32_t kGaussSmallLeafFaces = 8;
inline constexpr std::uint32_t kGaussSmallHullFaces = 128;
// A search over the tree starts from a cut of its top levels of at most this many nodes (caps wider than that prune
// nothing; on 300-point hulls a cut of 16 nodes was measured to cost more instructions), or of at most
// kGaussPairStartNodes against another hull (64 nodes: 3% fewer instructions on 300-point hull pairs, where a box
// against a hull takes 9% more).
inline constexpr std::size_t kGaussStartNodes = 32;
inline constexpr std::size_t kGaussPairStartNodes = 64;

template <class T> struct GaussTree {
  struct Node {
    Vec3<T> axis = Vec3<T>::UnitX();  // cap centre (unit)
    T cosAngle = T(-1), sinAngle = T(0);  // cap half-angle, slightly widened for rounding
    Vec3<T> centre = Vec3<T>::Zero();  // ball centre, in the hull's frame
    T radius = T(0);                   // ball radius (>= 0)
    T radiusMax = T(0);                // the faces' planes pass at most this far from the centre
    std::uint32_t faceBegin = 0, faceEnd = 0;  // faces of the subtree (tree order)
    std::uint32_t edgeBegin = 0, edgeEnd = 0;  // edges of the subtree (tree order)
    std::uint32_t child[2] = {0, 0};           // both 0 for a leaf (the root is never a child)
    std::uint32_t ringBegin = 0, ringEnd = 0;  // a leaf's ring: ringFaces[ringBegin, ringEnd)
    bool bounded = false;                      // false: the cap reaches a hemisphere (no useful bound)
    bool leaf() const { return child[0] == 0; }
  };
  struct Edge {
    std::uint32_t vertex0, vertex1;  // the edge's vertices (vertex0 is the one its push-outs use)
    std::uint32_t face1, face2;      // the faces beside it, tree order (face1 in the edge's leaf)
    T halfCos;                       // cos of half the angle between the faces' normals
    bool face2InLeaf;                // face2 belongs to the edge's leaf too
  };
  std::vector<Node> nodes;          // nodes[0] is the root
  std::vector<Vec3<T>> faceNormal;  // tree order
  std::vector<T> faceOffset;        // plane through the face's first vertex: n.x + offset = 0
  std::vector<std::uint32_t> facePolygon;  // the cooked polygon of each face (tree order)
  std::vector<Edge> edges;          // tree order
  // Per leaf, the faces outside it beside its edges (each once): with the leaf's own faces, the ends of its arcs.
  std::vector<std::uint32_t> ringFaces;
  std::vector<std::uint32_t> startCut;  // the search's first nodes: the top levels cut at kGaussStartNodes nodes
  std::vector<std::uint32_t> pairStartCut;  // the same cut at kGaussPairStartNodes nodes (against another hull)
  // Set when the hull is a closed manifold of polygons: otherwise the tree is empty and must not be used.
  bool usable = false;
};

// The tree of a cooked hull in its own (unscaled) frame: built on first use, then shared through a cache keyed by
// the mesh (a thread's last few lookups are answered without a lock). Thread-safe.
template <class T> const GaussTree<T>* hullGaussTree(const std::shared_ptr<const ConvexMesh<T>>& mesh);

// The tree of a box of the given half extents: one leaf (its six faces and twelve edges), unbounded. Built into
// `out`, capacity reused.
template <class T> void boxGaussTree(const Vec3<T>& halfExtents, GaussTree<T>& out);

}  // namespace gq::detail
