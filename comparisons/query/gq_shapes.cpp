#include "gq_shapes.h"

#include "gq/custom_shapes.h"

namespace gq::cases {
namespace {

template <class T> std::vector<Vec3<T>> castPoints(const std::vector<Vec3d>& points) {
  std::vector<Vec3<T>> out;
  out.reserve(points.size());
  for (const Vec3d& p : points) out.push_back(p.cast<T>());
  return out;
}

template <class T> MeshScale<T> toMeshScale(const ScaleDesc& s) {
  return MeshScale<T>(s.s.cast<T>(), s.q.cast<T>());
}

MeshGeometryFlag sidedness(bool doubleSided) {
  return doubleSided ? MeshGeometryFlag::DoubleSided : MeshGeometryFlag::None;
}

}  // namespace

template <class T> Status GqShapeFactory<T>::convex(const ShapeDesc& desc, std::shared_ptr<const ConvexMesh<T>>& out) {
  if (auto it = convexCache_.find(desc.cookKey); it != convexCache_.end()) {
    out = it->second;
    return {};
  }
  if (Status s = cookConvexMesh<T>(castPoints<T>(desc.points), out); !s.ok()) return s;
  convexCache_.emplace(desc.cookKey, out);
  return {};
}

template <class T> Status GqShapeFactory<T>::mesh(const ShapeDesc& desc, std::shared_ptr<const TriangleMesh<T>>& out) {
  if (auto it = meshCache_.find(desc.cookKey); it != meshCache_.end()) {
    out = it->second;
    return {};
  }
  std::vector<TriangleIndices> triangles(desc.triangles.begin(), desc.triangles.end());
  if (Status s = cookTriangleMesh<T>(castPoints<T>(desc.points), triangles, out); !s.ok()) return s;
  meshCache_.emplace(desc.cookKey, out);
  return {};
}

template <class T>
Status GqShapeFactory<T>::heightField(const ShapeDesc& desc, std::shared_ptr<const HeightField<T>>& out) {
  if (auto it = heightFieldCache_.find(desc.cookKey); it != heightFieldCache_.end()) {
    out = it->second;
    return {};
  }
  HeightFieldDesc<T> hf;
  hf.rows = desc.rows;
  hf.columns = desc.columns;
  hf.heights.assign(desc.heights.begin(), desc.heights.end());
  hf.holes = desc.holes;
  if (Status s = cookHeightField<T>(hf, out); !s.ok()) return s;
  heightFieldCache_.emplace(desc.cookKey, out);
  return {};
}

template <class T> Status GqShapeFactory<T>::build(const ShapeDesc& desc, Geometry<T>& out) {
  switch (desc.kind) {
    case ShapeKind::Sphere: out = SphereGeometry<T>(T(desc.radius)); return {};
    case ShapeKind::Capsule: out = CapsuleGeometry<T>(T(desc.radius), T(desc.halfHeight)); return {};
    case ShapeKind::Box: out = BoxGeometry<T>(desc.halfExtents.cast<T>()); return {};
    case ShapeKind::Plane: out = PlaneGeometry<T>(); return {};
    case ShapeKind::Convex: {
      std::shared_ptr<const ConvexMesh<T>> hull;
      if (Status s = convex(desc, hull); !s.ok()) return s;
      out = ConvexMeshGeometry<T>(hull, toMeshScale<T>(desc.scale));
      return {};
    }
    case ShapeKind::Mesh: {
      std::shared_ptr<const TriangleMesh<T>> m;
      if (Status s = mesh(desc, m); !s.ok()) return s;
      out = TriangleMeshGeometry<T>(m, toMeshScale<T>(desc.scale), sidedness(desc.doubleSided));
      return {};
    }
    case ShapeKind::HeightField: {
      std::shared_ptr<const HeightField<T>> hf;
      if (Status s = heightField(desc, hf); !s.ok()) return s;
      out = HeightFieldGeometry<T>(hf, T(desc.heightScale), T(desc.rowScale), T(desc.columnScale),
                                   sidedness(desc.doubleSided));
      return {};
    }
    // Core's ready-made custom shapes share the case format's convention (axis = local X, the cone's apex at
    // +halfHeight), so the sizes pass through unchanged.
    case ShapeKind::Cylinder: {
      CustomGeometry<T> cylinder;
      if (Status s = makeCylinder<T>(T(desc.radius), T(desc.halfHeight), cylinder); !s.ok()) return s;
      out = cylinder;
      return {};
    }
    case ShapeKind::Cone: {
      CustomGeometry<T> cone;
      if (Status s = makeCone<T>(T(desc.radius), T(desc.halfHeight), cone); !s.ok()) return s;
      out = cone;
      return {};
    }
  }
  return Status::invalid("unknown shape kind");
}

template class GqShapeFactory<float>;
template class GqShapeFactory<double>;

}  // namespace gq::cases
