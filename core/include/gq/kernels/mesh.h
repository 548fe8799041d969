#pragma once
// The mesh-instance frames and the convex query shape tested against many triangles, for hosts that walk a mesh's
// triangles themselves (the FCL adapter's mesh pairs).
// MeshInstance: the frames of a triangle-mesh instance: mesh space (cooked vertices) -> shape space
// (x_shape = S x_mesh with S = R diag(scale) R^T) -> world (pose). Shared by the mesh raycast, point distance, bounds
// and getTriangle.
// TriangleQueryShape: a convex query shape (sphere, capsule, box, convex mesh, convex custom) prepared once and tested
// against many world triangles: exact overlap (closed forms for sphere/capsule, 13-axis SAT for the box, GJK for hulls
// and custom shapes), distance (closed forms for sphere/capsule, GJK otherwise) and the per-triangle depenetration
// used by the iterative mesh penetration.
#include <limits>

#include "gq/cooking.h"
#include "gq/custom.h"
#include "gq/geometry.h"
#include "gq/kernels/gjk.h"
#include "gq/mesh_query.h"
#include "gq/query.h"
#include "gq/transform.h"

namespace gq::kernels {

template <class T> struct MeshInstance {
  const TriangleMesh<T>& mesh;
  Transform<T> pose;
  Mat3<T> scale;     // S (symmetric)
  Mat3<T> invScale;  // S^-1 = R diag(1/scale) R^T, also the normal transform (S^-T = S^-1)
  bool flips;        // mirrored scale: vertices 1 and 2 swap so the winding stays outward

  MeshInstance(const TriangleMeshGeometry<T>& g, const Transform<T>& p)
      : mesh(*g.mesh), pose(p), scale(g.scale.toMatrix()), flips(g.scale.flipsWinding()) {
    const Mat3<T> r = g.scale.rotation.toRotationMatrix();
    invScale = r * g.scale.scale.cwiseInverse().asDiagonal() * r.transpose();
  }

  Vec3<T> toWorld(const Vec3<T>& meshPoint) const { return pose.transform(scale * meshPoint); }

  // World triangle of a cooked triangle, in reported order (1 and 2 swapped under a mirrored scale).
  Triangle<T> worldTriangle(std::uint32_t cooked, std::uint32_t* vertexIndices = nullptr) const {
    TriangleIndices idx = mesh.triangles[cooked];
    if (flips) std::swap(idx[1], idx[2]);
    Triangle<T> tri;
    for (int k = 0; k < 3; ++k) {
      tri.verts[k] = toWorld(mesh.vertices[idx[k]]);
      if (vertexIndices) vertexIndices[k] = idx[k];
    }
    return tri;
  }
};


// A triangle as a convex custom shape for GJK/EPA, in a frame centred on its centroid (keeps GJK's relative
// precision when the triangle is far from the origin).
template <class T> class SurfaceTriangleSupport final : public CustomGeometryCallbacks<T> {
 public:
  explicit SurfaceTriangleSupport(const Triangle<T>& worldTri);
  const char* name() const override { return "triangle"; }
  Bounds3<T> localBounds() const override;
  Vec3<T> support(const Vec3<T>& dir) const override;
  bool raycast(const Vec3<T>&, const Vec3<T>&, T, HitFlags, RaycastHit<T>&) const override { return false; }
  // The GJK shape of this triangle (holds a pointer to *this).
  ConvexShape<T> shape() const;

 private:
  Vec3<T> centroid_;
  Vec3<T> local_[3];
};

// Depenetration of a shape from one triangle: translating the shape by direction * depth separates them.
template <class T> struct TrianglePush {
  Vec3<T> direction = Vec3<T>::UnitX();
  T depth = T(0);
};

template <class T> class TriangleQueryShape {
 public:
  // geom must be a sphere, capsule, box, convex mesh or convex custom shape (checked by the façades), and outlive
  // this object: a hull's bounds and ball are read from it on the first ask.
  TriangleQueryShape(const Geometry<T>& geom, const Transform<T>& pose);

  const Bounds3<T>& worldBounds() const;
  // Culling box: the world bounds grown by a relative epsilon, so touching triangles are never culled by rounding.
  Bounds3<T> cullBounds() const;
  // Culling box in another space: the AABB of the image of the shape grown by cullBounds' epsilon under
  // x -> linear (x - origin). Spheres, capsules and boxes map exactly (a rotated box's image box is tighter than the
  // image of its world box); other shapes map their cullBounds.
  Bounds3<T> cullBoundsIn(const Mat3<T>& linear, const Vec3<T>& origin) const;
  T size() const { return convex_.size; }
  Vec3<T> center() const { return centre_; }

  bool overlaps(const Triangle<T>& tri) const;
  // Distance to the triangle, >= 0 (0 in contact); point0 on the shape, point1 on the triangle, normal shape->triangle.
  // In contact the witnesses are the triangle point of deepest contact (point0 = point1).
  // `farEnough`: the caller keeps only distances up to it; returns false (out unwritten) when GJK certified the
  // triangle farther (hulls, boxes, custom shapes stop early; the closed forms always answer).
  bool distanceTo(const Triangle<T>& tri, DistanceResult<T>& out,
                  T farEnough = std::numeric_limits<T>::infinity()) const;
  // A lower bound of distanceTo from a ball around the shape (its centre's distance to the triangle less the ball's
  // radius): ~100 instructions where distanceTo runs GJK on hulls and custom shapes. -inf when there is no ball.
  T distanceLowerBound(const Triangle<T>& tri) const;
  // Whether distanceTo runs GJK (hulls, boxes, custom shapes), so that distanceLowerBound is worth asking first.
  bool distanceRunsGjk() const { return type_ != GeometryType::Sphere && type_ != GeometryType::Capsule; }
  // MTD of the shape against the triangle (call only when overlaps(tri)); with `oneSided`, a push towards the
  // triangle's back is replaced by the push along its normal that puts the whole shape in front of its plane.
  TrianglePush<T> pushOut(const Triangle<T>& tri, bool oneSided) const;

 private:
  GeometryType type_;
  Transform<T> pose_;
  ConvexShape<T> convex_;
  T radius_ = T(0);                  // sphere, capsule
  Vec3<T> segA_, segB_;              // capsule segment (world); sphere: both are the centre
  Vec3<T> halfExtents_;              // box
  const ConvexMeshGeometry<T>* hull_ = nullptr;
  // World bounds: a hull's on the first ask (a pass over its vertices that overlap tests never need), else at once.
  mutable Bounds3<T> bounds_;
  mutable bool boundsPending_ = false;
  // A point inside the shape (world, placed once): center(), and GJK's first direction for a hull or custom shape
  // against a triangle runs from it to the triangle's centroid.
  Vec3<T> centre_;
  // A ball holding the shape (world), for distanceLowerBound: a box's at once, a hull's on the first ask (its
  // vertices' farthest from their centroid; overlap queries never need it).
  mutable Vec3<T> ballCentre_ = Vec3<T>::Zero();
  mutable T ballRadius_ = std::numeric_limits<T>::infinity();
  mutable bool ballPending_ = false;
  // Warm start of distanceTo's GJK from the previous triangle: a surface query visits neighbouring triangles in
  // turn, whose closest features lie close (the cache is safe for any shapes: seedSimplex re-evaluates supports).
  mutable GjkCache<T> warm_;
};

}  // namespace gq::kernels
