#include "shape_conversion.h"

#include <assimp/scene.h>

#include <cmath>
#include <memory>
#include <vector>

#include <dart/dynamics/BoxShape.hpp>
#include <dart/dynamics/CapsuleShape.hpp>
#include <dart/dynamics/ConeShape.hpp>
#include <dart/dynamics/CylinderShape.hpp>
#include <dart/dynamics/EllipsoidShape.hpp>
#include <dart/dynamics/HeightmapShape.hpp>
#include <dart/dynamics/MeshShape.hpp>
#include <dart/dynamics/MultiSphereConvexHullShape.hpp>
#include <dart/dynamics/PlaneShape.hpp>
#include <dart/dynamics/PyramidShape.hpp>
#include <dart/dynamics/SoftMeshShape.hpp>
#include <dart/dynamics/SphereShape.hpp>

#include <gq/cooking.h>
#include <gq/custom_shapes.h>

namespace gq {
namespace dart {
namespace {

namespace dd = ::dart::dynamics;
using Vec = Vec3<double>;

// gq's +X axis (capsule, cylinder and cone axis) onto DART's +Z.
Transform<double> xToZ() {
  Mat3<double> r;
  r << 0, 1, 0,  //
      0, 0, 1,   //
      1, 0, 0;
  return Transform<double>(Vec::Zero(), Quat<double>(r));
}

Status finish(const Geometry<double>& geometry, const Transform<double>& offset, ConvertedShape& out) {
  ConvertedShape converted;
  const Status s = makeShape(geometry, converted.shape);
  if (!s.ok()) return s;
  converted.offset = offset;
  out = std::move(converted);
  return Status();
}

// The triangles of every mesh of an assimp scene (DART's other detectors ignore the node transforms too), vertices
// scaled; triangle ids follow the meshes' order, each mesh's faces in order (non-triangle faces are skipped and keep
// no id).
Status meshFromScene(const aiScene* scene, const Eigen::Vector3d& scale, ConvertedShape& out) {
  if (scene == nullptr) return Status(StatusCode::InvalidArgument, "the mesh shape has no mesh");
  std::vector<Vec> vertices;
  std::vector<TriangleIndices> triangles;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    const auto base = static_cast<std::uint32_t>(vertices.size());
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& p = mesh->mVertices[v];
      vertices.emplace_back(p.x * scale.x(), p.y * scale.y(), p.z * scale.z());
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;
      triangles.push_back({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
    }
  }
  std::shared_ptr<const TriangleMesh<double>> cooked;
  const Status s = cookTriangleMesh(vertices, triangles, cooked);
  if (!s.ok()) return s;
  return finish(TriangleMeshGeometry<double>(cooked), Transform<double>(), out);
}

Status softMesh(const aiMesh* mesh, ConvertedShape& out) {
  if (mesh == nullptr) return Status(StatusCode::InvalidArgument, "the soft mesh shape has no mesh");
  std::vector<Vec> vertices;
  std::vector<TriangleIndices> triangles;
  for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
    const aiVector3D& p = mesh->mVertices[v];
    vertices.emplace_back(p.x, p.y, p.z);
  }
  for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
    const aiFace& face = mesh->mFaces[f];
    if (face.mNumIndices == 3) triangles.push_back({face.mIndices[0], face.mIndices[1], face.mIndices[2]});
  }
  std::shared_ptr<const TriangleMesh<double>> cooked;
  const Status s = cookTriangleMesh(vertices, triangles, cooked);
  if (!s.ok()) return s;
  return finish(TriangleMeshGeometry<double>(cooked), Transform<double>(), out);
}

// DART's heightmap: width samples along x, depth samples along -y, centred on the origin in x and y; heights are z.
// gq's heightfield: rows along local X, columns along local Z, heights along Y. gq's (X, Y, Z) map to DART's
// (x, z, -y), and gq's row r is DART's column, gq's column c DART's row.
template <class S> Status heightmap(const dd::HeightmapShape<S>& hm, ConvertedShape& out) {
  const auto& h = hm.getHeightField();
  const auto rows = static_cast<std::uint32_t>(h.cols());     // DART's width (x)
  const auto columns = static_cast<std::uint32_t>(h.rows());  // DART's depth (-y)
  if (rows < 2 || columns < 2) return Status(StatusCode::InvalidArgument, "the heightmap has fewer than 2x2 samples");
  const auto& scale = hm.getScale();
  if (!(scale.array() > S(0)).all()) {
    return Status(StatusCode::InvalidArgument, "the heightmap's scale is not positive");
  }
  HeightFieldDesc<double> desc;
  desc.rows = rows;
  desc.columns = columns;
  desc.heights.resize(std::size_t(rows) * columns);
  for (std::uint32_t r = 0; r < rows; ++r) {
    for (std::uint32_t c = 0; c < columns; ++c) desc.heights[std::size_t(r) * columns + c] = double(h(c, r));
  }
  std::shared_ptr<const HeightField<double>> cooked;
  const Status s = cookHeightField(desc, cooked);
  if (!s.ok()) return s;
  Mat3<double> rot;
  rot << 1, 0, 0,  //
      0, 0, -1,    //
      0, 1, 0;
  const Vec corner(-0.5 * (rows - 1) * double(scale.x()), 0.5 * (columns - 1) * double(scale.y()), 0.0);
  return finish(HeightFieldGeometry<double>(cooked, double(scale.z()), double(scale.x()), double(scale.y())),
                Transform<double>(corner, Quat<double>(rot)), out);
}

// The convex hull of spheres, as the hull of points on each sphere: 20 directions per sphere (a dodecahedron's
// vertices) and the 6 axis directions, so the hull lies inside the exact one and within 0.21 * radius of it.
Status multiSphereHull(const dd::MultiSphereConvexHullShape& ms, ConvertedShape& out) {
  static const std::vector<Vec> directions = [] {
    std::vector<Vec> d;
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    for (int sx : {-1, 1})
      for (int sy : {-1, 1})
        for (int sz : {-1, 1}) d.push_back(Vec(sx, sy, sz).normalized());
    for (int a : {-1, 1})
      for (int b : {-1, 1}) {
        d.push_back(Vec(0, a / phi, b * phi).normalized());
        d.push_back(Vec(a / phi, b * phi, 0).normalized());
        d.push_back(Vec(a * phi, 0, b / phi).normalized());
      }
    for (int i = 0; i < 3; ++i) {
      d.push_back(Vec::Unit(i));
      d.push_back(-Vec::Unit(i));
    }
    return d;
  }();
  std::vector<Vec> points;
  for (const auto& sphere : ms.getSpheres()) {
    for (const Vec& d : directions) points.push_back(sphere.second + sphere.first * d);
  }
  std::shared_ptr<const ConvexMesh<double>> hull;
  const Status s = cookConvexMesh(points, hull);
  if (!s.ok()) return s;
  return finish(ConvexMeshGeometry<double>(hull), Transform<double>(), out);
}

Status pyramid(const dd::PyramidShape& p, ConvertedShape& out) {
  const double w = 0.5 * p.getBaseWidth(), d = 0.5 * p.getBaseDepth(), h = 0.5 * p.getHeight();
  const std::vector<Vec> points = {Vec(-w, -d, -h), Vec(w, -d, -h), Vec(w, d, -h), Vec(-w, d, -h), Vec(0, 0, h)};
  std::shared_ptr<const ConvexMesh<double>> hull;
  const Status s = cookConvexMesh(points, hull);
  if (!s.ok()) return s;
  return finish(ConvexMeshGeometry<double>(hull), Transform<double>(), out);
}

Status plane(const dd::PlaneShape& p, ConvertedShape& out) {
  const Vec n = p.getNormal();
  const double len = n.norm();
  if (!(len > 0.0) || !std::isfinite(len) || !std::isfinite(p.getOffset())) {
    return Status(StatusCode::InvalidArgument, "the plane's normal is zero or not finite");
  }
  const Vec unit = n / len;
  const Quat<double> q = Quat<double>::FromTwoVectors(Vec::UnitX(), unit);
  return finish(PlaneGeometry<double>(), Transform<double>(unit * (p.getOffset() / len), q.normalized()), out);
}

}  // namespace

Status convertShape(const dd::Shape& shape, ConvertedShape& out) {
  const std::string& type = shape.getType();
  if (type == dd::SphereShape::getStaticType()) {
    return finish(SphereGeometry<double>(static_cast<const dd::SphereShape&>(shape).getRadius()), Transform<double>(),
                  out);
  }
  if (type == dd::BoxShape::getStaticType()) {
    return finish(BoxGeometry<double>(0.5 * static_cast<const dd::BoxShape&>(shape).getSize()), Transform<double>(),
                  out);
  }
  if (type == dd::CapsuleShape::getStaticType()) {
    const auto& c = static_cast<const dd::CapsuleShape&>(shape);
    return finish(CapsuleGeometry<double>(c.getRadius(), 0.5 * c.getHeight()), xToZ(), out);
  }
  if (type == dd::CylinderShape::getStaticType()) {
    const auto& c = static_cast<const dd::CylinderShape&>(shape);
    CustomGeometry<double> g;
    const Status s = makeCylinder(c.getRadius(), 0.5 * c.getHeight(), g);
    return s.ok() ? finish(g, xToZ(), out) : s;
  }
  if (type == dd::ConeShape::getStaticType()) {
    const auto& c = static_cast<const dd::ConeShape&>(shape);
    CustomGeometry<double> g;
    const Status s = makeCone(c.getRadius(), 0.5 * c.getHeight(), g);
    return s.ok() ? finish(g, xToZ(), out) : s;
  }
  if (type == dd::EllipsoidShape::getStaticType()) {
    const auto& e = static_cast<const dd::EllipsoidShape&>(shape);
    const Vec radii = e.getRadii();
    if (e.isSphere()) return finish(SphereGeometry<double>(radii.x()), Transform<double>(), out);
    CustomGeometry<double> g;
    const Status s = makeEllipsoid(radii, g);
    return s.ok() ? finish(g, Transform<double>(), out) : s;
  }
  if (type == dd::PlaneShape::getStaticType()) return plane(static_cast<const dd::PlaneShape&>(shape), out);
  if (type == dd::MeshShape::getStaticType()) {
    const auto& m = static_cast<const dd::MeshShape&>(shape);
    return meshFromScene(m.getMesh(), m.getScale(), out);
  }
  if (type == dd::SoftMeshShape::getStaticType()) {
    return softMesh(static_cast<const dd::SoftMeshShape&>(shape).getAssimpMesh(), out);
  }
  // The heightmap's type string names its scalar type.
  if (type == dd::HeightmapShape<float>::getStaticType()) {
    return heightmap(static_cast<const dd::HeightmapShape<float>&>(shape), out);
  }
  if (type == dd::HeightmapShape<double>::getStaticType()) {
    return heightmap(static_cast<const dd::HeightmapShape<double>&>(shape), out);
  }
  if (type == dd::MultiSphereConvexHullShape::getStaticType()) {
    return multiSphereHull(static_cast<const dd::MultiSphereConvexHullShape&>(shape), out);
  }
  if (type == dd::PyramidShape::getStaticType()) return pyramid(static_cast<const dd::PyramidShape&>(shape), out);
  return Status(StatusCode::Unsupported, "a DART shape type gq does not model (line segments, point clouds, voxels)");
}

}  // namespace dart
}  // namespace gq
