#pragma once
// Fitting internals, in double whatever the scalar of the mesh: the solids a fit is made of, their signed distance,
// surface patches for the bound, and the fitters.
#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "gq/cooking.h"
#include "gq/fit.h"
#include "gq/geometry.h"
#include "gq/transform.h"

namespace gq::fit {

using Vec3d = Vec3<double>;
using Mat3d = Mat3<double>;

struct Face {
  Vec3d normal;  // outward unit
  double d = 0;  // inside: normal . x + d <= 0
  std::vector<std::uint32_t> vertices;  // counter-clockwise seen from outside
};

// A convex solid in the mesh frame. Capsule and cylinder axes are rotation.col(0); the box's axes are its columns.
struct Solid {
  enum class Kind : std::uint8_t { Sphere, Capsule, Box, Cylinder, Polytope };
  Kind kind = Kind::Sphere;
  Vec3d centre = Vec3d::Zero();
  Mat3d rotation = Mat3d::Identity();
  double radius = 0, halfHeight = 0;
  Vec3d halfExtents = Vec3d::Zero();
  std::vector<Vec3d> vertices;  // polytope
  std::vector<Face> faces;      // polytope
  std::vector<double> planes;   // polytope: each face's normal x, y, z and d, packed for the signed distance's scans
};

// Signed distance to the solid's surface (negative inside), exact; `gradient` gets a unit subgradient of it.
double signedDistance(const Solid& s, const Vec3d& p, Vec3d& gradient);
// Fills Solid::planes from the faces (polytopeOf does; call it after changing the faces).
void packPlanes(Solid& s);
// The solid's volume (closed forms; a polytope's from its faces about its centre).
double volumeOf(const Solid& s);

// The mesh in double, with its surface cooked for point distances.
struct Surface {
  std::vector<Vec3d> vertices;
  std::vector<TriangleIndices> triangles;  // triangles of positive area only (the cooked mesh's order)
  // Per triangle, a triangle across its edge (i, i + 1), or kNoNeighbour on a border.
  std::vector<std::array<std::uint32_t, 3>> neighbours;
  static constexpr std::uint32_t kNoNeighbour = 0xffffffffu;
  std::shared_ptr<const TriangleMesh<double>> cooked;
  double size = 0;  // bounding-box diagonal
  double distance(const Vec3d& p) const;
  // Same, and the (input) index of the nearest triangle.
  double distance(const Vec3d& p, std::uint32_t& triangle) const;
};

// Builds the surface; fails as cookTriangleMesh does.
Status makeSurface(const std::vector<Vec3d>& vertices, const std::vector<TriangleIndices>& triangles, Surface& out);

struct Bound {
  double upper = 0;  // certified upper bound
  double lower = 0;  // a distance actually attained (the largest seen)
};

// Two-sided Hausdorff distance between the surface and the boundary of the union of the parts, from above.
// Refinement stops where a piece is proven at most max(target, 1.02 * lower) or the patch budget is spent.
Bound certifiedBound(const Surface& surface, const std::vector<Solid>& parts, double target, std::uint32_t maxPatches);

// Conversions between solids and gq geometries (the bound is computed from the geometry handed out).
template <class T> Status toSolid(const Geometry<T>& g, const Transform<T>& pose, Solid& out);
template <class T> Status toGeometry(const Solid& s, std::pair<Geometry<T>, Transform<T>>& out);
Solid polytopeOf(const ConvexMesh<double>& hull);
template <class T> Solid polytopeOf(const ConvexMesh<T>& hull, const Transform<T>& pose);

// Smallest enclosing ball of points in 2 or 3 dimensions (Welzl's move-to-front algorithm, Gaertner's form);
// the radius is the largest distance of a point from the centre found, so every point is inside.
void enclosingCircle(const std::vector<Eigen::Vector2d>& pts, Eigen::Vector2d& centre, double& radius);
void enclosingSphere(const std::vector<Vec3d>& pts, Vec3d& centre, double& radius);

// Principal axes (columns by decreasing variance, a proper rotation) of points.
Mat3d principalAxes(const std::vector<Vec3d>& pts);

// Fitters, each enclosing `hull` (the hull vertices of the mesh). `axes` are candidate frames for the
// axis-aligned fits, the minimum-volume box's frame first.
Solid fitSphere(const std::vector<Vec3d>& hull);
Solid fitCapsule(const std::vector<Vec3d>& hull, const std::vector<Mat3d>& axes);
Solid fitCylinder(const std::vector<Vec3d>& hull, const std::vector<Mat3d>& axes);
Solid fitBox(const ConvexMesh<double>& hull, std::vector<Mat3d>& axes);
// Shrinks a containing solid for a close fit: a radius or half extents reduced by `by` (kept positive).
Solid shrunk(const Solid& s, double by);

// A hull of few vertices: farthest-point insertion among the hull's vertices until every vertex is within `slack`
// of it; with `contain`, every face plane is pushed out past the farthest vertex. Empty solid kind Polytope with no
// faces on failure.
Status simplifiedHull(const ConvexMesh<double>& hull, double slack, bool contain, Solid& out);
// The convex hull of points (qhull), grown where facet merging left a point outside, so that it holds every point.
Status enclosingHull(const std::vector<Vec3d>& pts, std::shared_ptr<const ConvexMesh<double>>& out);
// The same as a solid, or a status.
Status hullOf(const std::vector<Vec3d>& pts, Solid& out);

// Approximate convex decomposition: hierarchical splitting by concavity (docs/fit.md).
Status decompose(const Surface& surface, double tolerance, std::uint32_t maxParts, std::uint32_t maxPatches,
                 std::vector<Solid>& parts);

}  // namespace gq::fit
