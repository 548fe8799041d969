#pragma once
// The answer of one case, in double whatever precision the query ran in. Every backend fills these; one writer
// (result_writer.h) turns them into the output line, so all backends print identically.
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "case.h"

namespace gq::cases {

inline constexpr std::uint32_t kNoFace = 0xffffffffu;

struct RayHitOut {
  double distance = 0;
  std::optional<Vec3d> position, normal;     // present when the backend computed them
  std::uint32_t faceIndex = kNoFace;
  std::optional<std::array<double, 2>> uv;
};
struct RaycastOut { std::vector<RayHitOut> hits; };
struct OverlapOut { bool overlap = false; };
struct PenetrationOut {
  bool penetrating = false;
  Vec3d direction = Vec3d::Zero();
  double depth = 0;
};
struct DistanceOut {
  double distance = 0;
  Vec3d point0 = Vec3d::Zero(), point1 = Vec3d::Zero(), normal = Vec3d::Zero();
};
struct PointDistanceOut {
  double distance = 0;
  Vec3d closestPoint = Vec3d::Zero();
  std::uint32_t closestIndex = kNoFace;
};
struct SweepOut {
  bool hit = false;
  double distance = 0;
  std::optional<Vec3d> position, normal;
  std::uint32_t faceIndex = kNoFace;
  bool initialOverlap = false;
};
struct BoundsOut { Vec3d min = Vec3d::Zero(), max = Vec3d::Zero(); };

using ResultFields = std::variant<std::monostate, RaycastOut, OverlapOut, PenetrationOut, DistanceOut,
                                  PointDistanceOut, SweepOut, BoundsOut>;

struct Result {
  bool ok = false;
  std::string error;  // when !ok: "line N: field 'x': ...", "unsupported: ...", or a backend status message
  double ns = 0;      // median time of one query over the repeats
  ResultFields fields;

  static Result failure(std::string message, double ns = 0) {
    Result r;
    r.error = std::move(message);
    r.ns = ns;
    return r;
  }
};

}  // namespace gq::cases
