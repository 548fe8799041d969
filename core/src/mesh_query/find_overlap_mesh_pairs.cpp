// findOverlapTriangleMeshPairs: dual BVH traversal (mesh_pairs/mesh_mesh.h) with the exact triangle-triangle test,
// or the exact triangle distance against `tolerance` for proximity queries. Mesh 1 is expressed in mesh 0's frame.
#include <cmath>

#include "common/validate.h"
#include "gq/mesh_query.h"
#include "mesh_pairs/mesh_mesh.h"
#include "mesh_pairs/surface_pairs.h"

namespace gq {

template <class T>
Status findOverlapTriangleMeshPairs(const TrianglePairCallback& callback, const TriangleMeshGeometry<T>& mesh0,
                                    const Transform<T>& pose0, const TriangleMeshGeometry<T>& mesh1,
                                    const Transform<T>& pose1, bool& overlapFound, T tolerance) noexcept {
  return detail::guarded([&]() -> Status {
    if (!callback) return Status::invalid("callback is empty");
    if (Status s = detail::checkGeometryAndPose(Geometry<T>(mesh0), pose0, detail::kPose0Field); !s.ok()) return s;
    if (Status s = detail::checkGeometryAndPose(Geometry<T>(mesh1), pose1, detail::kPose1Field); !s.ok()) return s;
    if (!std::isfinite(tolerance) || tolerance < T(0)) return Status::invalid("tolerance is negative or not finite");
    const detail::MeshSurface<T> a(mesh0, Transform<T>());
    const detail::MeshSurface<T> b(mesh1, pose1.relativeTo(pose0));
    bool found = false;
    detail::forEachTrianglePair(a, b, tolerance, [&](std::uint32_t ia, const Triangle<T>& ta, std::uint32_t ib,
                                                     const Triangle<T>& tb) {
      if (!detail::trianglesWithin(ta, tb, tolerance)) return false;
      found = true;
      return !callback(a.inputIndex(ia), b.inputIndex(ib));
    });
    overlapFound = found;
    return Status();
  });
}

template Status findOverlapTriangleMeshPairs<float>(const TrianglePairCallback&, const TriangleMeshGeometry<float>&,
                                                    const Transform<float>&, const TriangleMeshGeometry<float>&,
                                                    const Transform<float>&, bool&, float);
template Status findOverlapTriangleMeshPairs<double>(const TrianglePairCallback&, const TriangleMeshGeometry<double>&,
                                                     const Transform<double>&, const TriangleMeshGeometry<double>&,
                                                     const Transform<double>&, bool&, double);

}  // namespace gq
