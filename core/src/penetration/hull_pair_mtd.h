#pragma once
// The exact MTD of two convex polytopes (hull-hull, box-hull) without posing either: the minimum push-out over the
// facets of their Minkowski difference, as the full SAT computes it over every face and crossing edge pair
// (satMinimumOverlap), found by branch and bound over each side's Gauss-map tree (penetration/gauss_tree.h) in
// geom0's frame.
//
// Every facet normal n of A - B is a face normal of A, a face normal of -B, or the crossing of an edge arc of A with
// an edge arc of -B, and its push-out is h_A(n) + h_B(-n). A tree node of either side bounds that from below for
// every facet normal from its faces and arcs, from one point of the other side (gauss_tree.h): the vertex the
// other side's support start table gives for minus the node's axis, without the climb (any point of it bounds from
// below). A leaf whose cap is too wide for its ball is bounded over its own faces and edge arcs from such a point.
// The search's first best push-out is the one along the line between the shapes' inner centres (any direction's
// push-out is at least the minimum). It starts from a cut of each tree's top levels (GaussTree::startCut, at most
// kGaussStartNodes nodes, or pairStartCut between two hulls: caps that wide prune nothing) and refines nodes in order of their bounds: a leaf's faces
// are evaluated exactly (h of the own face from its plane, of the other side by a hill-climbing support call), and
// its edges get their own bound
// (the linear n.(v - w) over the arc, for the other side's points w at the leaf's cap and at the edge's faces); a
// leaf whose faces and ring faces are all bounded out from its point keeps no edges. The search ends when the
// smallest bound left is not below the best push-out found; then only the edges of evaluated leaves whose
// bound is below it (first from the leaf's point alone, by its faces' bounds, which the edge's vertex shares) are
// paired, each pair of crossing arcs giving its push-out in O(1) (or, when the crossing is undecided within the
// arcs' rounding, the push-outs along both signs of its axis from support calls), pairs whose arcs' caps are apart
// skipped. What is skipped is proven not smaller, less a margin for the rounding of bounds and planes.
//
// Other vertices and normals are transformed only when touched. A hull scaled non-uniformly, a non-manifold hull or
// one not cooked here is not taken (the posed search of polytope_mtd.h answers it).
#include "gq/geometry.h"
#include "gq/transform.h"

namespace gq::detail {

// Return false when not taken; otherwise true, with `penetrating` and, when penetrating, the direction (moving geom0
// by direction * depth separates the shapes) and depth.
template <class T>
bool penetrationHullPairInFrame(const ConvexMeshGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1,
                                const Transform<T>& p1, bool& penetrating, Vec3<T>& direction, T& depth);
template <class T>
bool penetrationBoxHullInFrame(const BoxGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1,
                               const Transform<T>& p1, bool& penetrating, Vec3<T>& direction, T& depth);

}  // namespace gq::detail
