#pragma once
// ShapeDesc -> gq::Geometry<T>. Convex hulls, meshes and heightfields are cooked once per distinct description
// (keyed by ShapeDesc::cookKey) and shared by every case of the file.
#include <map>
#include <memory>
#include <string>

#include "case.h"
#include "gq/cooking.h"
#include "gq/geometry.h"
#include "gq/transform.h"

namespace gq::cases {

template <class T> class GqShapeFactory {
 public:
  // Fails with the cooking or size-validation status.
  Status build(const ShapeDesc& desc, Geometry<T>& out);

 private:
  Status convex(const ShapeDesc& desc, std::shared_ptr<const ConvexMesh<T>>& out);
  Status mesh(const ShapeDesc& desc, std::shared_ptr<const TriangleMesh<T>>& out);
  Status heightField(const ShapeDesc& desc, std::shared_ptr<const HeightField<T>>& out);

  std::map<std::string, std::shared_ptr<const ConvexMesh<T>>> convexCache_;
  std::map<std::string, std::shared_ptr<const TriangleMesh<T>>> meshCache_;
  std::map<std::string, std::shared_ptr<const HeightField<T>>> heightFieldCache_;
};

template <class T> Transform<T> toTransform(const PoseDesc& pose) {
  return Transform<T>(pose.p.cast<T>(), pose.q.cast<T>());
}

}  // namespace gq::cases
