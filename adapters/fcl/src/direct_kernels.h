#pragma once
// The adapter's fast path: core's per-pair kernels (core/src/overlap, core/src/distance) called directly on
// geometry the adapter has already validated (converted sizes, usable poses), without the public façade's
// re-validation, dispatch tables and Status strings. Only closed convex solids and half-spaces come here: sphere,
// plane (an FCL Halfspace), capsule, box, convex hull and convex custom shapes (cylinder, cone, ellipsoid, triangle).
// Semantics are the façade's: touching overlaps; distance is signed, normal from the first shape to the second.
#include "gq/geometry.h"
#include "gq/query.h"
#include "gq/status.h"
#include "gq/transform.h"

namespace gq::fcl::detail {

// Overlap of a and b; false (hit untouched) when the pair has no kernel (plane against plane).
template <class T>
bool directOverlap(const Geometry<T>& a, const Transform<T>& pa, const Geometry<T>& b, const Transform<T>& pb, bool& hit);

// Signed distance, witnesses and normal of a and b in world space. Returns false when the pair has no kernel
// (plane against plane) or the answer is not usable (GJK/EPA failed, non-finite result); `out` is then unspecified.
template <class T>
bool directDistance(const Geometry<T>& a, const Transform<T>& pa, const Geometry<T>& b, const Transform<T>& pb,
                    DistanceResult<T>& out);

}  // namespace gq::fcl::detail
