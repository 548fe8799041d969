// Forward kinematics: pose(child) = pose(parent) * origin * motion(q), motion a rotation about the joint axis
// (revolute, continuous) or a translation along it (prismatic). Links are stored parents first, so one pass over
// the joints in order places every link.
#include <cmath>
#include <string>

#include "internal.h"

namespace gq::urdf {
namespace internal {

template <class T> Status checkConfiguration(const RobotModel<T>& model, const std::vector<T>& q) {
  if (q.size() != model.variables.size())
    return Status::owned(StatusCode::InvalidArgument, "configuration has " + std::to_string(q.size()) + " values, the robot has " +
                           std::to_string(model.variables.size()) + " joints");
  for (const auto& j : model.joints) {
    if (j.variable < 0) continue;
    const T v = q[std::size_t(j.variable)];
    if (!std::isfinite(v)) return Status::owned(StatusCode::InvalidArgument, "joint '" + j.name + "' value is not finite");
    if (j.type != JointType::Continuous && !(v >= j.lower - limitSlack(j) && v <= j.upper + limitSlack(j)))
      return Status::owned(StatusCode::InvalidArgument, "joint '" + j.name + "' value " + std::to_string(double(v)) + " is outside its limits [" +
                             std::to_string(double(j.lower)) + ", " + std::to_string(double(j.upper)) + "]");
  }
  return {};
}

template Status checkConfiguration<float>(const RobotModel<float>&, const std::vector<float>&);
template Status checkConfiguration<double>(const RobotModel<double>&, const std::vector<double>&);

}  // namespace internal

namespace {

// origin * motion(value): a rotation by `value` about the unit axis is the quaternion (cos v/2, sin v/2 axis), so
// only the rotation part changes; a prismatic joint moves along the axis expressed in the parent frame.
template <class T> Transform<T> jointTransform(const Joint<T>& j, T value) {
  switch (j.type) {
    case JointType::Revolute:
    case JointType::Continuous: {
      const T half = T(0.5) * value, c = std::cos(half), s = std::sin(half);
      const Quat<T> motion(c, s * j.axis.x(), s * j.axis.y(), s * j.axis.z());
      return Transform<T>(j.origin.p, j.origin.q * motion);
    }
    case JointType::Prismatic: return Transform<T>(j.origin.p + j.origin.q * (j.axis * value), j.origin.q);
    case JointType::Fixed: break;
  }
  return j.origin;
}

}  // namespace

template <class T>
Status forwardKinematics(const RobotModel<T>& model, const std::vector<T>& q, std::vector<Transform<T>>& linkPoses) {
  Status s = internal::checkConfiguration(model, q);
  if (!s.ok()) return s;
  linkPoses.resize(model.links.size());
  linkPoses[0] = Transform<T>();
  for (const auto& j : model.joints) {
    T value = T(0);
    if (j.variable >= 0) value = q[std::size_t(j.variable)];
    if (j.mimicJoint >= 0) value = j.multiplier * q[std::size_t(model.joints[std::size_t(j.mimicJoint)].variable)] + j.offset;
    linkPoses[j.childLink] = linkPoses[j.parentLink] * jointTransform(j, value);
  }
  return {};
}

template <class T> std::vector<T> randomConfiguration(const RobotModel<T>& model, std::uint64_t& rngState) {
  std::vector<T> q(model.variables.size(), T(0));
  for (const auto& j : model.joints)
    if (j.variable >= 0)
      q[std::size_t(j.variable)] =
          std::clamp(T(j.lower + (j.upper - j.lower) * T(internal::uniform01(rngState))), j.lower, j.upper);
  return q;
}

template Status forwardKinematics<float>(const RobotModel<float>&, const std::vector<float>&,
                                         std::vector<Transform<float>>&);
template Status forwardKinematics<double>(const RobotModel<double>&, const std::vector<double>&,
                                          std::vector<Transform<double>>&);
template std::vector<float> randomConfiguration<float>(const RobotModel<float>&, std::uint64_t&);
template std::vector<double> randomConfiguration<double>(const RobotModel<double>&, std::uint64_t&);

}  // namespace gq::urdf
