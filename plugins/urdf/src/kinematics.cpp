// Forward kinematics: pose(child) = pose(parent) * origin * motion(q), motion a rotation about the joint axis
// (revolute, continuous) or a translation along it (prismatic). Links are stored parents first, so one pass over
// the joints in order places every link.
#include <cmath>
#include <string>

#include "internal.h"

namespace gq::urdf {
namespace {

// Joint limits are accepted with a relative slack of a few ulps of the limit's magnitude (values read back from
// text or computed in float land exactly on a limit).
template <class T> bool withinLimits(T value, const Joint<T>& j) {
  const T slack = T(8) * std::numeric_limits<T>::epsilon() * std::max({T(1), std::abs(j.lower), std::abs(j.upper)});
  return value >= j.lower - slack && value <= j.upper + slack;
}

template <class T> Status checkConfiguration(const RobotModel<T>& model, const std::vector<T>& q) {
  if (q.size() != model.variables.size())
    return Status::invalid("configuration has " + std::to_string(q.size()) + " values, the robot has " +
                           std::to_string(model.variables.size()) + " joints");
  for (const auto& j : model.joints) {
    if (j.variable < 0) continue;
    const T v = q[std::size_t(j.variable)];
    if (!std::isfinite(v)) return Status::invalid("joint '" + j.name + "' value is not finite");
    if (j.type != JointType::Continuous && !withinLimits(v, j))
      return Status::invalid("joint '" + j.name + "' value " + std::to_string(double(v)) + " is outside its limits [" +
                             std::to_string(double(j.lower)) + ", " + std::to_string(double(j.upper)) + "]");
  }
  return {};
}

template <class T> Transform<T> jointMotion(const Joint<T>& j, T value) {
  switch (j.type) {
    case JointType::Revolute:
    case JointType::Continuous: return Transform<T>(Vec3<T>::Zero(), Quat<T>(Eigen::AngleAxis<T>(value, j.axis)));
    case JointType::Prismatic: return Transform<T>(j.axis * value);
    case JointType::Fixed: break;
  }
  return Transform<T>();
}

}  // namespace

template <class T>
Status forwardKinematics(const RobotModel<T>& model, const std::vector<T>& q, std::vector<Transform<T>>& linkPoses) {
  Status s = checkConfiguration(model, q);
  if (!s.ok()) return s;
  linkPoses.resize(model.links.size());
  linkPoses[0] = Transform<T>();
  for (const auto& j : model.joints) {
    T value = T(0);
    if (j.variable >= 0) value = q[std::size_t(j.variable)];
    if (j.mimicJoint >= 0) value = j.multiplier * q[std::size_t(model.joints[std::size_t(j.mimicJoint)].variable)] + j.offset;
    linkPoses[j.childLink] = linkPoses[j.parentLink] * j.origin * jointMotion(j, value);
  }
  return {};
}

template <class T> std::vector<T> randomConfiguration(const RobotModel<T>& model, std::uint64_t& rngState) {
  std::vector<T> q(model.variables.size(), T(0));
  for (const auto& j : model.joints)
    if (j.variable >= 0)
      q[std::size_t(j.variable)] =
          std::clamp(T(j.lower + (j.upper - j.lower) * T(detail::uniform01(rngState))), j.lower, j.upper);
  return q;
}

template Status forwardKinematics<float>(const RobotModel<float>&, const std::vector<float>&,
                                         std::vector<Transform<float>>&);
template Status forwardKinematics<double>(const RobotModel<double>&, const std::vector<double>&,
                                          std::vector<Transform<double>>&);
template std::vector<float> randomConfiguration<float>(const RobotModel<float>&, std::uint64_t&);
template std::vector<double> randomConfiguration<double>(const RobotModel<double>&, std::uint64_t&);

}  // namespace gq::urdf
