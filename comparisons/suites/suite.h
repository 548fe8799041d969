#pragma once
// The exact-answer suites: case lines in the gq-query format (/work/shared/CASES.md) that carry the exact answer
// under "expect". Every answer is computed here (exact.h, long double), independently of gq and of every backend.
//
// "expect" holds: "group" (the hard-case family), "class" ("analytic" or "iterative": which tolerance applies),
// "scale" (the length that relative errors divide by: the largest shape size, pose or origin distance from the
// world origin), "margin" (how far the configuration is from flipping its boolean, in length units; a boolean is
// only judged when |margin| exceeds the tolerance times scale), and the answer fields of the query:
//   overlap: "overlap"; penetration: "penetrating", "depth"; distance: "distance" (signed);
//   raycast: "hit", "distance", and "spread" {"1e-09","1e-07","1e-04"}: how much the exact hit distance
//   moves (relative to scale) when the origin moves by that fraction of the scale. An answer is accepted within
//   tolerance + spread: the exact answer of inputs perturbed by the tolerance (grazing rays are ill-conditioned);
//   pointDistance: "distance".
#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "exact.h"

namespace gq::suites {

using V3d = Eigen::Vector3d;

enum class Kind { Sphere, Capsule, Box, Plane, Convex, Mesh, Cylinder };

struct Shape {
  Kind kind = Kind::Sphere;
  double radius = 0, halfHeight = 0;  // sphere, capsule, cylinder (axis = local X)
  V3d halfExtents = V3d::Zero();      // box
  std::vector<V3d> points;            // convex hull points, mesh vertices
  std::vector<std::array<std::uint32_t, 3>> triangles;  // mesh
  bool doubleSided = false;
};

struct Pose {
  V3d p = V3d::Zero();
  Eigen::Vector4d q = Eigen::Vector4d(0, 0, 0, 1);  // x, y, z, w as written; need not be unit
};

struct Placed {
  Shape shape;
  Pose pose;
};

// The case-format type name of a kind ("sphere", "capsule", ...).
const char* kindName(Kind k);
// Case-format JSON of a shape and a pose.
nlohmann::json toJson(const Shape& s);
nlohmann::json toJson(const Pose& p);

// Exact world-frame descriptions (the quaternion normalized in long double, as the runner normalizes it).
Q rotationOf(const Pose& p);
V3 toWorld(const Pose& p, const V3d& local);
Core coreOf(const Placed& s);          // sphere, capsule, box, convex
HalfSpace halfSpaceOf(const Placed& s);  // plane
TriangleSoup soupOf(const Placed& s);    // mesh
// Largest distance of the shape's surface from its own origin.
double sizeOf(const Shape& s);
bool isPolytopeOrRound(Kind k);  // has a Core

// Exact time of impact of `swept` moved along unit `dir` up to maxDist against `target` (sweep_suites.cpp).
struct SweepToi {
  bool hit = false;
  Ld distance = 0;  // the TOI when hit (0: initial overlap)
  Ld margin = 0;    // >= 0: how far the hit boolean is from flipping (length)
  Ld cosine = 1;    // |contact normal . dir| at the hit (1 for initial overlap)
};
SweepToi exactSweepToi(const Placed& swept, const Placed& target, const V3d& dir, double maxDist);

// Random shapes and poses.
class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
  int index(int n) { return std::uniform_int_distribution<int>(0, n - 1)(engine_); }
  V3d inBox(double h) { return V3d(uniform(-h, h), uniform(-h, h), uniform(-h, h)); }
  V3d unitVector();
  Eigen::Vector4d rotation();  // unit quaternion, uniform
  Shape shape(Kind k);         // well-proportioned, size about 0.3 .. 1.2
  // A target for ray and point suites: shape(k) (meshes: a fixed ellipsoid mesh) at a random pose near the origin.
  Placed placed(Kind k);
 private:
  std::mt19937_64 engine_;
};

// Unit quaternion (x, y, z, w) of a rotation by `angle` about unit `axis`.
Eigen::Vector4d axisAngle(const V3d& axis, double angle);
// q * r in (x, y, z, w) order.
Eigen::Vector4d compose(const Eigen::Vector4d& q, const Eigen::Vector4d& r);

// A closed, outward-facing ellipsoid mesh (subdivided octahedron) and a double-sided quad made of slivers.
Shape ellipsoidMesh(const V3d& radii, int subdivisions);
Shape sliverQuadMesh(double halfSize, int slivers, double sliverWidth);

// One suite per query family: "overlap", "penetration", "distance", "raycast", "pointDistance", "sweep".
struct Suite {
  std::string family;
  std::vector<nlohmann::json> cases;
};

struct SuiteOptions {
  std::uint64_t seed = 20240601;
  int randomPerPair = 6;   // well-conditioned random scenarios per shape pair
  int orientations = 1;    // random orientations per hard case
  int randomRays = 40;     // per target shape
  int randomPoints = 40;   // per target shape
  int randomSweeps = 4;    // per swept/target shape pair
};

// The embedded default suites are makeSuites(embeddedOptions()): small, generated in memory.
SuiteOptions embeddedOptions();
SuiteOptions fileOptions();
std::vector<Suite> makeSuites(const SuiteOptions& options);

// Each family's generator; every case is emitted in float and in double.
void addPairSuites(const SuiteOptions& options, std::vector<nlohmann::json>& overlap,
                   std::vector<nlohmann::json>& penetration, std::vector<nlohmann::json>& distance);
void addRaySuite(const SuiteOptions& options, std::vector<nlohmann::json>& out);
void addPointSuite(const SuiteOptions& options, std::vector<nlohmann::json>& out);
void addSweepSuite(const SuiteOptions& options, std::vector<nlohmann::json>& out);

// Appends `base` once per precision, with id "<id>/<precision>".
void emitBothPrecisions(nlohmann::json base, const std::string& id, std::vector<nlohmann::json>& out);

}  // namespace gq::suites
