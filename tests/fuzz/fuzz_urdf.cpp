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

// A folder with a unit-cube STL that fuzzed URDFs can reference as "cube.stl". Not OBJ: assimp's OBJ importer
// allocates and clears two 16 MB buffers per file, which under ASan was 80% of this target's time (perf), and OBJ
// parsing has its own target (fuzz_mesh_file).
std::string unitCubeStl() {
  const int v[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  std::string stl = "solid cube\n";
  for (const auto& t : f) {
    stl += "facet normal 0 0 0\nouter loop\n";  // assimp recomputes zero normals
    for (const int k : t)
      stl += "vertex " + std::to_string(v[k][0]) + " " + std::to_string(v[k][1]) + " " + std::to_string(v[k][2]) + "\n";
    stl += "endloop\nendfacet\n";
  }
  return stl + "endsolid cube\n";
}

const std::string& meshDir() {
  static const std::string dir = [] {
    const auto d = std::filesystem::temp_directory_path() / "gq_fuzz_urdf";
    std::filesystem::create_directories(d);
    std::ofstream(d / "cube.stl") << unitCubeStl();
    return d.string();
  }();
  return dir;
}

// A failed query names its reason: a Status that is not ok with an empty message is a bug.
void requireExplained(const gq::Status& s) {
  if (!s.ok() && *s.message() == '\0') std::abort();
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
  options.errorBoundTarget = 1e9;  // the bound's tightness is not under test: its first proven value ends refinement
  options.representation = static_cast<gq::urdf::Representation>(data[0] % 7);
  auto model = std::make_shared<gq::urdf::RobotModel<double>>();
  const gq::Status s = gq::urdf::loadRobotFromStrings(urdf, srdf, meshDir(), options, *model);
  if (!s.ok()) {
    if (!model->links.empty() || *s.message() == '\0') std::abort();
    return 0;
  }
  // Each call may reject what a fuzzed model holds (an SRDF home outside the joint limits, shapes too large for pair
  // queries): a rejection must say why, an answer must cover every link.
  std::vector<gq::Transform<double>> poses;
  const gq::Status kinematics = gq::urdf::forwardKinematics(*model, model->home, poses);
  requireExplained(kinematics);
  if (kinematics.ok() && poses.size() != model->links.size()) std::abort();
  gq::urdf::CheckerOptions checkerOptions;
  checkerOptions.orderingSamples = 4;  // the default 256 checks per built checker cut the exec rate ~3x
  gq::urdf::SelfCollisionChecker<double> checker(model, checkerOptions);
  gq::urdf::CollisionResult result;
  requireExplained(checker.checkSelfCollision(model->home, result));
  gq::urdf::SelfDistanceResult<double> distance;
  requireExplained(checker.selfDistance(model->home, distance));
  return 0;
}
