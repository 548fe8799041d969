// computeTriangleMeshPenetration / computeHeightFieldPenetration: the spec's iterative depenetration. Each
// iteration moves the shape by the deepest MTD among the triangles it touches, skipping (for one-sided surfaces)
// triangles whose plane has the shape's centre behind it. Runs in the surface's frame for precision.
#include <string>

#include "common/validate.h"
#include "common/unit_vector.h"
#include "cook/height_field_layout.h"
#include "gjk/gjk.h"
#include "gq/mesh_query.h"
#include "mesh_pairs/shape_triangle.h"
#include "mesh_pairs/surface.h"

namespace gq {
namespace {

template <class T> Status checkPenetrationShape(const Geometry<T>& g, const Transform<T>& pose, std::uint32_t maxIter) {
  if (Status s = detail::checkGeometryAndPose(g, pose, detail::kPoseField); !s.ok()) return s;
  if (!detail::isConvexShapeType(g.type()))
    return Status::unsupported("mesh penetration takes a convex shape").withType(g.type());
  if (const auto* c = g.template getIf<CustomGeometry<T>>(); c && !c->callbacks->isConvex())
    return Status::unsupported("mesh penetration needs a convex custom geometry (isConvex() is false)");
  if (maxIter == 0) return Status::invalid("maxIter must be at least 1");
  return Status();
}

// The deepest push among the counted triangles the shape touches at `pose`; false when none counts.
template <class T, class Surface>
bool deepestPush(const Geometry<T>& geom, const Transform<T>& pose, const Surface& surface, bool doubleSided,
                 detail::TrianglePush<T>& deepest, T& shapeSize) {
  const detail::TriangleQueryShape<T> shape(geom, pose);
  shapeSize = shape.size();
  const Vec3<T> centre = shape.center();
  bool found = false;
  surface.forEachTriangle(shape.cullBounds(), [&](std::uint32_t, const Triangle<T>& tri) {
    const Vec3<T> n = (tri.verts[1] - tri.verts[0]).cross(tri.verts[2] - tri.verts[0]);
    if (!doubleSided && n.dot(centre - tri.verts[0]) < T(0)) return false;  // centre behind the triangle: ignored
    if (!shape.overlaps(tri)) return false;
    const detail::TrianglePush<T> push = shape.pushOut(tri, !doubleSided);
    if (!found || push.depth > deepest.depth) deepest = push;
    found = true;
    return false;
  });
  return found;
}

template <class T, class Surface>
void iteratePenetration(PenetrationResult<T>& result, const Geometry<T>& geom, const Transform<T>& pose,
                        const Surface& surface, bool doubleSided, std::uint32_t maxIter, std::uint32_t& moves) {
  Transform<T> current = pose;
  Vec3<T> total = Vec3<T>::Zero(), firstDirection = Vec3<T>::UnitX();
  bool penetrating = false;
  moves = 0;
  for (std::uint32_t k = 0; k < maxIter; ++k) {
    detail::TrianglePush<T> push;
    T size = T(0);
    if (!deepestPush(geom, current, surface, doubleSided, push, size)) break;
    if (k == 0) {
      penetrating = true;
      firstDirection = push.direction;
    }
    // Only touching contacts left: converged (touching counts as overlapping, so it never reports false).
    if (push.depth <= T(tol::Rel<T>::kEpsilon) * size) break;
    total += push.direction * push.depth;
    current.p += push.direction * push.depth;
    ++moves;
  }
  result.penetrating = penetrating;
  // Range-safe: a push of ~1e-23 in float has a subnormal squared norm, and total / |total| came out 3 % long.
  result.depth = detail::rangeSafeNorm(total);
  Vec3<T> unit;
  result.direction = result.depth > T(0) && detail::tryUnit(total, unit) ? unit : firstDirection;
}

}  // namespace

// Coordinates near the scalar's range overflow the per-triangle MTDs (found by fuzz_mesh_queries): no NaN goes out.
namespace {
template <class T> Status checkFiniteResult(const PenetrationResult<T>& r) {
  if (isFinite(r.direction) && std::isfinite(r.depth)) return {};
  return Status::notConverged("mesh penetration overflowed the scalar range (coordinates too large for this type)");
}

// The iteration run in the surface's frame (surface built at the identity), its direction rotated back to world;
// `result` and `iterations` are written only on success.
template <class T, class Surface>
Status penetrationInSurfaceFrame(PenetrationResult<T>& result, const Geometry<T>& geom, const Transform<T>& pose,
                                 const Surface& surface, const Transform<T>& surfacePose, bool doubleSided,
                                 std::uint32_t maxIter, std::uint32_t* iterations) {
  PenetrationResult<T> r;
  std::uint32_t moves = 0;
  iteratePenetration(r, geom, pose.relativeTo(surfacePose), surface, doubleSided, maxIter, moves);
  if (r.penetrating) r.direction = surfacePose.rotate(r.direction);
  if (Status f = checkFiniteResult(r); !f.ok()) return f;
  result = r;
  if (iterations) *iterations = moves;
  return Status();
}
}  // namespace

template <class T>
Status computeTriangleMeshPenetration(PenetrationResult<T>& result, const Geometry<T>& geom, const Transform<T>& pose,
                                      const TriangleMeshGeometry<T>& mesh, const Transform<T>& meshPose,
                                      std::uint32_t maxIter, std::uint32_t* iterations) noexcept {
  return detail::guarded([&]() -> Status {
    if (Status s = checkPenetrationShape(geom, pose, maxIter); !s.ok()) return s;
    if (Status s = detail::checkGeometryAndPose(Geometry<T>(mesh), meshPose, detail::kMeshPoseField); !s.ok()) return s;
    return penetrationInSurfaceFrame(result, geom, pose, detail::MeshSurface<T>(mesh, Transform<T>()), meshPose,
                                     mesh.doubleSided(), maxIter, iterations);
  });
}

template <class T>
Status computeHeightFieldPenetration(PenetrationResult<T>& result, const Geometry<T>& geom, const Transform<T>& pose,
                                     const HeightFieldGeometry<T>& heightField, const Transform<T>& heightFieldPose,
                                     std::uint32_t maxIter, std::uint32_t* iterations) noexcept {
  return detail::guarded([&]() -> Status {
    if (Status s = checkPenetrationShape(geom, pose, maxIter); !s.ok()) return s;
    if (Status s = detail::checkGeometryAndPose(Geometry<T>(heightField), heightFieldPose, detail::kHeightFieldPoseField); !s.ok())
      return s;
    if (!detail::heightFieldIsWellFormed(*heightField.heightField))
      return Status::invalid("heightfield data is empty or inconsistent (use cookHeightField)");
    return penetrationInSurfaceFrame(result, geom, pose, detail::HeightFieldSurface<T>(heightField, Transform<T>()),
                                     heightFieldPose, heightField.doubleSided(), maxIter, iterations);
  });
}

template Status computeTriangleMeshPenetration<float>(PenetrationResult<float>&, const Geometry<float>&,
                                                      const Transform<float>&, const TriangleMeshGeometry<float>&,
                                                      const Transform<float>&, std::uint32_t, std::uint32_t*);
template Status computeTriangleMeshPenetration<double>(PenetrationResult<double>&, const Geometry<double>&,
                                                       const Transform<double>&, const TriangleMeshGeometry<double>&,
                                                       const Transform<double>&, std::uint32_t, std::uint32_t*);
template Status computeHeightFieldPenetration<float>(PenetrationResult<float>&, const Geometry<float>&,
                                                     const Transform<float>&, const HeightFieldGeometry<float>&,
                                                     const Transform<float>&, std::uint32_t, std::uint32_t*);
template Status computeHeightFieldPenetration<double>(PenetrationResult<double>&, const Geometry<double>&,
                                                      const Transform<double>&, const HeightFieldGeometry<double>&,
                                                      const Transform<double>&, std::uint32_t, std::uint32_t*);

}  // namespace gq
