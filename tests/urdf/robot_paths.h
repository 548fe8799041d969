#pragma once
// Shared helpers of the URDF tests: robot paths, cached models (loading fits the shapes and certifies their error bounds once per
// scalar type, robot and representation), and typed-test lists.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <string>
#include <tuple>

#include "gq/urdf/robot.h"
#include "gq/urdf/self_collision.h"
#include "shared_data.h"

namespace gq::urdf::test {

inline std::string robotsDir() { return gqtest::sharedPath("robots"); }
inline std::string robotFile(const std::string& rel) {
  return robotsDir() + "/example-robot-data/robots/" + rel;
}

struct RobotFiles {
  const char* name;
  const char* urdf;
  const char* srdf;
};
inline const RobotFiles kPanda{"panda", "panda_description/urdf/panda.urdf", "panda_description/srdf/panda.srdf"};
inline const RobotFiles kPandaPrimitives{"panda_collision", "panda_description/urdf/panda_collision.urdf",
                                         "panda_description/srdf/panda.srdf"};
inline const RobotFiles kUr5{"ur5", "ur_description/urdf/ur5_robot.urdf", "ur_description/srdf/ur5.srdf"};

inline LoadOptions testOptions(Representation rep) {
  LoadOptions o;
  o.representation = rep;
  o.packagePaths = {robotsDir()};
  o.useRosPackagePath = false;
  o.errorBoundTarget = 1e-3;  // a millimetre bound loads fast; tests of the bound itself ask for the default
  return o;
}

// A robot of the shared data folder, loaded once per process, scalar type and representation; nullptr (and a
// failure naming the robot) when it does not load. Callers ASSERT_TRUE the result before using it.
template <class T> std::shared_ptr<const RobotModel<T>> loadCached(const RobotFiles& robot, Representation rep) {
  static std::map<std::pair<std::string, int>, std::shared_ptr<const RobotModel<T>>> cache;
  auto& slot = cache[{robot.name, int(rep)}];
  if (!slot) {
    auto model = std::make_shared<RobotModel<T>>();
    const Status s = loadRobot(robotFile(robot.urdf), robotFile(robot.srdf), testOptions(rep), *model);
    if (!s.ok()) {
      ADD_FAILURE() << robot.name << " (" << toString(rep) << ") did not load: " << s.toString();
      return nullptr;
    }
    slot = model;
  }
  return slot;
}

// Tests on the real robots (Panda, its primitive URDF, UR5) derive their fixture from this one: each is skipped,
// naming the file it looked for, when the shared data folder does not hold the robots.
class RobotDataTest : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const RobotFiles* robot : {&kPanda, &kPandaPrimitives, &kUr5}) {
      GQ_REQUIRE_SHARED_FILE(robotFile(robot->urdf));
      GQ_REQUIRE_SHARED_FILE(robotFile(robot->srdf));
    }
  }
};

template <class T> std::vector<T> castConfiguration(const std::vector<double>& q) {
  return std::vector<T>(q.begin(), q.end());
}

template <class T> std::vector<T> namedConfiguration(const RobotModel<T>& m, const std::map<std::string, double>& values) {
  std::vector<T> q = m.home;
  for (const auto& [name, v] : values) {
    const auto it = std::find(m.variables.begin(), m.variables.end(), name);
    EXPECT_NE(it, m.variables.end()) << name;
    if (it != m.variables.end()) q[std::size_t(it - m.variables.begin())] = T(v);
  }
  return q;
}

template <class T> LinkPair pairOf(const RobotModel<T>& m, const char* a, const char* b) {
  const auto ia = std::uint32_t(m.findLink(a)), ib = std::uint32_t(m.findLink(b));
  return {std::min(ia, ib), std::max(ia, ib)};
}

using Scalars = ::testing::Types<float, double>;

}  // namespace gq::urdf::test
