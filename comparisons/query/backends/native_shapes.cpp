#include "native_shapes.h"

#include <cmath>
#include <sstream>

#include "gq/cooking.h"

namespace gq::cases::native {

Quatd zAxisToX() { return Quatd(Eigen::AngleAxis<double>(0.5 * M_PI, Vec3d::UnitY())); }

Mat3<double> scaleMatrix(const ScaleDesc& scale) {
  const Mat3<double> r = scale.q.toRotationMatrix();
  return r * scale.s.asDiagonal() * r.transpose();
}

std::vector<Vec3d> scaledPoints(const ShapeDesc& desc) {
  const Mat3<double> m = scaleMatrix(desc.scale);
  std::vector<Vec3d> out;
  out.reserve(desc.points.size());
  for (const Vec3d& p : desc.points) out.push_back(m * p);
  return out;
}

std::string scaledKey(const ShapeDesc& desc) {
  std::ostringstream key;
  key.precision(17);
  key << desc.cookKey << '|' << desc.scale.s.transpose() << '|' << desc.scale.q.coeffs().transpose();
  return key.str();
}

bool cookHullPolygons(const std::vector<Vec3d>& points, HullPolygons& out, std::string& error) {
  std::shared_ptr<const ConvexMesh<double>> hull;
  if (Status s = cookConvexMesh<double>(points, hull); !s.ok()) {
    error = s.detailedMessage();
    return false;
  }
  out.vertices = hull->vertices;
  out.polygons.clear();
  for (const HullPolygon<double>& poly : hull->polygons)
    out.polygons.emplace_back(hull->polygonVertices.begin() + poly.indexBase,
                              hull->polygonVertices.begin() + poly.indexBase + poly.indexCount);
  return true;
}

std::vector<std::array<std::uint32_t, 3>> scaledTriangles(const ShapeDesc& desc) {
  std::vector<std::array<std::uint32_t, 3>> out = desc.triangles;
  if (desc.scale.s.prod() < 0)
    for (auto& t : out) std::swap(t[1], t[2]);
  return out;
}

Vec3d unitOrZero(const Vec3d& v) {
  const double n = v.norm();
  return n > 0 && std::isfinite(n) ? Vec3d(v / n) : Vec3d::Zero();
}

Result unsupportedQuery(const char* backend, QueryKind query, const char* what) {
  return Result::failure(std::string("unsupported: ") + backend + " has no " + toString(query) + " for " + what);
}

}  // namespace gq::cases::native
