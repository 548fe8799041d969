// Triangle mesh cooking: validation, removal of degenerate triangles, 8-wide BVH build (bvh/build.cpp) with triangles
// reordered into leaf order, and the hull vertex list used for exact world bounds.
#include <libqhull_r/qhull_ra.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <type_traits>

#include "bvh/build.h"
#include "common/validate.h"
#include "gq/cooking.h"
#include "gq/tolerances.h"

namespace gq {
namespace {

template <class T> Status validateMeshInput(const std::vector<Vec3<T>>& vertices,
                                            const std::vector<TriangleIndices>& triangles) {
  if (triangles.empty()) return Status::degenerate("triangle mesh has no triangles");
  if (vertices.size() >= std::size_t(0xffffffffu)) return Status::invalid("triangle mesh has too many vertices");
  if (triangles.size() > std::size_t(MeshBvhNode::kLeafFirstMask))
    return Status::invalid("triangle mesh has more than 2^28 triangles");
  for (std::size_t i = 0; i < vertices.size(); ++i)
    if (!isFinite(vertices[i])) return Status::owned(StatusCode::InvalidArgument, "vertex " + std::to_string(i) + " is not finite");
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      if (triangles[t][k] >= vertices.size())
        return Status::owned(StatusCode::InvalidArgument, "triangle " + std::to_string(t) + " has vertex index " +
                               std::to_string(triangles[t][k]) + " out of range (" + std::to_string(vertices.size()) +
                               " vertices)");
  return {};
}

// Zero-area or collinear: doubled area below kDegenerateTriangleArea * (longest edge)^2 (computed in double).
template <class T> bool isDegenerate(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  const Vec3<double> e0 = (b - a).template cast<double>(), e1 = (c - a).template cast<double>(),
                     e2 = (c - b).template cast<double>();
  const double longestSq = std::max({e0.squaredNorm(), e1.squaredNorm(), e2.squaredNorm()});
  const double doubledArea = e0.cross(e1).norm();
  return !(doubledArea > tol::kDegenerateTriangleArea * longestSq);
}

// Indices of the used vertices that can be extreme in some direction: qhull's hull vertices plus the points it
// found coplanar with a facet (within its round-off), so that no extreme point is lost. Flat or tiny meshes, where
// qhull fails, keep every used vertex.
template <class T> std::vector<std::uint32_t> hullVertexIndices(const std::vector<Vec3<T>>& vertices,
                                                                const std::vector<std::uint32_t>& used) {
  std::vector<double> coords;
  coords.reserve(used.size() * 3);
  for (std::uint32_t i : used)
    for (int k = 0; k < 3; ++k) coords.push_back(double(vertices[i][k]));
  if (used.size() < 5) return used;
  char* buffer = nullptr;
  std::size_t size = 0;
  FILE* sink = open_memstream(&buffer, &size);  // qhull's messages must not reach the user's streams
  qhT qhData;
  qhT* qh = &qhData;
  qh_zero(qh, sink ? sink : stderr);
  char command[] = "qhull Qc";
  const int exitCode = qh_new_qhull(qh, 3, int(used.size()), coords.data(), False, command, nullptr,
                                    sink ? sink : stderr);
  std::vector<std::uint32_t> out;
  if (exitCode == 0) {
    std::vector<char> keep(used.size(), 0);
    vertexT* vertex;
    FORALLvertices keep[qh_pointid(qh, vertex->point)] = 1;
    facetT* facet;
    FORALLfacets {
      if (!facet->coplanarset) continue;
      pointT *point, **pointp;
      FOREACHpoint_(facet->coplanarset) keep[qh_pointid(qh, point)] = 1;
    }
    for (std::size_t i = 0; i < used.size(); ++i)
      if (keep[i]) out.push_back(used[i]);
  } else {
    out = used;
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong = 0, totlong = 0;
  qh_memfreeshort(qh, &curlong, &totlong);
  if (sink) std::fclose(sink);
  std::free(buffer);
  return out;
}

// The cooked triangles' vertex and index rows, leaf by leaf (TriangleMesh::leafVertices, leafLane), from the tree's
// leaves (each cooked triangle is in exactly one).
template <class T> void storeLeafVertices(const MeshBvh& bvh, TriangleMesh<T>& mesh) {
  const std::size_t n = mesh.triangles.size();
  mesh.leafVertices.assign(10 * n + 3, T(0));
  mesh.leafLane.assign(n, 0);
  auto store = [&](std::uint32_t ref) {
    if (!MeshBvhNode::isLeaf(ref)) return;
    const std::uint32_t first = MeshBvhNode::leafFirst(ref), count = MeshBvhNode::leafCount(ref);
    T* rows = mesh.leafValues(first);
    for (std::uint32_t lane = 0; lane < count; ++lane) {
      mesh.leafLane[first + lane] = std::uint8_t(lane | count << 2);
      for (std::uint32_t k = 0; k < 3; ++k)
        for (std::uint32_t a = 0; a < 3; ++a)
          rows[(3 * k + a) * count + lane] = mesh.vertices[mesh.triangles[first + lane][k]][a];
      rows[9 * count + lane] = TriangleMesh<T>::indexValue(mesh.inputIndex[first + lane]);
    }
  };
  store(bvh.rootChild);
  for (const MeshBvhNode& node : bvh.nodes)
    for (std::uint32_t ref : node.child) store(ref);
}

}  // namespace

template <class T>
Status cookTriangleMesh(const std::vector<Vec3<T>>& vertices, const std::vector<TriangleIndices>& triangles,
                        std::shared_ptr<const TriangleMesh<T>>& out, MeshCookReport* report) {
  return detail::guarded([&]() -> Status {
    if (Status s = validateMeshInput(vertices, triangles); !s.ok()) return s;
    // Keep the non-degenerate triangles and their float bounds (rounded outward: conservative for double).
    std::vector<std::uint32_t> kept;
    std::vector<Bounds3<float>> primBounds;
    kept.reserve(triangles.size());
    primBounds.reserve(triangles.size());
    for (std::uint32_t t = 0; t < triangles.size(); ++t) {
      const Vec3<T>& a = vertices[triangles[t][0]];
      const Vec3<T>& b = vertices[triangles[t][1]];
      const Vec3<T>& c = vertices[triangles[t][2]];
      if (isDegenerate(a, b, c)) continue;
      kept.push_back(t);
      primBounds.push_back(detail::roundOutward<T>(a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)));
    }
    if (kept.empty())
      return Status::owned(StatusCode::DegenerateMesh, "all " + std::to_string(triangles.size()) + " triangles are degenerate (zero area)");

    auto mesh = std::make_shared<TriangleMesh<T>>();
    mesh->vertices = vertices;
    std::vector<std::uint32_t> order;
    auto accel = std::make_shared<detail::MeshAccel>();
    accel->bvh = detail::buildBvh8(primBounds, order);
    mesh->triangles.resize(kept.size());
    mesh->inputIndex.resize(kept.size());
    mesh->cookedIndex.assign(triangles.size(), kRemovedTriangle);
    std::vector<char> usedFlag(vertices.size(), 0);
    for (std::uint32_t c = 0; c < order.size(); ++c) {
      const std::uint32_t input = kept[order[c]];
      mesh->triangles[c] = triangles[input];
      mesh->inputIndex[c] = input;
      mesh->cookedIndex[input] = c;
      for (std::uint32_t v : triangles[input]) usedFlag[v] = 1;
    }
    storeLeafVertices(accel->bvh, *mesh);
    mesh->bvhBytes = accel->bvh.bytes() + mesh->leafLane.size();
    mesh->accel = std::move(accel);
    std::vector<std::uint32_t> used;
    for (std::uint32_t v = 0; v < vertices.size(); ++v)
      if (usedFlag[v]) {
        used.push_back(v);
        mesh->localBounds.include(vertices[v]);
      }
    mesh->hullVertices = hullVertexIndices(vertices, used);

    if (report) {
      report->inputTriangles = std::uint32_t(triangles.size());
      report->removedDegenerate = std::uint32_t(triangles.size() - kept.size());
      report->cookedTriangles = std::uint32_t(kept.size());
      report->bvhBytes = mesh->bvhBytes;
    }
    out = std::move(mesh);
    return Status();
  });
}

template Status cookTriangleMesh<float>(const std::vector<Vec3<float>>&, const std::vector<TriangleIndices>&,
                                        std::shared_ptr<const TriangleMesh<float>>&, MeshCookReport*);
template Status cookTriangleMesh<double>(const std::vector<Vec3<double>>&, const std::vector<TriangleIndices>&,
                                         std::shared_ptr<const TriangleMesh<double>>&, MeshCookReport*);

}  // namespace gq
