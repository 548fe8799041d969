// A planar arm written here: a wide base plate (box), an upper arm (box) on a Y hinge at the plate's top, and a
// forearm (an OBJ box mesh this program writes, checked by its convex hull) on a Y hinge at the upper arm's tip.
// Straight up, the forearm is 0.55 above the plate; with both hinges at 90 degrees it hangs down through the plate.
// Adjacent links are never checked, so the only checked pair is plate-forearm.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <gq/urdf/robot.h>
#include <gq/urdf/self_collision.h>

namespace {

const char* kUrdf = R"(<?xml version="1.0"?>
<robot name="arm">
  <link name="plate">
    <collision><geometry><box size="1.2 1.2 0.1"/></geometry></collision>
  </link>
  <link name="upper">
    <collision><origin xyz="0 0 0.25"/><geometry><box size="0.05 0.05 0.5"/></geometry></collision>
  </link>
  <link name="fore">
    <collision><origin xyz="0 0 0.25"/><geometry><mesh filename="forearm.obj"/></geometry></collision>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="plate"/><child link="upper"/><origin xyz="0 0 0.1"/><axis xyz="0 1 0"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/>
  </joint>
  <joint name="elbow" type="revolute">
    <parent link="upper"/><child link="fore"/><origin xyz="0 0 0.5"/><axis xyz="0 1 0"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/>
  </joint>
</robot>
)";

// A 0.05 x 0.05 x 0.5 box centred on its origin, as an OBJ file.
std::string forearmObj() {
  std::string obj;
  for (int i = 0; i < 8; ++i) {
    char line[96];
    std::snprintf(line, sizeof line, "v %g %g %g\n", i & 1 ? 0.025 : -0.025, i & 2 ? 0.025 : -0.025,
                  i & 4 ? 0.25 : -0.25);
    obj += line;
  }
  obj += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  return obj;
}

}  // namespace

int main() {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "gq_install_urdf_self_collision";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "forearm.obj") << forearmObj();

  auto model = std::make_shared<gq::urdf::RobotModel<double>>();
  const gq::Status loaded = gq::urdf::loadRobotFromStrings(kUrdf, "", dir.string(), gq::urdf::LoadOptions(), *model);
  std::filesystem::remove_all(dir);
  if (!loaded.ok()) {
    std::fprintf(stderr, "loading the arm failed: %s\n", loaded.toString().c_str());
    return 1;
  }
  int failures = 0;
  const auto check = [&](bool ok, const char* what) {
    if (!ok) {
      std::fprintf(stderr, "wrong: %s\n", what);
      ++failures;
    }
  };
  check(model->links.size() == 3 && model->variables.size() == 2, "3 links, 2 joint variables");
  const std::int32_t plate = model->findLink("plate"), fore = model->findLink("fore");
  check(plate >= 0 && fore >= 0, "links named plate and fore");

  gq::urdf::SelfCollisionChecker<double> checker(model);
  gq::urdf::CollisionResult straight, folded;
  gq::Status s = checker.checkSelfCollision({0.0, 0.0}, straight);
  check(s.ok() && !straight.colliding, "straight up: no self-collision");
  std::printf("straight: %s, colliding %d\n", s.toString().c_str(), int(straight.colliding));

  gq::urdf::SelfDistanceResult<double> distance;
  s = checker.selfDistance({0.0, 0.0}, distance);
  // Forearm bottom at 0.1 + 0.5 = 0.6, plate top at 0.05.
  check(s.ok() && std::abs(distance.distance - 0.55) < 1e-6, "straight up: self distance 0.55");
  std::printf("straight: self distance %.12f\n", distance.distance);

  const double half = std::acos(-1.0) / 2;
  s = checker.checkSelfCollision({half, half}, folded);
  const bool platePair = folded.pairs.size() == 1 &&
                         folded.pairs[0] == gq::urdf::LinkPair{std::uint32_t(std::min(plate, fore)),
                                                               std::uint32_t(std::max(plate, fore))};
  check(s.ok() && folded.colliding && platePair, "folded: the forearm collides with the plate");
  std::printf("folded: %s, colliding %d, pairs %zu\n", s.toString().c_str(), int(folded.colliding),
              folded.pairs.size());
  return failures == 0 ? 0 : 1;
}
