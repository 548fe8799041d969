#pragma once
// The exact MTD of two polytopes (the minimum push-out over the facets of their Minkowski difference, as
// satMinimumOverlap computes it over every face and crossing edge pair) at a cost linear in their size.
//
// Certificate: with E_B = {c_B + M_B y : |y| <= 1} an ellipsoid inside B (its smallest semi-axis r_B: the ball
// about c_B of that radius is inside too), every facet normal u of A - B along which A is pushed out has
// h_B(-u) >= h_E(-u) = -u.c_B + |M_B^T u|, so
//  - a face f of A (normal n, offset o) pushes out by at least  -o - n.c_B + |M_B^T n|,
//  - an edge pair whose Gauss-map arcs cross at u, u on the arc of A's edge (faces f1, f2, a vertex v of the edge),
//    pushes out by at least  min over u in the arc of u.z + (a term >= 0), for z = v - c_B (term: r_B) and for
//    z = v - c_B + x_i, x_i = M_B M_B^T n_i / |M_B^T n_i| the point of E_B - c_B supporting n_i (term: 0, since
//    |M^T u| >= u.x_i); with e = min(n1.z, n2.z) that minimum of the linear u.z is >= e when e > 0 and
//    >= e / cos(theta / 2) otherwise (theta: the arc's angle);
// and symmetrically for B with an ellipsoid inside A. Once some axis's exact push-out `best` is known, every face
// whose bound is at least `best` and every edge pair one of whose edges has a bound at least `best` cannot give less:
// only the remaining faces and pairs are evaluated, exactly as the full SAT evaluates them (the same projections and
// arc tests). The answer therefore is the full SAT's minimum; what is skipped is proven not smaller (the bounds less
// a margin for their rounding).
// Arcs between (nearly) opposite faces (a hull scaled flat) span no usable angle: their edges are always evaluated.
// Where the argument does not apply, the full SAT answers: a side without faces or whose edge faces are unknown
// (non-manifold input).
#include <cstdint>

#include "overlap/polytope.h"

namespace gq::detail {

// An ellipsoid {centre + axes y : |y| <= 1} inside a shape, and its smallest semi-axis `radius`.
template <class T> struct InnerEllipsoid {
  Vec3<T> centre;
  Mat3<T> axes;
  T radius;
};
// A posed box's: the inscribed one. A posed hull's: about the cooked hull's interior point, along the mesh's axes in
// proportion to its bounds' extents, grown until it touches a face (then mapped by the scale and the pose); a hull not
// cooked gets the ball about its posed vertices' mean of radius the mean's least distance below its faces.
template <class T> InnerEllipsoid<T> boxInnerEllipsoid(const BoxGeometry<T>& box, const Transform<T>& pose);
template <class T>
InnerEllipsoid<T> hullInnerEllipsoid(const ConvexMeshGeometry<T>& hull, const Transform<T>& pose, const Polytope<T>& posed);

// Returns false when separated; otherwise the exact MTD of a (geom0) against b, as penetrationPolytopes.
template <class T>
bool penetrationPolytopesCertified(const Polytope<T>& a, const InnerEllipsoid<T>& innerA, const Polytope<T>& b,
                                   const InnerEllipsoid<T>& innerB, Vec3<T>& direction, T& depth);

// Per-thread counts of the exact polytope MTD searches (for measurement and tests): all of them, those answered in
// geom0's frame over the Gauss-map trees (hull_pair_mtd.h), and those the full SAT answered.
struct PolytopeMtdCounts {
  std::uint64_t searches = 0, inFrame = 0, fullSat = 0;
};
PolytopeMtdCounts& polytopeMtdCounts();

}  // namespace gq::detail
