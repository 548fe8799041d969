// libFuzzer target: gq::urdf::loadRobotFromStrings on arbitrary text, split into URDF and SRDF at the first NUL byte;
// the second byte picks the representation. A model that loads is run through forward kinematics and one
// self-collision check at its home configuration. Inputs naming /dev, /proc or /sys are skipped (a mesh path there
// could block). Contract: never crash or throw; a failed load leaves the model empty.
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "gq/urdf/robot.h"
#include "gq/urdf/self_collision.h"

namespace {

// A folder with a unit-cube OBJ that fuzzed URDFs can reference as "cube.obj".
const std::string& meshDir() {
  static const std::string dir = [] {
    const auto d = std::filesystem::temp_directory_path() / "gq_fuzz_urdf";
    std::filesystem::create_directories(d);
    std::ofstream(d / "cube.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                     "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\n"
                                     "f 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
    return d.string();
  }();
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  for (const char* banned : {"dev/", "proc/", "sys/", "/dev", "/proc", "/sys"})
    if (text.find(banned) != std::string::npos) return 0;
  const std::size_t nul = text.find('\0');
  const std::string urdf = text.substr(0, nul);
  const std::string srdf = nul == std::string::npos ? std::string() : text.substr(nul + 1);
  gq::urdf::LoadOptions options;
  options.useRosPackagePath = false;
  options.packagePaths = {meshDir()};
  options.errorSamplesPerShape = 8;
  options.representation = static_cast<gq::urdf::Representation>(data[0] % 7);
  auto model = std::make_shared<gq::urdf::RobotModel<double>>();
  const gq::Status s = gq::urdf::loadRobotFromStrings(urdf, srdf, meshDir(), options, *model);
  if (!s.ok()) {
    if (!model->links.empty() || s.message.empty()) std::abort();
    return 0;
  }
  std::vector<gq::Transform<double>> poses;
  gq::urdf::forwardKinematics(*model, model->home, poses);
  gq::urdf::CheckerOptions checkerOptions;
  checkerOptions.orderingSamples = 4;  // the default 256 checks per built checker cut the exec rate ~3x
  gq::urdf::SelfCollisionChecker<double> checker(model, checkerOptions);
  gq::urdf::CollisionResult result;
  checker.checkSelfCollision(model->home, result);
  gq::urdf::SelfDistanceResult<double> distance;
  checker.selfDistance(model->home, distance);
  return 0;
}
