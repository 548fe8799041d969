#pragma once
// The frames of a triangle-mesh instance: mesh space (cooked vertices) -> shape space (x_shape = S x_mesh with
// S = R diag(scale) R^T) -> world (pose). Shared by the mesh raycast, point distance, bounds and getTriangle.
#include "gq/cooking.h"
#include "gq/geometry.h"
#include "gq/mesh_query.h"
#include "gq/transform.h"

namespace gq::detail {

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

}  // namespace gq::detail
