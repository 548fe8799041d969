// Names of the plugin's enums, for messages, the CLI and `info`.
#include <array>
#include <string>

#include "gq/urdf/robot.h"

namespace gq::urdf {
namespace {
constexpr std::array<const char*, 7> kRepresentationNames = {"mesh",    "hull",   "box", "box-aabb",
                                                              "capsule", "sphere", "best-primitive"};
}  // namespace

const char* toString(Representation r) { return kRepresentationNames[std::size_t(r)]; }

Status parseRepresentation(const std::string& name, Representation& out) {
  for (std::size_t i = 0; i < kRepresentationNames.size(); ++i)
    if (name == kRepresentationNames[i]) {
      out = Representation(i);
      return {};
    }
  return Status::owned(StatusCode::InvalidArgument, "unknown representation '" + name +
                         "' (expected mesh, hull, box, box-aabb, capsule, sphere or best-primitive)");
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
