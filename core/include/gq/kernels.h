#pragma once
// gq::kernels: the geometry kernels under the façade, for hosts with their own pose types.
//
// The queries of gq/query.h validate their input, bring both poses into one frame and dispatch on the geometry
// types; then they call these kernels. A host that already holds its shapes and poses in its own form (rotation
// matrices, FCL's Transform3, Bullet's btTransform, a robot's link frames) calls the kernels directly and pays only
// for the geometry: the FCL and Bullet adapters and the URDF self-collision checker are built on this layer and on
// the public headers beside it, nothing else. Each kernel is the one implementation core's own queries run.
//
// What the layer does NOT do: validate. Inputs must be finite, sizes positive (as the geometry types require),
// rotations orthonormal with determinant +1, unit vectors unit, cooked data alive for the call; the façade checks
// these and returns a Status, a kernel trusts them (a bad input gives some answer, never a fault, but not a
// meaningful one). Touching counts as overlapping, as in the façade.
//
// Units and frames: lengths in the caller's unit. The plain-vector forms take both shapes in one frame, usually
// one shape's own (a box is centred at the origin with half extents h; a capsule is its centre, unit axis or half
// axis vector, and radius; a cylinder's axis is X); the Transform forms take the façade's poses. Results are in the
// frame of the inputs. Distance conventions are gq::DistanceResult's (gq/query.h): normal unit from shape 0
// towards shape 1, point1 = point0 + distance * normal, negative when penetrating.
//
// Every kernel exists for float and double (explicit instantiations in core). The headers:
//   gq/kernels/vector.h    unit vectors and norms safe at the ends of the floating-point range
//   gq/kernels/segment.h   closest points of points and segments
//   gq/kernels/clip.h      a polygon clipped to a rectangle (contact sets' incident faces)
//   gq/kernels/overlap.h   boolean overlap per primitive pair, certificates (cylinder-box, hull balls), GJK overlap
//   gq/kernels/distance.h  signed distance per primitive pair, box-box and box-cylinder in a box's frame, GJK/EPA
//   gq/kernels/gjk.h       the convex support shape (ConvexShape), GJK distance and overlap, EPA, hull start tables
//   gq/kernels/mesh.h      a triangle-mesh instance's frames and a convex shape tested against many triangles
//   gq/kernels/custom.h    the query callbacks of custom geometry, asked before a custom pair's generic kernel
//
// Stability: this layer follows core's releases, not the façade's compatibility promise; names and signatures may
// change with the kernels. Prefer gq/query.h (and prepared shapes, gq/shape.h) unless a host's pose type makes the
// conversion the dominant cost.
#include "gq/kernels/clip.h"
#include "gq/kernels/custom.h"
#include "gq/kernels/distance.h"
#include "gq/kernels/gjk.h"
#include "gq/kernels/mesh.h"
#include "gq/kernels/overlap.h"
#include "gq/kernels/segment.h"
#include "gq/kernels/vector.h"
