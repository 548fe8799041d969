#pragma once
// Independent exact referee for the FCL comparison: separating-axis test in long double between two convex
// polytopes (hulls, boxes or single triangles) placed in the world. Axes: face normals of both and all cross products of edge
// directions; the largest gap over these axes is > 0 exactly when the polytopes are disjoint, and when they overlap
// its magnitude is the exact penetration depth (minimum translational distance) of the two polytopes.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "gq/cooking.h"
#include "gq/urdf/robot.h"

namespace gq::urdf::test {

using LD = long double;
using Vec3L = Eigen::Matrix<LD, 3, 1>;

struct Polytope {
  std::vector<Vec3L> vertices;
  std::vector<Vec3L> faceNormals;
  std::vector<Vec3L> edgeDirections;
};

// `pose` maps the shape frame to the world. Returns false for shapes that are not polytopes.
inline bool worldPolytope(const Shape<double>& shape, const Transform<double>& pose, Polytope& out) {
  const Mat3<LD> r = pose.q.normalized().toRotationMatrix().cast<LD>();
  const Vec3L t = pose.p.cast<LD>();
  out = Polytope();
  if (const auto* box = shape.geometry.getIf<BoxGeometry<double>>()) {
    const Vec3L he = box->halfExtents.cast<LD>();
    for (int i = 0; i < 8; ++i)
      out.vertices.push_back(r * Vec3L((i & 1) ? he.x() : -he.x(), (i & 2) ? he.y() : -he.y(), (i & 4) ? he.z() : -he.z()) + t);
    for (int a = 0; a < 3; ++a) {
      out.faceNormals.push_back(r.col(a));
      out.edgeDirections.push_back(r.col(a));
    }
    return true;
  }
  const auto* convex = shape.geometry.getIf<ConvexMeshGeometry<double>>();
  if (!convex) return false;
  const ConvexMesh<double>& h = *convex->mesh;
  for (const auto& v : h.vertices) out.vertices.push_back(r * v.cast<LD>() + t);
  for (const auto& poly : h.polygons) {
    out.faceNormals.push_back(r * poly.normal.cast<LD>());
    for (std::uint32_t k = 0; k < poly.indexCount; ++k) {
      const std::uint32_t i = h.polygonVertices[poly.indexBase + k];
      const std::uint32_t j = h.polygonVertices[poly.indexBase + (k + 1) % poly.indexCount];
      if (i < j) out.edgeDirections.push_back(out.vertices[j] - out.vertices[i]);  // each edge once
    }
  }
  return true;
}

// One triangle as a flat polytope. Besides its normal, the in-plane edge normals n x e are face axes too: they
// separate coplanar triangles, which the normal and the edge cross products cannot.
inline Polytope trianglePolytope(const Vec3L& a, const Vec3L& b, const Vec3L& c) {
  Polytope out;
  out.vertices = {a, b, c};
  const Vec3L n = (b - a).cross(c - a);
  out.faceNormals.push_back(n);
  for (const Vec3L& e : {Vec3L(b - a), Vec3L(c - b), Vec3L(a - c)}) {
    out.edgeDirections.push_back(e);
    out.faceNormals.push_back(n.cross(e));
  }
  return out;
}

inline void project(const Polytope& p, const Vec3L& axis, LD& lo, LD& hi) {
  lo = hi = axis.dot(p.vertices[0]);
  for (const auto& v : p.vertices) {
    const LD d = axis.dot(v);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
}

// The gap max(loB - hiA, loA - hiB) along `axis`, or a value <= `floor` once the vertices projected so far show
// that it cannot exceed `floor`: adding vertices only widens [lo, hi], so the gap only falls (the result of satGap
// is the same; hulls of hundreds of vertices drop most of their edge-pair axes after a few vertices).
inline LD gapAbove(const Polytope& a, const Polytope& b, const Vec3L& axis, LD floor) {
  LD loA = axis.dot(a.vertices[0]), hiA = loA, loB = axis.dot(b.vertices[0]), hiB = loB;
  const std::size_t na = a.vertices.size(), nb = b.vertices.size();
  for (std::size_t k = 1; k < std::max(na, nb); ++k) {
    if (k < na) {
      const LD d = axis.dot(a.vertices[k]);
      loA = std::min(loA, d);
      hiA = std::max(hiA, d);
    }
    if (k < nb) {
      const LD d = axis.dot(b.vertices[k]);
      loB = std::min(loB, d);
      hiB = std::max(hiB, d);
    }
    if (std::max(loB - hiA, loA - hiB) <= floor) return floor;
  }
  return std::max(loB - hiA, loA - hiB);
}

// Largest separating gap over all SAT axes (> 0: disjoint; <= 0: overlapping by -gap).
inline LD satGap(const Polytope& a, const Polytope& b) {
  LD best = -std::numeric_limits<LD>::infinity();
  const auto test = [&](Vec3L axis) {
    const LD n = axis.norm();
    if (!(n > 1e-12L)) return;
    axis /= n;
    best = std::max(best, gapAbove(a, b, axis, best));
  };
  for (const auto& n : a.faceNormals) test(n);
  for (const auto& n : b.faceNormals) test(n);
  for (const auto& ea : a.edgeDirections)
    for (const auto& eb : b.edgeDirections) test(ea.normalized().cross(eb.normalized()));
  return best;
}

}  // namespace gq::urdf::test
