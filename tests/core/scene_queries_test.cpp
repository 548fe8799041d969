// Every scene query equals the loop over all instances through the single-geometry queries, on seeded random scenes
// of spheres, capsules, boxes, hulls and meshes, after adds, moves and removes (float and double).
#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <thread>
#include <type_traits>
#include <vector>

#include "gq/custom.h"
#include "gq/scene.h"
#include "scene_test_support.h"

namespace gq {
namespace {

using scenetest::Library;
using scenetest::World;
using test::Rng;

template <class T> class SceneQueries : public ::testing::Test {};
TYPED_TEST_SUITE(SceneQueries, test::Scalars);

constexpr HitFlags kMultiFlags = kDefaultHitFlags | HitFlag::MeshMultiple;

// The scene's closest hit of one ray against the loop over all instances: whether it hits, and the hit's instance and
// fields. `has` and `hit` receive the scene's answer.
template <class T>
void expectClosestAsTheLoop(const World<T>& w, const Vec3<T>& o, const Vec3<T>& d, T maxDist, const SceneFilter& filter,
                            bool& has, SceneRaycastHit<T>& hit) {
  SceneRaycastHit<T> ref;
  has = false;
  const Status s = w.scene.raycastClosest(o, d, maxDist, hit, has, kDefaultHitFlags, filter);
  ASSERT_EQ(s.code, StatusCode::Ok) << s.toString();
  ASSERT_EQ(has, scenetest::bruteClosestRay(w, o, d, maxDist, kDefaultHitFlags, ref, filter));
  if (has) {
    EXPECT_EQ(hit.id, ref.id);
    EXPECT_EQ(hit.hit.distance, ref.hit.distance);
    EXPECT_EQ(hit.hit.position, ref.hit.position);
    EXPECT_EQ(hit.hit.normal, ref.hit.normal);
    EXPECT_EQ(hit.hit.faceIndex, ref.hit.faceIndex);
  }
}

template <class T> void expectRaysMatch(const World<T>& w, Rng& rng, int rays, const SceneFilter& filter = {}) {
  for (int r = 0; r < rays; ++r) {
    const Vec3<T> o = rng.inBox<T>(w.half * 1.5);
    Vec3<T> d = rng.unitVector<T>();
    if (r % 3 == 0) d = (rng.inBox<T>(w.half * 0.5) - o).normalized();  // aimed at the middle
    const T maxDist = T(rng.uniform(5, 60));
    SCOPED_TRACE(r);

    SceneRaycastHit<T> hit;
    bool has = false;
    ASSERT_NO_FATAL_FAILURE(expectClosestAsTheLoop(w, o, d, maxDist, filter, has, hit));

    SceneRaycastHit<T> any;
    bool hasAny = false;
    ASSERT_TRUE(w.scene.raycastAny(o, d, maxDist, any, hasAny, kDefaultHitFlags, filter).ok());
    ASSERT_EQ(hasAny, has);
    if (hasAny) {  // a real hit of the instance it names
      const auto& it = w.items.at(any.id);
      RaycastHit<T> h;
      std::uint32_t n = 0;
      ASSERT_TRUE(raycast(o, d, it.geometry, it.pose, maxDist, kDefaultHitFlags, 1u, &h, n).ok());
      ASSERT_EQ(n, 1u);
      EXPECT_EQ(any.hit.distance, h.distance);
    }

    const std::uint32_t maxHits = 1 + std::uint32_t(r % 6);
    std::vector<SceneRaycastHit<T>> all(maxHits);
    std::uint32_t count = 99;
    ASSERT_TRUE(w.scene.raycastAll(o, d, maxDist, kMultiFlags, maxHits, all.data(), count, filter).ok());
    const auto refAll = scenetest::bruteAllRay(w, o, d, maxDist, kMultiFlags, maxHits, filter);
    ASSERT_EQ(count, refAll.size());
    for (std::uint32_t k = 0; k < count; ++k) {
      EXPECT_EQ(all[k].id, refAll[k].id) << k;
      EXPECT_EQ(all[k].hit.distance, refAll[k].hit.distance) << k;
      EXPECT_EQ(all[k].hit.faceIndex, refAll[k].hit.faceIndex) << k;
    }
  }
}

template <class T>
void expectShapeQueriesMatch(const World<T>& w, Rng& rng, const Library<T>& lib, int queries,
                             const SceneFilter& filter = {}) {
  for (int q = 0; q < queries; ++q) {
    SCOPED_TRACE(q);
    const Geometry<T> g = scenetest::randomQueryGeometry(rng, lib);
    const Transform<T> pose = rng.pose<T>(w.half);

    std::vector<InstanceId> ids;
    const Status so = w.scene.overlapAll(g, pose, ids, filter);
    ASSERT_EQ(so.code, StatusCode::Ok) << so.toString();
    EXPECT_EQ(ids, scenetest::bruteOverlap(w, g, pose, filter));

    const T bound = q % 2 ? std::numeric_limits<T>::infinity() : T(rng.uniform(0, 3));
    SceneDistanceResult<T> near, refNear;
    bool found = false;
    const Status sn = w.scene.nearest(g, pose, bound, near, found, filter);
    ASSERT_EQ(sn.code, StatusCode::Ok) << sn.toString();
    const bool refFound = scenetest::bruteNearest(w, g, pose, bound, refNear, filter);
    ASSERT_EQ(found, refFound);
    if (found) {
      EXPECT_EQ(near.id, refNear.id);
      EXPECT_EQ(near.result.distance, refNear.result.distance);
      EXPECT_EQ(near.result.point0, refNear.result.point0);
      EXPECT_EQ(near.result.normal, refNear.result.normal);
    }

    const Vec3<T> d = rng.unitVector<T>();
    const T maxDist = T(rng.uniform(1, 25));
    SceneSweepHit<T> sh, refSh;
    bool hasSweep = false;
    const Status ss = w.scene.sweepClosest(d, maxDist, g, pose, sh, hasSweep, kDefaultHitFlags, T(0), filter);
    ASSERT_EQ(ss.code, StatusCode::Ok) << ss.toString();
    const bool refSweep = scenetest::bruteSweep(w, d, maxDist, g, pose, refSh, filter);
    ASSERT_EQ(hasSweep, refSweep);
    if (hasSweep) {
      EXPECT_EQ(sh.id, refSh.id);
      EXPECT_EQ(sh.hit.distance, refSh.hit.distance);
      EXPECT_EQ(sh.hit.normal, refSh.hit.normal);
    }
  }
}

template <class T> void expectPairsMatch(const World<T>& w) {
  std::vector<ScenePair> pairs;
  ASSERT_TRUE(w.scene.overlappingPairs(pairs).ok());
  EXPECT_EQ(pairs, scenetest::brutePairs(w));
}

// Adds, then moves a third, removes a quarter and adds more: each stage checked against brute force.
template <class T> void runStages(std::uint64_t seed, bool masks, const SceneFilter& filter) {
  Rng rng(seed);
  Library<T> lib(rng);
  World<T> w;
  scenetest::populate(w, rng, lib, 120, 1, masks);
  expectRaysMatch(w, rng, 150, filter);
  expectShapeQueriesMatch(w, rng, lib, 60, filter);
  expectPairsMatch(w);
  w.scene.rebuild();  // the moves below refit a tree built top down
  EXPECT_GE(w.scene.rebuildCount(), 1u);

  std::vector<InstanceId> ids;
  for (const auto& [id, it] : w.items) ids.push_back(id);
  for (std::size_t i = 0; i < ids.size(); i += 3) w.setPose(ids[i], rng.pose<T>(w.half));
  expectRaysMatch(w, rng, 100, filter);
  expectShapeQueriesMatch(w, rng, lib, 40, filter);
  expectPairsMatch(w);

  for (std::size_t i = 1; i < ids.size(); i += 4) w.remove(ids[i]);
  scenetest::populate(w, rng, lib, 40, 5000, masks);
  EXPECT_EQ(w.scene.size(), w.items.size());
  expectRaysMatch(w, rng, 100, filter);
  expectShapeQueriesMatch(w, rng, lib, 40, filter);
  expectPairsMatch(w);
}

TYPED_TEST(SceneQueries, EveryQueryMatchesBruteForceAfterAddsMovesAndRemoves) {
  runStages<TypeParam>(44, false, SceneFilter{});
}

TYPED_TEST(SceneQueries, MasksAndCallbacksFilterAsTheLoopDoes) {
  SceneFilter filter;
  filter.mask = 0x5u;  // two of the four mask bits
  filter.callback = [](void*, InstanceId id) { return id % 3 != 0; };
  runStages<TypeParam>(45, true, filter);
}

TYPED_TEST(SceneQueries, CallbackUserDataReachesTheCallback) {
  using T = TypeParam;
  Rng rng(7);
  Library<T> lib(rng);
  World<T> w;
  scenetest::populate(w, rng, lib, 60);
  InstanceId banned = w.items.begin()->first;
  SceneFilter filter;
  filter.userData = &banned;
  filter.callback = [](void* user, InstanceId id) { return id != *static_cast<InstanceId*>(user); };
  const auto& it = w.items.at(banned);
  std::vector<InstanceId> ids;
  ASSERT_TRUE(w.scene.overlapAll(it.geometry, it.pose, ids, filter).ok());
  EXPECT_EQ(std::count(ids.begin(), ids.end(), banned), 0);
  ASSERT_TRUE(w.scene.overlapAll(it.geometry, it.pose, ids).ok());
  EXPECT_EQ(std::count(ids.begin(), ids.end(), banned), 1);
}

TYPED_TEST(SceneQueries, PairsBetweenTwoScenesMatchBruteForce) {
  using T = TypeParam;
  Rng rng(46);
  Library<T> lib(rng);
  World<T> a, b;
  scenetest::populate(a, rng, lib, 80, 1, true);
  scenetest::populate(b, rng, lib, 70, 3, true);
  std::vector<ScenePair> pairs;
  ASSERT_TRUE(a.scene.overlappingPairs(b.scene, pairs).ok());
  const auto ref = scenetest::brutePairs(a, b);
  EXPECT_EQ(pairs, ref);
  EXPECT_FALSE(ref.empty());
}

TYPED_TEST(SceneQueries, PairFilterCallbackDropsPairs) {
  using T = TypeParam;
  Rng rng(47);
  Library<T> lib(rng);
  World<T> w;
  scenetest::populate(w, rng, lib, 100);
  std::vector<ScenePair> all, filtered;
  ASSERT_TRUE(w.scene.overlappingPairs(all).ok());
  ScenePairFilter f;
  f.callback = [](void*, InstanceId a, InstanceId b) { return (a + b) % 2 == 0; };
  ASSERT_TRUE(w.scene.overlappingPairs(filtered, f).ok());
  std::vector<ScenePair> expected;
  for (const auto& p : all) {
    if ((p.id0 + p.id1) % 2 == 0) expected.push_back(p);
  }
  EXPECT_EQ(filtered, expected);
  EXPECT_LT(filtered.size(), all.size());
}

TYPED_TEST(SceneQueries, ManyMovesRebuildTheTreeAndKeepAnswers) {
  using T = TypeParam;
  Rng rng(48);
  Library<T> lib(rng);
  World<T> w;
  scenetest::populate(w, rng, lib, 200);
  const auto before = w.scene.rebuildCount();
  std::vector<InstanceId> ids;
  for (const auto& [id, it] : w.items) ids.push_back(id);
  // Everything moves far along +x in small steps: refits stretch the inner boxes until a rebuild.
  for (int step = 0; step < 20; ++step) {
    for (InstanceId id : ids) {
      Transform<T> p = w.items.at(id).pose;
      p.p += rng.inBox<T>(2.0);
      w.setPose(id, p);
    }
  }
  EXPECT_GT(w.scene.rebuildCount(), before);
  EXPECT_LE(w.scene.treeDepth(), 40u);
  w.half = 20;
  expectRaysMatch(w, rng, 100);
  expectShapeQueriesMatch(w, rng, lib, 30);
  expectPairsMatch(w);
}

// Rays walk the 8-wide ray tree: grown by adds, rebuilt top down, refit by moves, with lanes emptied by removals; an
// instance beyond float's reach keeps rays on the binary tree. Every stage answers as the loop over all instances.
TYPED_TEST(SceneQueries, RaysAnswerAsTheLoopOnTheRayTreeGrownRebuiltRefitAndEmptied) {
  using T = TypeParam;
  Rng rng(51);
  Library<T> lib(rng);
  World<T> w;
  scenetest::populate(w, rng, lib, 150);
  EXPECT_TRUE(w.scene.rayTreeCurrent());
  expectRaysMatch(w, rng, 60);
  w.scene.rebuild();
  EXPECT_TRUE(w.scene.rayTreeCurrent());
  expectRaysMatch(w, rng, 80);
  std::vector<InstanceId> ids;
  for (const auto& [id, it] : w.items) ids.push_back(id);
  for (std::size_t i = 0; i < ids.size(); i += 2) w.setPose(ids[i], rng.pose<T>(w.half));
  EXPECT_TRUE(w.scene.rayTreeCurrent());
  expectRaysMatch(w, rng, 60);
  for (std::size_t i = 1; i < ids.size(); i += 5) w.remove(ids[i]);
  EXPECT_TRUE(w.scene.rayTreeCurrent());
  expectRaysMatch(w, rng, 60);
  scenetest::populate(w, rng, lib, 30, 9000);  // into lanes the removals emptied, and new ones
  EXPECT_TRUE(w.scene.rayTreeCurrent());
  expectRaysMatch(w, rng, 40);
  for (std::size_t i = 0; i < ids.size(); i += 7) {
    if (w.items.count(ids[i])) w.setPose(ids[i], rng.pose<T>(w.half));
  }
  expectRaysMatch(w, rng, 40);
  w.scene.rebuild();
  EXPECT_TRUE(w.scene.rayTreeCurrent());
  expectRaysMatch(w, rng, 60);
  // A large sphere far out: the ray tree is not built over it (in float its box's area overflows, so it is kept
  // beside the trees as planes are), rays still find it.
  w.add(20000, SphereGeometry<T>(T(1e29)), Transform<T>(Vec3<T>(T(1e31), T(0), T(0))));
  EXPECT_EQ(w.scene.rayTreeCurrent(), (std::is_same_v<T, float>));
  expectRaysMatch(w, rng, 20);
  w.scene.rebuild();
  EXPECT_EQ(w.scene.rayTreeCurrent(), (std::is_same_v<T, float>));
  expectRaysMatch(w, rng, 40);
  SceneRaycastHit<T> hit;
  bool has = false;
  ASSERT_TRUE(w.scene.raycastClosest(Vec3<T>(T(5e30), T(0), T(0)), Vec3<T>::UnitX(), T(1e31), hit, has).ok());
  ASSERT_TRUE(has);
  EXPECT_EQ(hit.id, 20000u);
}

// Boxes added along x in increasing order chain the ray tree's insertions past the depth its walk allows: the tree is
// left, and built again once the adds since its last build reach an eighth of the instances, so rays walk it after
// most adds.
TYPED_TEST(SceneQueries, InstancesAddedInSortedOrderKeepRaysOnTheRayTreeAfterMostAdds) {
  using T = TypeParam;
  Rng rng(53);
  World<T> w;
  int current = 0;
  constexpr int kBoxes = 2000;
  for (int i = 0; i < kBoxes; ++i) {
    w.add(InstanceId(i + 1), BoxGeometry<T>(T(0.25), T(0.5), T(0.5)), Transform<T>(Vec3<T>(T(i), T(0), T(0))));
    current += w.scene.rayTreeCurrent() ? 1 : 0;
  }
  EXPECT_GE(current, kBoxes * 3 / 4);
  for (int r = 0; r < 40; ++r) {
    SCOPED_TRACE(r);
    const Vec3<T> o(T(rng.uniform(-5, 2005)), T(rng.uniform(-1, 1)), T(rng.uniform(-3, 3)));
    const Vec3<T> d = rng.unitVector<T>();
    SceneRaycastHit<T> hit;
    bool has = false;
    ASSERT_NO_FATAL_FAILURE(expectClosestAsTheLoop(w, o, d, T(100), {}, has, hit));
  }
}

// A custom unit cube (a box of half-extent 1) whose raycast records the ray lengths it is asked with.
template <class T> class RecordingCube : public CustomGeometryCallbacks<T> {
 public:
  const char* name() const override { return "recording cube"; }
  Bounds3<T> localBounds() const override { return Bounds3<T>{Vec3<T>::Constant(T(-1)), Vec3<T>::Constant(T(1))}; }
  Vec3<T> support(const Vec3<T>& d) const override {
    return Vec3<T>(d.x() < 0 ? T(-1) : T(1), d.y() < 0 ? T(-1) : T(1), d.z() < 0 ? T(-1) : T(1));
  }
  bool raycast(const Vec3<T>& o, const Vec3<T>& d, T maxDist, HitFlags, RaycastHit<T>& hit) const override {
    lengths.push_back(maxDist);
    RaycastHit<T> h[1];
    std::uint32_t n = 0;
    if (!gq::raycast(o, d, Geometry<T>(BoxGeometry<T>(T(1), T(1), T(1))), Transform<T>(), maxDist, kDefaultHitFlags,
                     1u, h, n)
             .ok() ||
        n == 0)
      return false;
    hit = h[0];
    return true;
  }
  mutable std::vector<T> lengths;
};

// Instances hit at the same distance: the smaller id wins whichever the walk asks first. An instance asked after a
// closer hit gets one step more than that distance as its ray's length (a mesh hit at distance 0 is still found), a
// custom shape the query's maxDist.
TYPED_TEST(SceneQueries, TiesAtTheClosestDistanceGoToTheSmallerIdWhicheverIsAskedFirst) {
  using T = TypeParam;
  Rng rng(52);
  Library<T> lib(rng);
  for (const bool smallerFirst : {true, false}) {
    SCOPED_TRACE(smallerFirst);
    // Two open quads at z = 0 (both faces): a ray starting on them hits both at distance 0.
    World<T> quads;
    const TriangleMeshGeometry<T> quad(lib.quads, MeshScale<T>(), MeshGeometryFlag::DoubleSided);
    quads.add(smallerFirst ? 2 : 5, quad, Transform<T>());
    quads.add(smallerFirst ? 5 : 2, quad, Transform<T>());
    // Two recording cubes at the same place: both hit at distance 4.
    World<T> cubes;
    auto a = std::make_shared<RecordingCube<T>>(), b = std::make_shared<RecordingCube<T>>();
    cubes.add(smallerFirst ? 4 : 9, CustomGeometry<T>(a), Transform<T>(Vec3<T>(T(0), T(0), T(5))));
    cubes.add(smallerFirst ? 9 : 4, CustomGeometry<T>(b), Transform<T>(Vec3<T>(T(0), T(0), T(5))));
    for (const bool rebuilt : {false, true}) {
      if (rebuilt) {
        quads.scene.rebuild();
        cubes.scene.rebuild();
      }
      SceneRaycastHit<T> hit;
      bool has = false;
      ASSERT_TRUE(quads.scene.raycastClosest(Vec3<T>(T(0.1), T(0.2), T(0)), Vec3<T>::UnitZ(), T(10), hit, has).ok());
      ASSERT_TRUE(has);
      EXPECT_EQ(hit.id, 2u);
      EXPECT_EQ(hit.hit.distance, T(0));
      ASSERT_TRUE(cubes.scene.raycastClosest(Vec3<T>::Zero(), Vec3<T>::UnitZ(), T(100), hit, has).ok());
      ASSERT_TRUE(has);
      EXPECT_EQ(hit.id, 4u);
      EXPECT_EQ(hit.hit.distance, T(4));
      for (const auto& cube : {a, b}) {
        ASSERT_FALSE(cube->lengths.empty());
        for (T length : cube->lengths) EXPECT_EQ(length, T(100));
        cube->lengths.clear();
      }
    }
  }
}

// Two copies of a bumpy heightfield at one pose: every ray hits both at the same distance, found by triangle tests
// that compare t scaled by their determinant; the smaller id wins whichever copy the walk asks first.
TYPED_TEST(SceneQueries, HeightfieldTiesGoToTheSmallerIdWhicheverIsAskedFirst) {
  using T = TypeParam;
  Rng rng(54);
  HeightFieldDesc<T> desc;
  desc.rows = desc.columns = 9;
  for (std::uint32_t i = 0; i < desc.rows * desc.columns; ++i) desc.heights.push_back(T(rng.uniform(-0.5, 0.5)));
  std::shared_ptr<const HeightField<T>> field;
  ASSERT_TRUE(cookHeightField(desc, field).ok());
  const HeightFieldGeometry<T> hf(field, T(1), T(1.25), T(1.25));
  for (const bool smallerFirst : {true, false}) {
    SCOPED_TRACE(smallerFirst);
    World<T> w;
    w.add(smallerFirst ? 3 : 8, hf, Transform<T>());
    w.add(smallerFirst ? 8 : 3, hf, Transform<T>());
    int hits = 0;
    for (int r = 0; r < 400; ++r) {
      const Vec3<T> o(T(rng.uniform(0, 10)), T(rng.uniform(1, 4)), T(rng.uniform(0, 10)));
      const Vec3<T> target(T(rng.uniform(0, 10)), T(rng.uniform(-0.5, 0.5)), T(rng.uniform(0, 10)));
      const Vec3<T> d = (target - o).normalized();
      SceneRaycastHit<T> hit;
      bool has = false;
      ASSERT_NO_FATAL_FAILURE(expectClosestAsTheLoop(w, o, d, T(30), {}, has, hit));
      if (!has) continue;
      ++hits;
      EXPECT_EQ(hit.id, 3u);
    }
    EXPECT_GT(hits, 300);
  }
}

TYPED_TEST(SceneQueries, PlanesAreTestedByEveryQuery) {
  using T = TypeParam;
  Rng rng(49);
  Library<T> lib(rng);
  World<T> w;
  scenetest::populate(w, rng, lib, 50);
  w.add(1000, PlaneGeometry<T>(), Transform<T>(Vec3<T>(T(-5), T(0), T(0))));
  w.add(
      1001, PlaneGeometry<T>(),
      Transform<T>(Vec3<T>(T(0), T(-6), T(0)), Quat<T>(Eigen::AngleAxis<T>(T(1.5707963267948966), Vec3<T>::UnitZ()))));
  expectRaysMatch(w, rng, 100);
  // A box crossing the first plane overlaps it.
  std::vector<InstanceId> ids;
  ASSERT_TRUE(
      w.scene
          .overlapAll(Geometry<T>(BoxGeometry<T>(T(1), T(1), T(1))), Transform<T>(Vec3<T>(T(-5.5), T(30), T(30))), ids)
          .ok());
  EXPECT_EQ(ids, std::vector<InstanceId>{1000});
  // Plane against mesh is not answered by overlap(): those pairs are left out with a Warning naming how many.
  std::vector<ScenePair> pairs;
  const Status s = w.scene.overlappingPairs(pairs);
  ASSERT_TRUE(s.ok());
  std::vector<ScenePair> ref = scenetest::brutePairs(w);
  EXPECT_EQ(pairs, ref);
  std::uint32_t unsupported = 0;
  for (const auto& [id, it] : w.items) {
    for (InstanceId plane : {InstanceId(1000), InstanceId(1001)}) {
      if (id == plane || (id == 1001 && plane == 1000)) continue;
      bool hit = false;
      if (!overlap(w.items.at(plane).geometry, w.items.at(plane).pose, it.geometry, it.pose, hit).ok()) ++unsupported;
    }
  }
  if (unsupported > 0) {
    EXPECT_EQ(s.code, StatusCode::Warning);
    EXPECT_EQ(s.index(), unsupported);
  }
}

TYPED_TEST(SceneQueries, ConcurrentQueriesAnswerAsOneThread) {
  using T = TypeParam;
  Rng rng(50);
  Library<T> lib(rng);
  World<T> w;
  scenetest::populate(w, rng, lib, 150);
  std::vector<Vec3<T>> origins, dirs;
  for (int i = 0; i < 400; ++i) {
    origins.push_back(rng.inBox<T>(15));
    dirs.push_back(rng.unitVector<T>());
  }
  auto castAll = [&](std::vector<T>& out) {
    out.assign(origins.size(), T(-1));
    for (std::size_t i = 0; i < origins.size(); ++i) {
      SceneRaycastHit<T> h;
      bool has = false;
      if (w.scene.raycastClosest(origins[i], dirs[i], T(50), h, has).ok() && has) out[i] = h.hit.distance;
      std::vector<InstanceId> ids;
      (void)w.scene.overlapAll(Geometry<T>(SphereGeometry<T>(T(1))), Transform<T>(origins[i]), ids);
    }
  };
  // The tree grown by insertions, then the one rebuilt top down (rays then walk the 8-wide ray tree).
  for (const bool rebuilt : {false, true}) {
    SCOPED_TRACE(rebuilt);
    if (rebuilt) w.scene.rebuild();
    std::vector<T> serial;
    castAll(serial);
    std::vector<std::vector<T>> results(8);  // eight threads over one scene (the TSan build checks them too)
    std::vector<std::thread> threads;
    for (auto& r : results) threads.emplace_back([&castAll, &r] { castAll(r); });
    for (auto& t : threads) t.join();
    for (const auto& r : results) EXPECT_EQ(r, serial);
  }
}

}  // namespace
}  // namespace gq
