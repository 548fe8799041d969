#pragma once
// Convention conversions shared by the native backends (fcl, libccd, bullet, embree). gq's conventions: capsule,
// cylinder and cone along local X with half heights; plane x = 0 with normal +X (solid x <= 0); mesh scale
// x' = R diag(s) R^T x; penetration direction moves geom0 out; distance normal points from geom0 to geom1.
#include <cstdint>
#include <string>
#include <vector>

#include "case.h"
#include "result.h"

namespace gq::cases::native {

// Rotation taking a backend's Z axis onto gq's X axis (FCL capsules, cylinders and cones lie along Z):
// a rotation of +90 degrees about Y maps (0,0,1) to (1,0,0).
Quatd zAxisToX();

// The mesh-scale matrix R diag(s) R^T of a convex or mesh description.
Mat3<double> scaleMatrix(const ScaleDesc& scale);
// The description's points with its scale applied.
std::vector<Vec3d> scaledPoints(const ShapeDesc& desc);
// A cache key for cooked native data: the cooked data plus the scale applied to it.
std::string scaledKey(const ShapeDesc& desc);

// A convex hull as vertices plus outward, counter-clockwise polygons, cooked with gq's hull (qhull) so every
// backend sees the same polytope. False with `error` when the points are degenerate.
struct HullPolygons {
  std::vector<Vec3d> vertices;
  std::vector<std::vector<std::uint32_t>> polygons;
};
bool cookHullPolygons(const std::vector<Vec3d>& points, HullPolygons& out, std::string& error);

// Mesh triangles with the scale applied; a mirroring scale reverses the winding so normals stay outward.
std::vector<std::array<std::uint32_t, 3>> scaledTriangles(const ShapeDesc& desc);

// The unit vector of v, or zero when v is (numerically) zero.
Vec3d unitOrZero(const Vec3d& v);

// "unsupported: <backend> has no <query> for <shape>".
Result unsupportedQuery(const char* backend, QueryKind query, const char* what);

}  // namespace gq::cases::native
