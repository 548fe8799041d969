#pragma once
// Internal pieces of the URDF plugin shared between its source files.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "gq/cooking.h"
#include "gq/urdf/robot.h"

namespace gq::urdf::internal {

// SplitMix64: a small, portable generator, so sampled configurations are identical on every platform.
inline std::uint64_t nextRandom(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}
// Uniform in [0, 1) with 53 random bits.
inline double uniform01(std::uint64_t& state) { return double(nextRandom(state) >> 11) * 0x1.0p-53; }

// ---- SRDF (srdf.cpp) ----------------------------------------------------------------------------------------
struct SrdfDisabledPair {
  std::string link1, link2, reason;
};
struct SrdfGroupState {
  std::string name;
  std::vector<std::pair<std::string, double>> values;  // joint name -> position
};
struct SrdfData {
  std::vector<SrdfDisabledPair> disabled;
  std::vector<SrdfGroupState> states;
};
// ParseError with tinyxml2's line and message for malformed XML, or for a <disable_collisions> missing a link.
Status parseSrdf(const std::string& xml, SrdfData& out);

// ---- Shapes (cylinder.cpp, mesh_shape.cpp) -------------------------------------------------------------------
template <class T> std::size_t hullBytes(const ConvexMesh<T>& hull);
// The exact custom Cylinder for a URDF cylinder along local Z; `fit` turns the custom shape's X axis onto Z.
template <class T> Status cylinderShape(T radius, T length, Shape<T>& shape, Transform<T>& fit);

// A mesh collision element's model: one shape per part (several for a convex decomposition), each placed in the
// mesh frame by fits[i]; geometry, representation, fitted, fitParts, errorBound, modelTriangles and bytes are set.
template <class T> struct MeshParts {
  std::vector<Shape<T>> shapes;
  std::vector<Transform<T>> fits;
};
template <class T>
Status meshShapes(const MeshData<T>& mesh, Representation rep, const LoadOptions& options, MeshParts<T>& out);

// ---- Point-cloud frames (mesh_shape.cpp) ---------------------------------------------------------------------
// Principal axes of the points as a proper rotation (columns by decreasing variance), and their mean.
template <class T> Mat3<double> principalAxes(const std::vector<Vec3<T>>& v, Vec3<double>& mean);
// Extents of the points in frame `r`: lo/hi of R^T v.
template <class T> void extentsIn(const std::vector<Vec3<T>>& v, const Mat3<double>& r, Vec3<double>& lo, Vec3<double>& hi);

// Capsule along r's first column enclosing every point (or every ball: point i with radius (*radii)[i]): radius =
// largest distance from the axis through the centre of the points' r-box cross-section plus the ball's radius (at
// least minRadius), segment ends as short as every ball allows.
struct EnclosingCapsule {
  Vec3<double> centre = Vec3<double>::Zero(), axis = Vec3<double>::UnitX();
  double halfHeight = 0, radius = 0;
};
template <class T>
EnclosingCapsule enclosingCapsule(const std::vector<Vec3<T>>& v, const Mat3<double>& r, double minRadius,
                                  const std::vector<double>* radii = nullptr);

// ---- Culling volumes (shape_bounds.cpp) ----------------------------------------------------------------------
// Bounding volumes of a shape in its own frame: an enclosing sphere, an enclosing box (the smaller of the local
// AABB and, for hulls and meshes, the box along the vertices' principal axes) and, where one is known, an enclosing
// capsule (capsules and cylinders themselves; hulls and meshes along their principal axis; boxes along the longest).
template <class T> struct CullVolume {
  Vec3<T> sphereCentre = Vec3<T>::Zero();
  T radius = T(0);
  Vec3<T> boxCentre = Vec3<T>::Zero();
  Mat3<T> boxAxes = Mat3<T>::Identity();  // columns: box axes in the shape frame
  Vec3<T> halfExtents = Vec3<T>::Zero();
  bool hasCapsule = false;  // an enclosing capsule tighter than the sphere: segment start + span, radius
  Vec3<T> capsuleStart = Vec3<T>::Zero(), capsuleSpan = Vec3<T>::Zero();
  T capsuleRadius = T(0);
};
template <class T> Status shapeCullVolume(const Geometry<T>& g, CullVolume<T>& out);

// ---- Configurations (kinematics.cpp) ------------------------------------------------------------------------
// Joint limits hold with a relative slack of a few ulps of the limit's magnitude (values read back from text or
// computed in float land exactly on a limit).
template <class T> T limitSlack(const Joint<T>& j) {
  return T(8) * std::numeric_limits<T>::epsilon() * std::max({T(1), std::abs(j.lower), std::abs(j.upper)});
}
// Size, finiteness and limits of a configuration: InvalidArgument naming the joint on failure.
template <class T> Status checkConfiguration(const RobotModel<T>& model, const std::vector<T>& q);

// ---- Model semantics (allowed_collisions.cpp) ---------------------------------------------------------------
// Fills model.allowed/allowedReason (adjacent links across fixed joints and shapeless links, same link, SRDF)
// and model.home. Unknown link names in the SRDF are listed in `warnings`.
template <class T> void computeAllowedCollisions(RobotModel<T>& model, const SrdfData& srdf, std::string& warnings);
template <class T> void chooseHomeConfiguration(RobotModel<T>& model, const SrdfData& srdf);

}  // namespace gq::urdf::internal
