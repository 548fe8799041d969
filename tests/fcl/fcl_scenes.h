#pragma once
// Test shapes as real ::fcl geometries, seeded random poses, and the shape list the equivalence tests loop over.
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <fcl/fcl.h>

namespace gq::fcltest {

enum class Kind { Sphere, Box, Capsule, Cylinder, Cone, Ellipsoid, Convex, TriangleP, Halfspace, Plane, Mesh };
const char* name(Kind k);
std::vector<Kind> allKinds();
bool isPlaneLike(Kind k);
// Every unordered pair of kinds, except pairs of two plane-like kinds (Halfspace, Plane).
std::vector<std::pair<Kind, Kind>> allPairs();
// Name generator of INSTANTIATE_TEST_SUITE_P over allPairs(): "Sphere_Box".
struct PairName {
  template <class ParamInfo> std::string operator()(const ParamInfo& info) const {
    return std::string(name(info.param.first)) + "_" + name(info.param.second);
  }
};

// A geometry with the data the exact references need (polytope vertices/faces, sizes).
struct TestShape {
  Kind kind;
  std::shared_ptr<::fcl::CollisionGeometryd> geometry;
  std::vector<::fcl::Vector3d> vertices;        // polytopes (box corners, hull, triangle, mesh vertices)
  std::vector<std::vector<int>> faces;          // polytope faces (CCW from outside); mesh triangles
  ::fcl::Vector3d size = ::fcl::Vector3d::Zero();  // sphere r; box sides; capsule/cylinder/cone (r, lz); radii
  ::fcl::Vector3d planeNormal = ::fcl::Vector3d::UnitZ();
  double planeOffset = 0;
};

TestShape makeShape(Kind k, std::mt19937& rng);

// The eight faces (CCW from outside) of an octahedron whose vertices are +x, -x, +y, -y, +z, -z points on the axes.
std::vector<std::vector<int>> octahedronFaces(const std::vector<::fcl::Vector3d>& v);
// FCL's Convex over these vertices and polygon faces.
std::shared_ptr<::fcl::Convexd> convexGeometry(const std::vector<::fcl::Vector3d>& vertices,
                                               const std::vector<std::vector<int>>& faces);

// A uniformly random rotation and a translation uniform in [-extent, extent]^3.
::fcl::Transform3d randomPose(std::mt19937& rng, double extent);

// A closed convex polytope: the hull of `count` points on an ellipsoid, as vertices + CCW faces (triangulated).
void randomHull(std::mt19937& rng, int count, std::vector<::fcl::Vector3d>& vertices, std::vector<std::vector<int>>& faces);

// Whether FCL 0.7 (Debian 0.7.0, libccd solver) can be asked this pair: it has a function for it and does not crash
// on it (libccd's MPR/GJK on a Plane or Halfspace: SIGSEGV in ccdMPRIntersect / __ccdSupport).
bool fclHasCollide(const TestShape& a, const TestShape& b);
bool fclHasDistance(const TestShape& a, const TestShape& b);

}  // namespace gq::fcltest
