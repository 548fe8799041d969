#pragma once
// Panda (../shared/robots, example-robot-data) loaded for the URDF benchmarks, in one representation; nullptr when
// the robot files are missing. The certified error bound is not measured here, so a coarse target loads fast.
#include <memory>
#include <string>

#include "gq/urdf/robot.h"

namespace gqbench {

inline std::shared_ptr<const gq::urdf::RobotModel<double>> loadPanda(gq::urdf::Representation rep) {
  const std::string robots = std::string(GQ_SHARED_DIR) + "/robots";
  gq::urdf::LoadOptions o;
  o.representation = rep;
  o.packagePaths = {robots};
  o.useRosPackagePath = false;
  o.errorBoundTarget = 1.0;
  auto model = std::make_shared<gq::urdf::RobotModel<double>>();
  const std::string base = robots + "/example-robot-data/robots/panda_description/";
  if (!gq::urdf::loadRobot(base + "urdf/panda.urdf", base + "srdf/panda.srdf", o, *model).ok()) return nullptr;
  return model;
}

}  // namespace gqbench
