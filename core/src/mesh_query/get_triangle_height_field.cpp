// getTriangle for heightfields: triangle `triangleIndex` (2*cell or 2*cell+1, see gq/cooking.h) in world space.
// Triangles of hole cells are returned too (they exist in the layout; queries just never report them).
#include <string>

#include "common/validate.h"
#include "cook/height_field_layout.h"
#include "gq/mesh_query.h"

namespace gq {

template <class T>
Status getTriangle(const HeightFieldGeometry<T>& heightField, const Transform<T>& pose, std::uint32_t triangleIndex,
                   Triangle<T>& triangle, std::uint32_t* vertexIndices) noexcept {
  return detail::guarded([&]() -> Status {
    if (Status s = detail::checkGeometryAndPose(Geometry<T>(heightField), pose, detail::kPoseField); !s.ok()) return s;
    const HeightField<T>& hf = *heightField.heightField;
    if (!detail::heightFieldIsWellFormed(hf))
      return Status::invalid("heightfield data is empty or inconsistent (use cookHeightField)");
    const std::uint32_t count = detail::heightFieldTriangleCount(hf);
    if (triangleIndex >= count)
      return Status::invalid("triangle index is out of range of the heightfield's triangles").withIndex(triangleIndex);
    const std::array<std::uint32_t, 3> samples = detail::heightFieldTriangleSamples(hf, triangleIndex);
    for (int i = 0; i < 3; ++i) {
      triangle.verts[i] = pose.transform(detail::heightFieldVertex(heightField, samples[i]));
      if (vertexIndices) vertexIndices[i] = samples[i];
    }
    return Status();
  });
}

template Status getTriangle<float>(const HeightFieldGeometry<float>&, const Transform<float>&, std::uint32_t,
                                   Triangle<float>&, std::uint32_t*);
template Status getTriangle<double>(const HeightFieldGeometry<double>&, const Transform<double>&, std::uint32_t,
                                    Triangle<double>&, std::uint32_t*);

}  // namespace gq
