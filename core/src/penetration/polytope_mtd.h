#pragma once
// The exact MTD of two polytopes (the minimum push-out over the facets of their Minkowski difference, as
// satMinimumOverlap computes it over every face and crossing edge pair) at a cost linear in their size.
//
// Certificate: with c_B a point inside B and r_B the radius of a ball about it inside B, every facet normal u of
// A - B along which A is pushed out has h_B(-u) >= -u.c_B + r_B, so
//  - a face f of A (normal n, offset o) pushes out by at least  -o - n.c_B + r_B,
//  - an edge pair whose Gauss-map arcs cross at u, u on the arc of A's edge (faces f1, f2, a vertex v of the edge),
//    pushes out by at least  min over u in the arc of u.(v - c_B) + r_B: with e = min(n1.(v - c_B), n2.(v - c_B)),
//    that minimum is >= e when e > 0 and >= e / cos(theta / 2) otherwise (theta: the arc's angle);
// and symmetrically for B with a ball inside A. Once some axis's exact push-out `best` is known, every face whose
// bound is at least `best` and every edge pair one of whose edges has a bound at least `best` cannot give less: only
// the remaining faces and pairs are evaluated, exactly as the full SAT evaluates them (the same projections and arc
// tests). The answer therefore is the full SAT's minimum; what is skipped is proven not smaller (the bounds less a
// margin for their rounding).
// Arcs between (nearly) opposite faces (a hull scaled flat) span no usable angle: their edges are always evaluated.
// Where the argument does not apply, the full SAT answers: a side without faces or whose edge faces are unknown
// (non-manifold input).
#include <cstdint>

#include "overlap/polytope.h"

namespace gq::detail {

// A ball inside a shape (radius 0: a point of it), for the bounds above.
template <class T> struct InnerBall {
  Vec3<T> centre;
  T radius;
};
// A posed box's: its centre and smallest half extent. A posed hull's: the cooked hull's inner ball, mapped by the
// scale (S ball(c, r) contains ball(S c, r min|s|)); a hull without one (not cooked) gets its posed vertices' mean
// and the mean's least distance below its faces.
template <class T> InnerBall<T> boxInnerBall(const BoxGeometry<T>& box, const Transform<T>& pose);
template <class T> InnerBall<T> hullInnerBall(const ConvexMeshGeometry<T>& hull, const Transform<T>& pose, const Polytope<T>& posed);

// Returns false when separated; otherwise the exact MTD of a (geom0) against b, as penetrationPolytopes.
template <class T>
bool penetrationPolytopesCertified(const Polytope<T>& a, const InnerBall<T>& ballA, const Polytope<T>& b,
                                   const InnerBall<T>& ballB, Vec3<T>& direction, T& depth);

// Per-thread counts of the searches above and of those the full SAT answered (for measurement and tests).
struct PolytopeMtdCounts {
  std::uint64_t searches = 0, fullSat = 0;
};
PolytopeMtdCounts& polytopeMtdCounts();

}  // namespace gq::detail
