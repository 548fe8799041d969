#pragma once
// Exact primitive-triangle kernels shared by the mesh and heightfield pair queries (overlap, mesh queries,
// distance). Touching counts as overlapping: every comparison is inclusive. All points are in one frame.
#include "gq/math.h"
#include "gq/mesh_query.h"

namespace gq::detail {

// Closest points of a segment [p, q] and a triangle; distSq = |onSegment - onTriangle|^2.
template <class T> struct SegmentTriangleClosest {
  T distSq = T(0);
  Vec3<T> onSegment = Vec3<T>::Zero();
  Vec3<T> onTriangle = Vec3<T>::Zero();
};

// Segment vs triangle: 0 when the segment crosses (or touches) the triangle, else the minimum over the endpoints vs
// the triangle and the segment vs the three edges (the closest pair of two disjoint convex sets has a vertex or an
// edge-edge pair on it).
template <class T> SegmentTriangleClosest<T> closestSegmentTriangle(const Vec3<T>& p, const Vec3<T>& q, const Triangle<T>& tri);

// Shortest translation of a segment [p, q] along which it leaves a triangle it touches or crosses: `exit` along the
// unit `direction` (negative: already apart by -exit along it). The set segment - triangle is a polytope whose face
// normals are the triangle normal n and s x e_i (segment x each edge), so the least exit over those axes, both signs,
// is the exact minimum translation. `hint` (the closest-point direction of a disjoint pair, exact there but
// ill-conditioned near contact) joins the candidates. A capsule of radius r leaves with depth r + exit.
template <class T> struct SegmentTriangleExit {
  Vec3<T> direction = Vec3<T>::UnitX();
  T exit = T(0);
};
template <class T>
SegmentTriangleExit<T> segmentTriangleExit(const Vec3<T>& p, const Vec3<T>& q, const Triangle<T>& tri, const Vec3<T>* hint);

// Sphere (centre, radius) touches or intersects the triangle: |c - closest(c)|^2 <= r^2.
template <class T> bool overlapSphereTriangle(const Vec3<T>& center, T radius, const Triangle<T>& tri);

// Capsule (segment [p, q], radius) vs triangle: segment-triangle distance <= radius.
template <class T> bool overlapCapsuleTriangle(const Vec3<T>& p, const Vec3<T>& q, T radius, const Triangle<T>& tri);

// Box (half extents, at the origin, axis aligned) vs a triangle given in the box's frame: SAT over 13 axes (3 box
// face normals, the triangle normal, 9 box-axis x triangle-edge crosses).
template <class T> bool overlapBoxTriangle(const Vec3<T>& halfExtents, const Triangle<T>& triInBoxFrame);

// Triangle vs triangle: SAT over 17 axes (2 normals, 9 edge x edge crosses, 6 in-plane edge normals that decide the
// coplanar case). A zero axis (parallel edges) never separates, so it needs no special case.
template <class T> bool overlapTriangleTriangle(const Triangle<T>& a, const Triangle<T>& b);

// Closest points of two triangles (0 and a common point when they intersect): the minimum of the 6 edge-vs-triangle
// distances covers vertex-face, edge-edge and crossing configurations.
template <class T> struct TrianglePairClosest {
  T distSq = T(0);
  Vec3<T> onA = Vec3<T>::Zero();
  Vec3<T> onB = Vec3<T>::Zero();
};
template <class T> TrianglePairClosest<T> closestTriangleTriangle(const Triangle<T>& a, const Triangle<T>& b);

template <class T> Bounds3<T> triangleBounds(const Triangle<T>& tri) {
  Bounds3<T> b;
  for (const auto& v : tri.verts) b.include(v);
  return b;
}

}  // namespace gq::detail
