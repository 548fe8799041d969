#pragma once
// One parsed line of a case file (see /work/shared/CASES.md), independent of any backend: every number is a
// double, every geometry a plain description. Backends build their own shapes from it.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "gq/math.h"

namespace gq::cases {

using Vec3d = Vec3<double>;
using Quatd = Quat<double>;

enum class Precision { Float, Double };

struct PoseDesc {
  Vec3d p = Vec3d::Zero();
  Quatd q = Quatd::Identity();  // normalized by the parser
};

// Non-uniform mesh scale {"s":[..],"q":[..]}.
struct ScaleDesc {
  Vec3d s = Vec3d::Ones();
  Quatd q = Quatd::Identity();  // normalized by the parser
};

enum class ShapeKind { Sphere, Capsule, Box, Plane, Convex, Mesh, HeightField, Cylinder, Cone };
const char* toString(ShapeKind kind);

struct ShapeDesc {
  ShapeKind kind = ShapeKind::Sphere;
  double radius = 0;       // sphere, capsule, cylinder, cone
  double halfHeight = 0;   // capsule, cylinder, cone (axis = local X)
  Vec3d halfExtents = Vec3d::Zero();  // box
  // Convex: hull points (from `points` or the vertices of `file`). Mesh: vertices + triangles.
  std::vector<Vec3d> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  ScaleDesc scale;
  bool doubleSided = false;  // mesh, heightfield
  // Heightfield.
  std::uint32_t rows = 0, columns = 0;
  std::vector<double> heights;
  std::vector<std::uint32_t> holes;
  double rowScale = 1, columnScale = 1, heightScale = 1;
  // Identifies the cooked data (hull points, mesh, heightfield samples) so each is cooked once per file.
  std::string cookKey;
};

enum class QueryKind { Raycast, Overlap, Penetration, Distance, PointDistance, Sweep, Bounds };
const char* toString(QueryKind kind);

// Hit flag names of the case format, in gq::HitFlag bit order.
inline constexpr std::array<const char*, 10> kHitFlagNames = {
    "position", "normal", "uv", "faceIndex", "meshMultiple", "meshBothSides", "anyHit", "mtd", "preciseSweep",
    "assumeNoInitialOverlap"};

struct RaycastCase {
  ShapeDesc geom;
  PoseDesc pose;
  Vec3d origin = Vec3d::Zero();
  Vec3d dir = Vec3d::UnitX();
  double maxDist = 0;
  std::uint16_t flags = 0;  // gq::HitFlag bits
  std::uint32_t maxHits = 1;
};

// overlap, penetration and distance.
struct PairCase {
  ShapeDesc geom0, geom1;
  PoseDesc pose0, pose1;
};

struct PointDistanceCase {
  ShapeDesc geom;
  PoseDesc pose;
  Vec3d point = Vec3d::Zero();
};

struct SweepCase {
  ShapeDesc geom0, geom1;
  PoseDesc pose0, pose1;
  Vec3d dir = Vec3d::UnitX();
  double maxDist = 0;
  std::uint16_t flags = 0;
  double inflation = 0;
};

struct BoundsCase {
  ShapeDesc geom;
  PoseDesc pose;
  double offset = 0;
  double inflation = 1.01;
};

struct Case {
  std::size_t line = 0;  // 1-based line number in the file
  nlohmann::json id;     // echoed unchanged
  Precision precision = Precision::Double;
  QueryKind query = QueryKind::Raycast;
  std::variant<RaycastCase, PairCase, PointDistanceCase, SweepCase, BoundsCase> input;
};

}  // namespace gq::cases
