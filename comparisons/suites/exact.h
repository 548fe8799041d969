#pragma once
// Exact answers in long double, independent of gq and of every native backend. A solid is a "rounded core":
// the convex hull of a few points inflated by a radius (sphere = point + r, capsule = segment + r, box and convex
// hull = points + 0). Distances come from brute force over all feature pairs of the cores; overlap and penetration
// depth from SAT over every face normal and edge-pair axis, which is exact for polytopes because the faces of the
// Minkowski difference are among those axes.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace gq::suites {

using Ld = long double;
using V3 = Eigen::Matrix<Ld, 3, 1>;
using Q = Eigen::Quaternion<Ld>;

struct Core {
  std::vector<V3> points;  // world frame
  Ld radius = 0;
};

// Plane in world frame: the solid is the half-space n·x <= n·origin.
struct HalfSpace {
  V3 normal = V3::UnitX();
  V3 origin = V3::Zero();
};

struct TriangleSoup {
  std::vector<V3> vertices;  // world frame
  std::vector<std::array<std::uint32_t, 3>> triangles;
  bool doubleSided = false;
};

// SAT candidate axes (unit) appended to `axes`: the normals of every point triple of `pts`, and the cross products of
// every edge (point pair) of `a` with every edge of `b`; near-parallel factors give no axis.
void addTriangleNormals(const std::vector<V3>& pts, std::vector<V3>& axes);
void addEdgePairAxes(const std::vector<V3>& a, const std::vector<V3>& b, std::vector<V3>& axes);

// Distance between two points sets' convex hulls by brute force over point/segment/triangle pairs.
Ld hullDistance(const std::vector<V3>& a, const std::vector<V3>& b);
// Signed distance of the two hulls: distance when apart, minus the penetration depth when they overlap.
Ld hullSignedDistance(const std::vector<V3>& a, const std::vector<V3>& b);
// Rounded cores: hullSignedDistance minus both radii (Minkowski sums add radii exactly).
Ld signedDistance(const Core& a, const Core& b);
// A rounded core against a half-space: lowest point's height minus the radius.
Ld signedDistance(const Core& a, const HalfSpace& plane);

Ld pointTriangleDistance(const V3& p, const V3& a, const V3& b, const V3& c);
Ld segmentSegmentDistance(const V3& p0, const V3& p1, const V3& q0, const V3& q1);

// Closest ray hit parameter t in [0, maxDist]; t = 0 when the origin is inside or on the solid. `dir` is unit.
std::optional<Ld> rayHit(const Core& core, const V3& origin, const V3& dir, Ld maxDist);
// Planes are single-sided for rays (spec): an origin behind the plane reports no hit.
std::optional<Ld> rayHit(const HalfSpace& plane, const V3& origin, const V3& dir, Ld maxDist);
// Brute force over all triangles; back faces are culled unless doubleSided.
std::optional<Ld> rayHit(const TriangleSoup& mesh, const V3& origin, const V3& dir, Ld maxDist);

// Unsigned distance from a point to the mesh surface (brute force over all triangles).
Ld pointMeshDistance(const V3& p, const TriangleSoup& mesh);

}  // namespace gq::suites
