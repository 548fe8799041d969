// libFuzzer target: gq::loadMeshFile on arbitrary bytes saved as .obj or .stl (gq's own OBJ and STL readers; first
// byte picks), then cooking of what loaded. Contract: ok -> every index in range; error -> `out` untouched; nothing
// crashes or throws. Built a second time as fuzz_mesh_file_stl (GQ_FUZZ_STL_ONLY: every input saved as .stl).
// DAE is not mutated here: assimp 5.2's Collada loader segfaults on malformed files
// (known_crashes/fuzz_mesh_file_assimp_collada_segv.bin, third-party); the DAE tests of tests/core cover that format.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "gq/io.h"

namespace {

std::string scratchPath(const char* extension) {
  // /dev/shm keeps the round trip in memory; one file per process (parallel fuzzing jobs do not collide).
  const std::filesystem::path dir = std::filesystem::exists("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
  return (dir / ("gq_fuzz_mesh_" + std::to_string(getpid()) + extension)).string();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
#ifdef GQ_FUZZ_STL_ONLY
  const std::string path = scratchPath(".stl");
#else
  static const char* const kExtensions[] = {".obj", ".stl"};
  const std::string path = scratchPath(kExtensions[data[0] % 2]);
#endif
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
  gq::MeshData<double> mesh;
  mesh.triangles = {{7, 7, 7}};
  const gq::Status s = gq::loadMeshFile(path, mesh);
  std::filesystem::remove(path);
  if (!s.ok()) {
    if (mesh.triangles.size() != 1 || mesh.triangles[0][0] != 7 || !mesh.vertices.empty()) std::abort();
    return 0;
  }
  for (const auto& t : mesh.triangles)
    for (std::uint32_t i : t)
      if (i >= mesh.vertices.size()) std::abort();
  std::shared_ptr<const gq::TriangleMesh<double>> cooked;
  (void)gq::cookTriangleMesh(mesh.vertices, mesh.triangles, cooked);  // any status: the target checks it returns
  if (mesh.vertices.size() <= 64) {
    std::shared_ptr<const gq::ConvexMesh<double>> hull;
    (void)gq::cookConvexMesh(mesh.vertices, hull);  // any status: the target checks it returns
  }
  return 0;
}
