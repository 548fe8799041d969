#pragma once
// The seeded scene and rays of bench_scene, shared by gq's benchmarks (bench_scene.cpp) and the peers'
// (bench_scene_peers.cpp) so that both answer the same objects and rays in the same run.
#include <memory>
#include <vector>

#include "gq/cooking.h"
#include "gq/scene.h"

namespace bench_scene {

using T = double;
using V = gq::Vec3<T>;

constexpr int kObjects = 1000;
constexpr int kRays = 1000000;       // into the scene
constexpr int kBunnyRays = 1000000;  // at the bunny alone
constexpr int kBruteRays = 2000;
constexpr double kHalf = 20;
// Bunny rays report either face, as Embree's do (the bunny is open at its base).
const gq::HitFlags kBothFaces = gq::kDefaultHitFlags | gq::HitFlag::MeshBothSides;

struct Fixture {
  std::shared_ptr<const gq::TriangleMesh<T>> bunny;
  std::vector<V> bunnyVertices;  // centred, unscaled (as cooked)
  std::vector<gq::TriangleIndices> bunnyTriangles;
  T bunnyScale = 1;
  std::vector<gq::Geometry<T>> geometries;  // object i: geometries[i] at poses[i], scene id i
  std::vector<gq::Transform<T>> poses;
  gq::Scene<T> scene;
  std::vector<V> origins, dirs;
  std::vector<V> bunnyOrigins, bunnyDirs;
  bool ok = false;
};

const Fixture& fixture();

}  // namespace bench_scene
