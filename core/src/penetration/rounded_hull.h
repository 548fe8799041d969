#pragma once
// The exact MTD of a sphere or capsule (a point or segment core plus a radius) against an unscaled cooked hull,
// computed in the hull's own frame from its polygons: no posed copy of the hull is built.
//  - Every face plane's signed distance to the core's endpoints: the largest of min(s(a), s(b)) is a separating
//    gap when positive (more than the radius: apart), and clipping the core by all planes tells whether it meets the
//    hull.
//  - Core inside the hull or crossing it: the push-out is the minimum over the facets of (hull - core), that is the
//    faces' -min(s(a), s(b)) and, for a segment, the hull edges whose Gauss-map arc crosses the great circle
//    perpendicular to the segment (the crossing is then the facet normal k, and the push-out k.(edge vertex - a) is
//    O(1)); an undecided crossing (its sign within kEpsilon, or a flat arc) is projected in full on both signs, as
//    the full SAT does. Radius added.
//  - Core outside: the hull point closest to the core lies on a face that some core point sees (s > 0; the
//    offset between the closest points is a non-negative combination of the normals of the faces there), so only
//    those faces are searched: an endpoint's projection inside the polygon, or the polygon's edges. Radius less
//    that distance.
// These are the same minima as the SAT and closest-point search over the posed polytope (overlap/polytope.h),
// which answers what this does not take (a scaled hull, polygons of fewer than 3 vertices, a non-manifold hull).
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
