// Names of the plugin's enums, for messages, the CLI and `info`.
#include <array>
#include <cmath>
#include <cstdlib>
#include <string>

#include "gq/urdf/robot.h"

namespace gq::urdf {
namespace {
constexpr std::array<const char*, 8> kRepresentationNames = {"mesh",    "hull",   "box",            "box-aabb",
                                                              "capsule", "sphere", "best-primitive", "fit"};
constexpr const char* kModes = "mesh, hull, box, box-aabb, capsule, sphere, best-primitive or fit:<tolerance in metres>";
}  // namespace

const char* toString(Representation r) { return kRepresentationNames[std::size_t(r)]; }

Status parseRepresentation(const std::string& name, Representation& out) {
  for (std::size_t i = 0; i < kRepresentationNames.size(); ++i)
    if (name == kRepresentationNames[i]) {
      out = Representation(i);
      return {};
    }
  return Status::owned(StatusCode::InvalidArgument, "unknown representation '" + name + "' (expected " + kModes + ")");
}

Status parseMode(const std::string& mode, LoadOptions& options) {
  const std::string prefix = "fit:";
  if (mode.compare(0, prefix.size(), prefix) != 0) {
    if (mode == "fit")
      return Status::owned(StatusCode::InvalidArgument, "mode 'fit' needs a tolerance in metres, e.g. fit:0.002");
    return parseRepresentation(mode, options.representation);
  }
  const std::string number = mode.substr(prefix.size());
  char* end = nullptr;
  const double tolerance = number.empty() ? 0.0 : std::strtod(number.c_str(), &end);
  if (number.empty() || *end != '\0' || !std::isfinite(tolerance) || !(tolerance > 0))
    return Status::owned(StatusCode::InvalidArgument,
                         "mode '" + mode + "': the fit tolerance must be a finite number of metres > 0 (e.g. fit:0.002)");
  options.representation = Representation::Fit;
  options.fitTolerance = tolerance;
  return {};
}

const char* toString(JointType t) {
  switch (t) {
    case JointType::Revolute: return "revolute";
    case JointType::Continuous: return "continuous";
    case JointType::Prismatic: return "prismatic";
    case JointType::Fixed: return "fixed";
  }
  return "?";
}

const char* toString(ShapeSource s) {
  switch (s) {
    case ShapeSource::Box: return "box";
    case ShapeSource::Sphere: return "sphere";
    case ShapeSource::Cylinder: return "cylinder";
    case ShapeSource::Mesh: return "mesh";
  }
  return "?";
}

}  // namespace gq::urdf
