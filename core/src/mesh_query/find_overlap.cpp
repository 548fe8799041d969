// findOverlapTriangleMesh / findOverlapHeightField: the triangles a sphere, capsule or box touches, with paging.
// The shape is expressed in the surface's frame (the surface sits at the identity), so far-away poses keep their
// relative precision; culling (BVH or cell range) then the exact per-triangle test of mesh_pairs/.
#include <string>

#include "common/validate.h"
#include "cook/height_field_layout.h"
#include "gq/mesh_query.h"
#include "mesh_pairs/shape_triangle.h"
#include "mesh_pairs/surface.h"

namespace gq {
namespace {

// The spec's PxMeshQuery accepts only spheres, capsules and boxes.
template <class T> Status checkQueryShape(const Geometry<T>& g, const Transform<T>& pose) {
  if (Status s = detail::checkGeometryAndPose(g, pose, detail::kPoseField); !s.ok()) return s;
  const GeometryType t = g.type();
  if (t != GeometryType::Sphere && t != GeometryType::Capsule && t != GeometryType::Box)
    return Status::unsupported("mesh overlap queries take a sphere, capsule or box").withType(t);
  return Status();
}

Status checkPage(const TriangleOverlapPage& page) {
  if (page.indices == nullptr && page.capacity > 0)
    return Status::invalid("page.indices is null but page.capacity is not 0");
  return Status();
}

// Walks the overlapping triangles in the surface's fixed order, skipping the first page.start.
template <class T, class Surface>
void collectOverlaps(const detail::TriangleQueryShape<T>& shape, const Surface& surface,
                     const TriangleOverlapPage& page, TriangleOverlapPageResult& result) {
  std::uint32_t* const results = page.indices;
  const std::uint32_t bufferSize = page.capacity, startIndex = page.start;
  std::uint32_t seen = 0, written = 0;
  bool more = false;
  surface.forEachTriangle(shape.cullBounds(), [&](std::uint32_t index, const Triangle<T>& tri) {
    if (!shape.overlaps(tri)) return false;
    if (seen++ < startIndex) return false;
    if (written == bufferSize) {
      more = true;
      return true;
    }
    results[written++] = index;
    return false;
  });
  result.overflow = more;
  result.count = written;
}

}  // namespace

template <class T>
Status findOverlapTriangleMesh(const Geometry<T>& geom, const Transform<T>& pose, const TriangleMeshGeometry<T>& mesh,
                               const Transform<T>& meshPose, const TriangleOverlapPage& page,
                               TriangleOverlapPageResult& result) noexcept {
  return detail::guarded([&]() -> Status {
    if (Status s = checkQueryShape(geom, pose); !s.ok()) return s;
    if (Status s = detail::checkGeometryAndPose(Geometry<T>(mesh), meshPose, detail::kMeshPoseField); !s.ok()) return s;
    if (Status s = checkPage(page); !s.ok()) return s;
    const detail::TriangleQueryShape<T> shape(geom, pose.relativeTo(meshPose));
    const detail::MeshSurface<T> surface(mesh, Transform<T>());
    collectOverlaps(shape, surface, page, result);
    return Status();
  });
}

template <class T>
Status findOverlapHeightField(const Geometry<T>& geom, const Transform<T>& pose,
                              const HeightFieldGeometry<T>& heightField, const Transform<T>& heightFieldPose,
                              const TriangleOverlapPage& page, TriangleOverlapPageResult& result) noexcept {
  return detail::guarded([&]() -> Status {
    if (Status s = checkQueryShape(geom, pose); !s.ok()) return s;
    if (Status s = detail::checkGeometryAndPose(Geometry<T>(heightField), heightFieldPose, detail::kHeightFieldPoseField); !s.ok())
      return s;
    if (!detail::heightFieldIsWellFormed(*heightField.heightField))
      return Status::invalid("heightfield data is empty or inconsistent (use cookHeightField)");
    if (Status s = checkPage(page); !s.ok()) return s;
    const detail::TriangleQueryShape<T> shape(geom, pose.relativeTo(heightFieldPose));
    const detail::HeightFieldSurface<T> surface(heightField, Transform<T>());
    collectOverlaps(shape, surface, page, result);
    return Status();
  });
}

template Status findOverlapTriangleMesh<float>(const Geometry<float>&, const Transform<float>&,
                                               const TriangleMeshGeometry<float>&, const Transform<float>&,
                                               const TriangleOverlapPage&, TriangleOverlapPageResult&);
template Status findOverlapTriangleMesh<double>(const Geometry<double>&, const Transform<double>&,
                                                const TriangleMeshGeometry<double>&, const Transform<double>&,
                                                const TriangleOverlapPage&, TriangleOverlapPageResult&);
template Status findOverlapHeightField<float>(const Geometry<float>&, const Transform<float>&,
                                              const HeightFieldGeometry<float>&, const Transform<float>&,
                                              const TriangleOverlapPage&, TriangleOverlapPageResult&);
template Status findOverlapHeightField<double>(const Geometry<double>&, const Transform<double>&,
                                               const HeightFieldGeometry<double>&, const Transform<double>&,
                                               const TriangleOverlapPage&, TriangleOverlapPageResult&);

}  // namespace gq
