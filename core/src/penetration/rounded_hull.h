#pragma once
// The exact MTD of a sphere or capsule (a point or segment core plus a radius) against an unscaled cooked hull,
// computed in the hull's own frame over its Gauss-map tree (penetration/gauss_tree.h): no posed copy of the hull is
// built, and whole groups of faces and edges are ruled out by one bound each.
//  - The minimum push-out over the facets of (hull - core), by branch and bound: the faces' -min(s(a), s(b)) (s: the
//    signed distance of the core's endpoints to the face plane) and, for a segment, the hull edges whose Gauss-map
//    arc crosses the great circle perpendicular to it (the crossing is then the facet normal k, and the push-out
//    k.(edge vertex - a) is O(1)); an undecided crossing (its sign within kEpsilon, or a flat arc) is evaluated on
//    both signs from support calls, as the full SAT does from all vertices. A tree node bounds every facet from its
//    faces and arcs by its ball and cap against the core's endpoints (no support call: the core's are its
//    endpoints). Not negative: the core meets the hull, and the depth is that plus the radius. Below minus the
//    radius: apart.
//  - Otherwise the core is outside: the hull point closest to it lies on a face that some core point sees (s > 0;
//    the offset between the closest points is a non-negative combination of the normals of the faces there), so
//    only those faces are searched (an endpoint's projection inside the polygon, or the polygon's edges; for a point,
//    only the edges whose line its projection is outside of). The face of the separating gap (or one beside the
//    gap's edge) is measured first; its closest pair is the answer when the plane through the hull's point
//    perpendicular to the pair's offset has the hull on one side (one support call) and the core on the other.
//    Otherwise the search goes on over the faces, skipping nodes whose cap and ball show that no face sees the core
//    or that every face is farther than the best distance found; it ends once a distance equals the separating gap.
//    Radius less that distance.
// These are the same minima as the SAT and closest-point search over the posed polytope (overlap/polytope.h),
// which answers what this does not take (a scaled hull, a non-manifold hull, one not made by cookConvexMesh).
#include "gq/geometry.h"
#include "gq/transform.h"
#include "overlap/polytope.h"

namespace gq::detail {

// Returns false when it does not apply (see above); otherwise true, with `penetrating` and, when penetrating,
// the direction (moving the core's shape by direction * depth separates it) and depth.
template <class T>
bool penetrationRoundedHull(const RoundedCore<T>& core, const ConvexMeshGeometry<T>& hull, const Transform<T>& pose,
                            bool& penetrating, Vec3<T>& direction, T& depth);

}  // namespace gq::detail
