#pragma once
// Seeded random scenes for the scene and batch tests, and the brute-force reference: every instance asked through
// the single-geometry queries of gq/query.h, in id order, with the scene's documented tie rules.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <vector>

#include "gq/cooking.h"
#include "gq/query.h"
#include "gq/scene.h"
#include "mesh_test_helpers.h"
#include "random_hulls.h"
#include "test_util.h"

namespace gq::scenetest {

using test::Rng;

template <class T> struct Item {
  Geometry<T> geometry;
  Transform<T> pose;
  std::uint32_t mask = 0xffffffffu;
};

// Cooked data shared by every random geometry of a test.
template <class T> struct Library {
  std::shared_ptr<const ConvexMesh<T>> hull;
  std::shared_ptr<const TriangleMesh<T>> sphereMesh;  // closed icosphere, 80 triangles
  std::shared_ptr<const TriangleMesh<T>> quads;       // two parallel open squares: rays cross both

  explicit Library(Rng& rng) {
    hull = test::ellipsoidHull<T>(24, rng);
    const auto ico = meshtest::icosphere<T>(1);
    sphereMesh = meshtest::cook(ico.vertices, ico.triangles);
    const auto q = meshtest::quadStack<T>(2);
    quads = meshtest::cook(q.vertices, q.triangles);
  }
};

// Spheres, capsules, boxes, hulls and meshes of sizes 0.2 to 2.
template <class T> Geometry<T> randomGeometry(Rng& rng, const Library<T>& lib) {
  const double pick = rng.uniform(0, 6);
  const T s = T(rng.uniform(0.2, 2.0));
  if (pick < 1) return SphereGeometry<T>(s);
  if (pick < 2) return CapsuleGeometry<T>(s * T(0.5), s);
  if (pick < 3) {
    const Vec3<T> he = rng.vec<T>(0.2, 1.5);
    return BoxGeometry<T>(he);
  }
  if (pick < 4) return ConvexMeshGeometry<T>(lib.hull, MeshScale<T>(s));
  if (pick < 5) return TriangleMeshGeometry<T>(lib.sphereMesh, MeshScale<T>(s));
  return TriangleMeshGeometry<T>(lib.quads, MeshScale<T>(s), MeshGeometryFlag::DoubleSided);
}

// A query shape for sweeps, overlaps and distances: a primitive or a hull (pairs every instance type answers).
template <class T> Geometry<T> randomQueryGeometry(Rng& rng, const Library<T>& lib) {
  const double pick = rng.uniform(0, 4);
  const T s = T(rng.uniform(0.3, 1.5));
  if (pick < 1) return SphereGeometry<T>(s);
  if (pick < 2) return CapsuleGeometry<T>(s * T(0.5), s);
  if (pick < 3) return BoxGeometry<T>(s, s * T(0.7), s * T(0.5));
  return ConvexMeshGeometry<T>(lib.hull, MeshScale<T>(s));
}

// The scene under test and its mirror, kept in step.
template <class T> struct World {
  Scene<T> scene;
  std::map<InstanceId, Item<T>> items;
  double half = 10;  // positions in [-half, half]^3

  void add(InstanceId id, const Geometry<T>& g, const Transform<T>& pose, std::uint32_t mask = 0xffffffffu) {
    const Status s = scene.add(id, g, pose, mask);
    ASSERT_TRUE(s.ok()) << s.toString();
    items[id] = Item<T>{g, pose, mask};
  }
  void setPose(InstanceId id, const Transform<T>& pose) {
    const Status s = scene.setPose(id, pose);
    ASSERT_TRUE(s.ok()) << s.toString();
    items[id].pose = pose;
  }
  void remove(InstanceId id) {
    const Status s = scene.remove(id);
    ASSERT_TRUE(s.ok()) << s.toString();
    items.erase(id);
  }
};

// `count` random instances with ids firstId, firstId + 7, ... (sparse ids).
template <class T>
void populate(World<T>& w, Rng& rng, const Library<T>& lib, int count, InstanceId firstId = 1, bool masks = false) {
  for (int i = 0; i < count; ++i) {
    const Geometry<T> g = randomGeometry(rng, lib);
    const Transform<T> pose = rng.pose<T>(w.half);
    const std::uint32_t mask = masks ? (1u << std::uint32_t(rng.uniform(0, 4))) : 0xffffffffu;
    w.add(firstId + InstanceId(7 * i), g, pose, mask);
  }
}

inline bool passes(const SceneFilter& f, std::uint32_t mask, InstanceId id) {
  return (f.mask & mask) != 0 && (f.callback == nullptr || f.callback(f.userData, id));
}

// ---- brute force --------------------------------------------------------------------------------------------

template <class T>
bool bruteClosestRay(const World<T>& w, const Vec3<T>& o, const Vec3<T>& d, T maxDist, HitFlags flags,
                     SceneRaycastHit<T>& best, const SceneFilter& filter = {}) {
  bool found = false;
  for (const auto& [id, it] : w.items) {
    if (!passes(filter, it.mask, id)) continue;
    RaycastHit<T> h;
    std::uint32_t n = 0;
    if (!raycast(o, d, it.geometry, it.pose, maxDist, flags, 1u, &h, n).ok() || n == 0) continue;
    if (!found || h.distance < best.hit.distance) {
      best = {id, h};
      found = true;
    }
  }
  return found;
}

template <class T>
std::vector<SceneRaycastHit<T>> bruteAllRay(const World<T>& w, const Vec3<T>& o, const Vec3<T>& d, T maxDist,
                                            HitFlags flags, std::uint32_t maxHits, const SceneFilter& filter = {}) {
  std::vector<SceneRaycastHit<T>> all;
  std::vector<RaycastHit<T>> local(maxHits);
  for (const auto& [id, it] : w.items) {
    if (!passes(filter, it.mask, id)) continue;
    std::uint32_t n = 0;
    if (!raycast(o, d, it.geometry, it.pose, maxDist, flags, maxHits, local.data(), n).ok()) continue;
    for (std::uint32_t k = 0; k < n; ++k) all.push_back({id, local[k]});
  }
  std::stable_sort(all.begin(), all.end(), [](const auto& a, const auto& b) {
    return a.hit.distance < b.hit.distance || (a.hit.distance == b.hit.distance && a.id < b.id);
  });
  if (all.size() > maxHits) all.resize(maxHits);
  return all;
}

template <class T>
bool bruteSweep(const World<T>& w, const Vec3<T>& d, T maxDist, const Geometry<T>& g, const Transform<T>& pose,
                SceneSweepHit<T>& best, const SceneFilter& filter = {}) {
  bool found = false;
  for (const auto& [id, it] : w.items) {
    if (!passes(filter, it.mask, id)) continue;
    SweepHit<T> h;
    bool has = false;
    if (!sweep(d, maxDist, g, pose, it.geometry, it.pose, h, has).ok() || !has) continue;
    if (!found || h.distance < best.hit.distance) {
      best = {id, h};
      found = true;
    }
  }
  return found;
}

template <class T>
std::vector<InstanceId> bruteOverlap(const World<T>& w, const Geometry<T>& g, const Transform<T>& pose,
                                     const SceneFilter& filter = {}) {
  std::vector<InstanceId> out;
  for (const auto& [id, it] : w.items) {
    if (!passes(filter, it.mask, id)) continue;
    bool hit = false;
    if (overlap(g, pose, it.geometry, it.pose, hit).ok() && hit) out.push_back(id);
  }
  return out;
}

template <class T>
bool bruteNearest(const World<T>& w, const Geometry<T>& g, const Transform<T>& pose, T maxDistance,
                  SceneDistanceResult<T>& best, const SceneFilter& filter = {}) {
  bool found = false;
  for (const auto& [id, it] : w.items) {
    if (!passes(filter, it.mask, id)) continue;
    DistanceResult<T> r;
    if (!distance(r, g, pose, it.geometry, it.pose).ok() || r.distance > maxDistance) continue;
    if (!found || r.distance < best.result.distance) {
      best = {id, r};
      found = true;
    }
  }
  return found;
}

template <class T> std::vector<ScenePair> brutePairs(const World<T>& w) {
  std::vector<ScenePair> out;
  for (auto a = w.items.begin(); a != w.items.end(); ++a) {
    for (auto b = std::next(a); b != w.items.end(); ++b) {
      if ((a->second.mask & b->second.mask) == 0) continue;
      bool hit = false;
      if (overlap(a->second.geometry, a->second.pose, b->second.geometry, b->second.pose, hit).ok() && hit) {
        out.push_back({a->first, b->first});
      }
    }
  }
  return out;
}

template <class T> std::vector<ScenePair> brutePairs(const World<T>& wa, const World<T>& wb) {
  std::vector<ScenePair> out;
  for (const auto& [ia, a] : wa.items) {
    for (const auto& [ib, b] : wb.items) {
      if ((a.mask & b.mask) == 0) continue;
      bool hit = false;
      if (overlap(a.geometry, a.pose, b.geometry, b.pose, hit).ok() && hit) out.push_back({ia, ib});
    }
  }
  return out;
}

}  // namespace gq::scenetest
