// Large ray batches against a mesh cast their rays in a coherent order (blocks sorted by batch/ray_order.h's key):
// the order must change no answer, no Status and no untouched output, at any thread count; the key sort must be a
// stable sort by key, and the key must depend only on where a ray enters the target box and its direction.
#include "gq/batch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "batch/ray_order.h"
#include "mesh_test_helpers.h"
#include "test_util.h"

namespace gq {
namespace {

using test::Rng;

template <class T> class BatchRayOrder : public ::testing::Test {};
TYPED_TEST_SUITE(BatchRayOrder, test::Scalars);

// One block of the coherent order (its passes shared by the workers at any thread count), of rays most of which enter
// the mesh's bounds.
constexpr std::size_t kManyRays = 140001;

// Rays from a shell around the origin aimed into a box of half size 1.5 (most hit a radius-2 sphere), every 5th
// with a random direction; a few bad items: NaN and infinite origins, non-unit, NaN and zero directions.
template <class T> void manyRays(Rng& rng, std::vector<Vec3<T>>& origins, std::vector<Vec3<T>>& dirs) {
  origins.resize(kManyRays);
  dirs.resize(kManyRays);
  for (std::size_t i = 0; i < kManyRays; ++i) {
    origins[i] = rng.unitVector<T>() * T(5) + rng.inBox<T>(1);
    dirs[i] = i % 5 == 0 ? rng.unitVector<T>() : Vec3<T>((rng.inBox<T>(1.5) - origins[i]).normalized());
  }
  const T nan = std::numeric_limits<T>::quiet_NaN();
  origins[17].x() = nan;
  origins[40000].z() = std::numeric_limits<T>::infinity();
  dirs[123] *= T(2);
  dirs[65536].y() = nan;
  dirs[69999] = Vec3<T>::Zero();
}

// The hits' distance, position, normal, face and flags, bit for bit (not their padding).
// The rays as a batch with maxDist 20.
template <class T> RayBatch<T> batchOf(const std::vector<Vec3<T>>& origins, const std::vector<Vec3<T>>& dirs) {
  RayBatch<T> batch;
  batch.origins = StridedArray<Vec3<T>>(origins.data(), origins.size());
  batch.unitDirs = StridedArray<Vec3<T>>(dirs.data(), dirs.size());
  batch.maxDist = T(20);
  return batch;
}

template <class T> bool sameBytes(const RaycastHit<T>& a, const RaycastHit<T>& b) {
  return std::memcmp(&a.distance, &b.distance, sizeof(T)) == 0 &&
         std::memcmp(a.position.data(), b.position.data(), sizeof(Vec3<T>)) == 0 &&
         std::memcmp(a.normal.data(), b.normal.data(), sizeof(Vec3<T>)) == 0 && a.faceIndex == b.faceIndex &&
         a.flags == b.flags;
}

// The single query per ray of a batch: its hit, hit flag and Status code; `failed` counts the failed rays.
template <class T> struct SingleRaycasts {
  std::vector<RaycastHit<T>> hits;
  std::vector<std::uint8_t> has;
  std::vector<StatusCode> codes;
  std::size_t failed = 0, hitCount = 0;
  SingleRaycasts(const RayBatch<T>& batch, const Shape<T>& mesh, const Transform<T>& pose)
      : hits(batch.origins.count), has(batch.origins.count, 0), codes(batch.origins.count) {
    for (std::size_t i = 0; i < batch.origins.count; ++i) {
      std::uint32_t n = 0;
      const Status s =
          raycast(batch.origins[i], batch.unitDirs[i], mesh, pose, batch.maxDist, batch.hitFlags, 1u, &hits[i], n);
      codes[i] = s.code;
      has[i] = n > 0 ? 1 : 0;
      failed += s.ok() ? 0 : 1;
      hitCount += n;
    }
  }
  // The batch's outputs against these, item by item (a failed item leaves its outputs untouched: has 7).
  void expectSameAs(const std::vector<RaycastHit<T>>& batchHits, const std::vector<std::uint8_t>& batchHas,
                    const std::vector<Status>& statuses) const {
    for (std::size_t i = 0; i < hits.size(); ++i) {
      ASSERT_EQ(statuses[i].code, codes[i]) << i;
      if (codes[i] != StatusCode::Ok) {
        ASSERT_EQ(batchHas[i], 7) << "a failed item leaves its output untouched: " << i;
        continue;
      }
      ASSERT_EQ(batchHas[i], has[i]) << i;
      if (has[i]) {
        ASSERT_TRUE(sameBytes(batchHits[i], hits[i])) << i;
      }
    }
  }
};

// kManyRays rays (manyRays) at a scaled icosphere mesh at a random pose, both faces, and the single query per ray.
template <class T> struct ManyRaysAtAMesh {
  Rng rng;
  Transform<T> pose;
  Shape<T> mesh;
  std::vector<Vec3<T>> origins, dirs;
  RayBatch<T> batch;
  SingleRaycasts<T> ref;
  explicit ManyRaysAtAMesh(std::uint64_t seed)
      : rng(seed), mesh(scaledIcosphere()), batch(rays()), ref(batch, mesh, pose) {}

 private:
  Shape<T> scaledIcosphere() {
    const auto ico = meshtest::icosphere<T>(3);
    Shape<T> m;
    EXPECT_TRUE(Shape<T>::make(TriangleMeshGeometry<T>(meshtest::cook(ico.vertices, ico.triangles),
                                                       MeshScale<T>(Vec3<T>(T(2), T(1.5), T(1)))),
                               m)
                    .ok());
    pose = rng.pose<T>(1);
    return m;
  }
  RayBatch<T> rays() {
    manyRays(rng, origins, dirs);
    RayBatch<T> b = batchOf(origins, dirs);
    b.hitFlags = kDefaultHitFlags | HitFlag::MeshBothSides;
    return b;
  }
};

TYPED_TEST(BatchRayOrder, LargeMeshBatchesEqualSingleRaycastsBitForBitAtAnyThreadCount) {
  using T = TypeParam;
  const ManyRaysAtAMesh<T> at(4401);
  const RayBatch<T>& batch = at.batch;
  const SingleRaycasts<T>& ref = at.ref;
  ASSERT_EQ(ref.failed, 5u);
  ASSERT_GT(ref.hitCount, kManyRays / 2);

  BatchSettings inputOrder{1, 64};
  inputOrder.coherentRayOrder = false;
  // Scratch kept between calls: the 1-thread call grows one worker's arrays, the later calls reuse and add to them.
  BatchScratch kept;
  const BatchSettings settings[] = {{1, 64}, {2, 64}, {8, 5}, inputOrder,
                                    {1, 64, true, &kept}, {2, 64, true, &kept}, {8, 5, true, &kept}, {1, 64, true, &kept}};
  for (const BatchSettings& setting : settings) {
    SCOPED_TRACE(::testing::Message() << "threads " << setting.threads << " coherent " << setting.coherentRayOrder
                                      << " kept scratch " << (setting.scratch != nullptr));
    std::vector<RaycastHit<T>> hits(kManyRays);
    std::vector<std::uint8_t> has(kManyRays, 7);
    std::vector<Status> statuses(kManyRays);
    const Status s = raycastBatch(batch, at.mesh, at.pose, hits.data(), has.data(), statuses.data(), setting);
    EXPECT_EQ(s.code, StatusCode::Warning);
    EXPECT_EQ(s.index(), 5u);
    ref.expectSameAs(hits, has, statuses);
  }
  EXPECT_GT(kept.bytes(), kManyRays * sizeof(Vec3<T>));  // the rays' copies at least
  kept.release();
  EXPECT_EQ(kept.bytes(), 0u);
}

// A pool failing midway through any pass of the coherent order (its keys, copies, sorts, casts or copy-out) leaves
// the answers of the single queries: the block is cast again in input order.
TYPED_TEST(BatchRayOrder, APoolFailingInAnyPassOfTheOrderLeavesTheSingleRaycastsAnswers) {
  using T = TypeParam;
  const ManyRaysAtAMesh<T> at(4402);
  for (int run = 0; run < 5; ++run) {  // the order's five pooled passes
    SCOPED_TRACE(::testing::Message() << "failing pool run " << run);
    std::vector<RaycastHit<T>> hits(kManyRays);
    std::vector<std::uint8_t> has(kManyRays, 7);
    std::vector<Status> statuses(kManyRays);
    detail::failBatchPoolRun(run);
    const Status s =
        raycastBatch(at.batch, at.mesh, at.pose, hits.data(), has.data(), statuses.data(), BatchSettings{2, 64});
    detail::failBatchPoolRun(-1);
    EXPECT_EQ(s.code, StatusCode::Warning);
    EXPECT_EQ(s.index(), 5u);  // each failed ray counted once
    at.ref.expectSameAs(hits, has, statuses);
  }
}

template <class T> bool sameFields(const RaycastHit<T>& a, const RaycastHit<T>& b) {
  return sameBytes(a, b) && std::memcmp(&a.u, &b.u, sizeof(T)) == 0 && std::memcmp(&a.v, &b.v, sizeof(T)) == 0;
}

// The coherent order casts in key order and copies each hit out in input order: every requested field (and the
// unrequested ones' defaults) must be the single query's, under a mirrored, rotated scale (u and v swapped) and a
// rotated pose, for any hit flags.
TYPED_TEST(BatchRayOrder, EveryHitFlagAndMirroredScaleGiveTheSingleRaycastsFields) {
  using T = TypeParam;
  Rng rng(4407);
  const auto ico = meshtest::icosphere<T>(2);
  const Quat<T> scaleRotation = Quat<T>(T(0.9), T(0.3), T(-0.2), T(0.1)).normalized();
  Shape<T> mesh;
  ASSERT_TRUE(Shape<T>::make(TriangleMeshGeometry<T>(meshtest::cook(ico.vertices, ico.triangles),
                                                     MeshScale<T>(Vec3<T>(T(-2), T(1.5), T(1)), scaleRotation)),
                             mesh)
                  .ok());
  const Transform<T> pose = rng.pose<T>(1);
  constexpr std::size_t n = 40000;  // above the order's 32,768-ray threshold at 1 thread
  std::vector<Vec3<T>> origins(n), dirs(n);
  for (std::size_t i = 0; i < n; ++i) {
    origins[i] = pose.p + rng.unitVector<T>() * T(5);
    dirs[i] = (pose.p + rng.inBox<T>(1.5) - origins[i]).normalized();
  }
  const HitFlags flagSets[] = {HitFlag::Position | HitFlag::Normal | HitFlag::FaceIndex | HitFlag::UV,
                               HitFlags(HitFlag::UV), HitFlags(HitFlag::Position),
                               HitFlag::Normal | HitFlag::MeshBothSides, HitFlag::AnyHit | HitFlag::Normal};
  for (const HitFlags flags : flagSets) {
    SCOPED_TRACE(::testing::Message() << "flags " << flags.bits());
    RayBatch<T> batch;
    batch.origins = StridedArray<Vec3<T>>(origins.data(), n);
    batch.unitDirs = StridedArray<Vec3<T>>(dirs.data(), n);
    batch.maxDist = T(20);
    batch.hitFlags = flags;
    std::vector<RaycastHit<T>> hits(n);
    std::vector<std::uint8_t> has(n, 7);
    ASSERT_TRUE(raycastBatch(batch, mesh, pose, hits.data(), has.data(), nullptr, {1, 64}).ok());
    std::size_t hitCount = 0;
    for (std::size_t i = 0; i < n; ++i) {
      RaycastHit<T> ref;
      std::uint32_t count = 0;
      ASSERT_TRUE(raycast(origins[i], dirs[i], mesh, pose, batch.maxDist, flags, 1u, &ref, count).ok());
      ASSERT_EQ(has[i], count > 0 ? 1 : 0) << i;
      if (count > 0) {
        ASSERT_TRUE(sameFields(hits[i], ref)) << i;
      }
      hitCount += count;
    }
    EXPECT_GT(hitCount, n / 4);
  }
}

// The batch keys rays 8 at a time with AVX2 where the CPU has it, else one at a time: the keys may differ, the
// answers may not.
TYPED_TEST(BatchRayOrder, WideAndScalarRayKeysGiveTheSameBatchBytes) {
  using T = TypeParam;
  if (!detail::rayOrderKeysHaveWidePath()) GTEST_SKIP() << "this build or CPU keys rays one at a time only";
  Rng rng(4406);
  const auto ico = meshtest::icosphere<T>(3);
  Shape<T> mesh;
  ASSERT_TRUE(Shape<T>::make(TriangleMeshGeometry<T>(meshtest::cook(ico.vertices, ico.triangles)), mesh).ok());
  const Transform<T> pose = rng.pose<T>(1);
  std::vector<Vec3<T>> origins, dirs;
  manyRays(rng, origins, dirs);
  RayBatch<T> batch = batchOf(origins, dirs);
  struct Output {
    std::vector<RaycastHit<T>> hits = std::vector<RaycastHit<T>>(kManyRays);
    std::vector<std::uint8_t> has = std::vector<std::uint8_t>(kManyRays, 7);
    std::vector<Status> statuses = std::vector<Status>(kManyRays);
  };
  auto run = [&](bool scalarKeys, Output& out) {
    detail::setRayOrderKeysScalarOnly(scalarKeys);
    const Status s = raycastBatch(batch, mesh, pose, out.hits.data(), out.has.data(), out.statuses.data(), {1, 64});
    detail::setRayOrderKeysScalarOnly(false);
    return s;
  };
  Output wide, scalar;
  const Status sw = run(false, wide), ss = run(true, scalar);
  EXPECT_EQ(sw.index(), 5u);
  EXPECT_EQ(ss.index(), 5u);
  EXPECT_EQ(wide.has, scalar.has);
  std::size_t hits = 0;
  for (std::size_t i = 0; i < kManyRays; ++i) {
    ASSERT_EQ(wide.statuses[i].code, scalar.statuses[i].code) << i;
    if (wide.has[i] == 1) ASSERT_TRUE(sameFields(wide.hits[i], scalar.hits[i])) << i;
    hits += wide.has[i] == 1 ? 1 : 0;
  }
  EXPECT_GT(hits, kManyRays / 4);
}

// keyRays gives every ray a 30-bit key or the miss mark, on both key paths and for any input; rays
// aimed away from the box, or stopping before it, are marked (rays with a NaN may be marked either way: the cast
// fails them).
TEST(RayOrder, KeyRaysMarkRaysMissingTheBoxAndKeyAnyInput) {
  const detail::RayOrderKey<double> key(Bounds3<double>::fromMinMax(Vec3<double>(-1, -1, -1), Vec3<double>(1, 1, 1)));
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  enum Enters { kNo, kYes, kEither };
  struct Ray {
    Vec3<double> origin, dir;
    Enters enters;
  };
  const std::vector<Ray> kinds = {
      {Vec3<double>(0, 0, 5), Vec3<double>(0, 0, -1), kYes},
      {Vec3<double>(0, 0, 5), Vec3<double>(0, 0, 1), kNo},
      {Vec3<double>(0.2, 0.1, 0), Vec3<double>(1, 0, 0), kYes},  // inside
      {Vec3<double>(0, 3, 0), Vec3<double>(1, 0, 0), kNo},
      {Vec3<double>(0, 0, 50), Vec3<double>(0, 0, -1), kNo},  // enters at 49 > maxDist 10
      {Vec3<double>(nan, 0, 0), Vec3<double>(1, 0, 0), kEither},
      {Vec3<double>(0, 0, 5), Vec3<double>(nan, 0, 0), kEither},
      {Vec3<double>(inf, 0, 0), Vec3<double>(-1, 0, 0), kNo},
      {Vec3<double>(0, 0, 5), Vec3<double>(0, 0, 0), kNo},
      {Vec3<double>(1e300, 0, 0), Vec3<double>(-1, 0, 0), kNo},
      {Vec3<double>(-4, 0.5, -0.5), Vec3<double>(1, 0, 0), kYes},
  };
  std::vector<Ray> rays;  // 33: four groups of 8 and one more, each kind in several lanes
  for (int copy = 0; copy < 3; ++copy) rays.insert(rays.end(), kinds.begin(), kinds.end());
  for (const bool scalar : {false, true}) {
    SCOPED_TRACE(scalar ? "scalar keys" : "wide keys");
    detail::setRayOrderKeysScalarOnly(scalar);
    std::vector<std::uint32_t> keys(rays.size() + 1, 7u);
    key.keyRays(StridedArray<Vec3<double>>(&rays[0].origin, rays.size(), sizeof(Ray)),
                StridedArray<Vec3<double>>(&rays[0].dir, rays.size(), sizeof(Ray)), 10.0, keys.data());
    detail::setRayOrderKeysScalarOnly(false);
    EXPECT_EQ(keys.back(), 7u) << "nothing written past the last ray";
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const std::uint32_t k = keys[i];
      if (rays[i].enters != kEither) {
        EXPECT_EQ(k != detail::RayOrderKey<double>::kMisses, rays[i].enters == kYes) << i;
      }
      EXPECT_TRUE(k < (1u << 30) || k == detail::RayOrderKey<double>::kMisses) << i;
    }
  }
}

TYPED_TEST(BatchRayOrder, LargeBatchesOfColumnsAndNormalizedDirectionsEqualTheInputOrder) {
  using T = TypeParam;
  Rng rng(4402);
  const auto ico = meshtest::icosphere<T>(2);
  Shape<T> mesh;
  ASSERT_TRUE(Shape<T>::make(TriangleMeshGeometry<T>(meshtest::cook(ico.vertices, ico.triangles),
                                                     MeshScale<T>(T(2))),
                             mesh)
                  .ok());
  std::vector<Vec3<T>> origins, dirs;
  manyRays(rng, origins, dirs);
  for (std::size_t i = 0; i < kManyRays; i += 3) dirs[i] *= T(3.5);  // lengths the batch divides out
  RayBatch<T> batch;
  batch.origins = StridedArray<Vec3<T>>(origins.data(), origins.size());
  batch.unitDirs = StridedArray<Vec3<T>>(dirs.data(), dirs.size());
  batch.maxDist = T(20);
  batch.normalizeDirections = true;
  struct Columns {
    std::vector<std::uint8_t> hit = std::vector<std::uint8_t>(kManyRays, 9);
    std::vector<T> distance = std::vector<T>(kManyRays, T(-1));
    std::vector<T> position = std::vector<T>(3 * kManyRays, T(-1));
    std::vector<T> normal = std::vector<T>(3 * kManyRays, T(-1));
    std::vector<std::int64_t> face = std::vector<std::int64_t>(kManyRays, -7);
    std::vector<Status> statuses = std::vector<Status>(kManyRays);
  };
  auto run = [&](const BatchSettings& settings, Columns& c) {
    RayHitColumns<T> out;
    out.hit = c.hit.data();
    out.distance = c.distance.data();
    out.position = c.position.data();
    out.normal = c.normal.data();
    out.faceIndex = c.face.data();
    return raycastBatch(batch, mesh, Transform<T>(), out, c.statuses.data(), settings);
  };
  BatchSettings inputOrder{1, 64};
  inputOrder.coherentRayOrder = false;
  Columns expected;
  const Status se = run(inputOrder, expected);
  EXPECT_EQ(se.index(), 4u) << "the non-unit direction is divided by its length";
  for (const BatchSettings& setting : {BatchSettings{1, 64}, BatchSettings{2, 64}, BatchSettings{8, 64}}) {
    Columns c;
    const Status s = run(setting, c);
    EXPECT_EQ(s.code, se.code);
    EXPECT_EQ(s.index(), se.index());
    EXPECT_EQ(c.hit, expected.hit);
    EXPECT_EQ(std::memcmp(c.distance.data(), expected.distance.data(), kManyRays * sizeof(T)), 0);
    EXPECT_EQ(std::memcmp(c.position.data(), expected.position.data(), 3 * kManyRays * sizeof(T)), 0);
    EXPECT_EQ(std::memcmp(c.normal.data(), expected.normal.data(), 3 * kManyRays * sizeof(T)), 0);
    EXPECT_EQ(c.face, expected.face);
    for (std::size_t i = 0; i < kManyRays; ++i) ASSERT_EQ(c.statuses[i].code, expected.statuses[i].code) << i;
  }
}

TEST(RayOrder, SortByKeyIsAStableSortByTheKeyBits) {
  std::mt19937_64 gen(4403);
  for (const std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(1000), std::size_t(70000)}) {
    std::vector<std::uint64_t> items(n), scratch(n);
    for (std::size_t i = 0; i < n; ++i) {
      // Few distinct keys, so that equal keys are common; the payload is the input position.
      const std::uint64_t key = n > 1 && i % 7 == 0 ? std::uint64_t(5) << 20 : gen() % (std::uint64_t(1) << 30);
      items[i] = key << 32 | std::uint64_t(i);
    }
    std::vector<std::uint64_t> expected = items;
    std::stable_sort(expected.begin(), expected.end(),
                     [](std::uint64_t a, std::uint64_t b) { return a >> 32 < b >> 32; });
    const std::uint64_t* sorted = detail::sortByKey(items.data(), scratch.data(), n);
    EXPECT_TRUE(std::equal(expected.begin(), expected.end(), sorted)) << n;
  }
  // Keys sharing every digit but the top one: only that pass runs.
  std::vector<std::uint64_t> items = {std::uint64_t(3) << 52 | 0, std::uint64_t(1) << 52 | 1,
                                     std::uint64_t(2) << 52 | 2};
  std::vector<std::uint64_t> scratch(3);
  const std::uint64_t* sorted = detail::sortByKey(items.data(), scratch.data(), 3);
  EXPECT_EQ(sorted[0] & 0xff, 1u);
  EXPECT_EQ(sorted[1] & 0xff, 2u);
  EXPECT_EQ(sorted[2] & 0xff, 0u);
}

// Rays sharing one bucket of the order (nearly the same line): the bucket is cast in several chunks, bad items
// among them, and every answer is the single query's.
TYPED_TEST(BatchRayOrder, OneBucketOfManyChunksEqualsSingleRaycasts) {
  using T = TypeParam;
  Rng rng(4404);
  const auto ico = meshtest::icosphere<T>(2);
  Shape<T> mesh;
  ASSERT_TRUE(Shape<T>::make(TriangleMeshGeometry<T>(meshtest::cook(ico.vertices, ico.triangles)), mesh).ok());
  constexpr std::size_t n = 40000;  // above the order's 32,768-ray threshold at 1 thread
  std::vector<Vec3<T>> origins(n), dirs(n);
  const Vec3<T> dir = Vec3<T>(T(0.02), T(-0.03), T(-1)).normalized();
  for (std::size_t i = 0; i < n; ++i) {
    origins[i] = Vec3<T>(T(0.05), T(-0.02), T(3)) + rng.inBox<T>(0.001);
    dirs[i] = dir;
  }
  origins[777].y() = std::numeric_limits<T>::quiet_NaN();
  dirs[30001] *= T(1.5);
  RayBatch<T> batch;
  batch.origins = StridedArray<Vec3<T>>(origins.data(), n);
  batch.unitDirs = StridedArray<Vec3<T>>(dirs.data(), n);
  batch.maxDist = T(10);
  std::vector<RaycastHit<T>> hits(n);
  std::vector<std::uint8_t> has(n, 7);
  std::vector<Status> statuses(n);
  const Status s = raycastBatch(batch, mesh, Transform<T>(), hits.data(), has.data(), statuses.data(), {1, 64});
  EXPECT_EQ(s.index(), 2u);
  std::size_t hitCount = 0;
  for (std::size_t i = 0; i < n; ++i) {
    RaycastHit<T> ref;
    std::uint32_t count = 0;
    const Status r = raycast(origins[i], dirs[i], mesh, Transform<T>(), batch.maxDist, batch.hitFlags, 1u, &ref, count);
    ASSERT_EQ(statuses[i].code, r.code) << i;
    if (!r.ok()) {
      ASSERT_EQ(has[i], 7) << i;
      continue;
    }
    ASSERT_EQ(has[i], count > 0 ? 1 : 0) << i;
    if (count > 0) {
      ASSERT_TRUE(sameBytes(hits[i], ref)) << i;
    }
    hitCount += count;
  }
  EXPECT_EQ(hitCount, n - 2);
}

TEST(RayOrder, SortByKeyOfFewerBitsUsesFewerPassesAndStaysStable) {
  std::mt19937_64 gen(4405);
  for (const int bits : {0, 1, 11, 20, 22, 32}) {  // 0: every key 0, the input order
    const std::size_t n = 5000;
    std::vector<std::uint64_t> items(n), scratch(n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint64_t key = (gen() % 97 == 0 ? 3u : gen()) & ((std::uint64_t(1) << bits) - 1);  // bits <= 32
      items[i] = key << 32 | std::uint64_t(i);
    }
    std::vector<std::uint64_t> expected = items;
    std::stable_sort(expected.begin(), expected.end(),
                     [](std::uint64_t a, std::uint64_t b) { return a >> 32 < b >> 32; });
    const std::uint64_t* sorted = detail::sortByKey(items.data(), scratch.data(), n, bits);
    EXPECT_TRUE(std::equal(expected.begin(), expected.end(), sorted)) << bits;
  }
}

TEST(RayOrder, KeyDependsOnTheEntryPointAndTheDirectionOnly) {
  const detail::RayOrderKey<double> key(Bounds3<double>::fromMinMax(Vec3<double>(-1, -2, -3), Vec3<double>(1, 2, 3)));
  const Vec3<double> dir = Vec3<double>(0.3, -0.5, 0.2).normalized();
  const Vec3<double> entry(-0.7, 2, 1.1);  // on the box's y = max face, the ray going in
  const std::uint32_t k = key(entry, dir);
  EXPECT_LT(k, 1u << 30);
  // Any origin before the entry on the ray's line, and any direction length, give the same key.
  EXPECT_EQ(key(entry - 3.0 * dir, dir), k);
  EXPECT_EQ(key(entry - 40.0 * dir, 2.5 * dir), k);
  // Another entry point or another direction changes it.
  EXPECT_NE(key(entry + Vec3<double>(1.5, 0, 0), dir), k);
  EXPECT_NE(key(entry, Vec3<double>(0.3, -0.5, -0.2).normalized()), k);
  // Bad inputs still give a key (the batch fails such rays when it casts them).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_LT(key(Vec3<double>(nan, 0, 0), dir), 1u << 30);
  EXPECT_LT(key(Vec3<double>(inf, 0, 0), Vec3<double>(-1, 0, 0)), 1u << 30);
  EXPECT_LT(key(entry, Vec3<double>(nan, nan, nan)), 1u << 30);
  EXPECT_LT(key(entry, Vec3<double>::Zero()), 1u << 30);
  // A flat box (zero extent on an axis) keys rays too.
  const detail::RayOrderKey<float> flat(Bounds3<float>::fromMinMax(Vec3<float>(0, 0, 0), Vec3<float>(1, 1, 0)));
  EXPECT_LT(flat(Vec3<float>(0.5f, 0.5f, 2), Vec3<float>(0, 0, -1)), 1u << 30);
}

}  // namespace
}  // namespace gq
