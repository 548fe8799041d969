// Batches answer bitwise what the loop of single queries answers, for every thread count and grain; a bad item gets
// its own Status and leaves the others answered; bad arrays are rejected before anything is written.
#include "gq/batch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <string>

#include "scene_test_support.h"

namespace gq {
namespace {

using scenetest::Library;
using scenetest::World;
using test::Rng;

template <class T> class Batch : public ::testing::Test {};
TYPED_TEST_SUITE(Batch, test::Scalars);

// A ray as a caller may store it: the batch reads the two fields in place through strides.
template <class T> struct RayRecord {
  Vec3<T> origin;
  std::uint32_t tag = 0;
  Vec3<T> dir;
};

const BatchSettings kSettings[] = {{1, 64}, {2, 1}, {2, 7}, {8, 5}, {0, 64}};

template <class T> std::vector<RayRecord<T>> randomRays(Rng& rng, std::size_t n, double half) {
  std::vector<RayRecord<T>> rays(n);
  for (std::size_t i = 0; i < n; ++i) {
    rays[i].origin = rng.inBox<T>(half);
    rays[i].dir = rng.unitVector<T>();
    if (i % 2 == 0) rays[i].dir = (rng.inBox<T>(half * 0.2) - rays[i].origin).normalized();
  }
  rays[3].origin.x() = std::numeric_limits<T>::quiet_NaN();  // one bad item
  rays[5].dir *= T(2);                                       // and a non-unit direction
  return rays;
}

// The two fields of the records, read in place.
template <class T> RayBatch<T> rayBatch(const std::vector<RayRecord<T>>& rays, T maxDist) {
  RayBatch<T> b;
  b.origins = StridedArray<Vec3<T>>(&rays[0].origin, rays.size(), sizeof(RayRecord<T>));
  b.unitDirs = StridedArray<Vec3<T>>(&rays[0].dir, rays.size(), sizeof(RayRecord<T>));
  b.maxDist = maxDist;
  return b;
}

template <class T> void expectSameHit(const RaycastHit<T>& a, const RaycastHit<T>& b) {
  EXPECT_EQ(a.distance, b.distance);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.normal, b.normal);
  EXPECT_EQ(a.faceIndex, b.faceIndex);
  EXPECT_EQ(a.flags, b.flags);
}

TYPED_TEST(Batch, RaysAgainstOneMeshEqualSingleRaycastsForAnyThreadCount) {
  using T = TypeParam;
  Rng rng(60);
  const auto ico = meshtest::icosphere<T>(3);
  const Geometry<T> mesh = TriangleMeshGeometry<T>(meshtest::cook(ico.vertices, ico.triangles), MeshScale<T>(T(2)));
  const Transform<T> pose = rng.pose<T>(1);
  const auto rays = randomRays<T>(rng, 700, 4);
  const RayBatch<T> batch = rayBatch(rays, T(10));
  for (const BatchSettings& settings : kSettings) {
    std::vector<RaycastHit<T>> hits(rays.size());
    std::vector<std::uint8_t> has(rays.size(), 7);
    std::vector<Status> statuses(rays.size());
    const Status s = raycastBatch(batch, mesh, pose, hits.data(), has.data(), statuses.data(), settings);
    EXPECT_EQ(s.code, StatusCode::Warning);
    EXPECT_EQ(s.index(), 2u);
    std::size_t hitCount = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      RaycastHit<T> ref;
      std::uint32_t n = 0;
      const Status r = raycast(rays[i].origin, rays[i].dir, mesh, pose, T(10), kDefaultHitFlags, 1u, &ref, n);
      ASSERT_EQ(statuses[i].code, r.code) << i;
      if (!r.ok()) {
        EXPECT_EQ(has[i], 7) << "a failed item leaves its output untouched";
        continue;
      }
      ASSERT_EQ(has[i], n > 0 ? 1 : 0) << i;
      if (n > 0) {
        expectSameHit(hits[i], ref);
        ++hitCount;
      }
    }
    EXPECT_GT(hitCount, rays.size() / 4);
  }
}

// A prepared icosphere mesh of radius 1.
template <class T> Shape<T> icosphereShape() {
  const auto ico = meshtest::icosphere<T>(2);
  Shape<T> mesh;
  EXPECT_TRUE(Shape<T>::make(TriangleMeshGeometry<T>(meshtest::cook(ico.vertices, ico.triangles)), mesh).ok());
  return mesh;
}

TYPED_TEST(Batch, HitColumnsHoldTheClosestHitsFieldByField) {
  using T = TypeParam;
  Rng rng(66);
  const Shape<T> mesh = icosphereShape<T>();
  auto rays = randomRays<T>(rng, 500, 3);
  rays[3].origin.x() = T(0);
  rays[5].dir.normalize();
  const RayBatch<T> batch = rayBatch(rays, T(10));
  std::vector<RaycastHit<T>> hits(rays.size());
  std::vector<std::uint8_t> has(rays.size(), 0);
  ASSERT_TRUE(raycastBatch(batch, mesh, Transform<T>(), hits.data(), has.data()).ok());
  std::vector<std::uint8_t> hit(rays.size(), 7);
  std::vector<T> distance(rays.size()), position(3 * rays.size()), normal(3 * rays.size());
  std::vector<std::int64_t> face(rays.size());
  RayHitColumns<T> columns;
  columns.hit = hit.data();
  columns.distance = distance.data();
  columns.position = position.data();
  columns.normal = normal.data();
  columns.faceIndex = face.data();
  ASSERT_TRUE(raycastBatch(batch, mesh, Transform<T>(), columns).ok());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    ASSERT_EQ(hit[i], has[i]) << i;
    if (has[i]) {
      EXPECT_EQ(distance[i], hits[i].distance);
      EXPECT_EQ(Vec3<T>(position[3 * i], position[3 * i + 1], position[3 * i + 2]), hits[i].position);
      EXPECT_EQ(Vec3<T>(normal[3 * i], normal[3 * i + 1], normal[3 * i + 2]), hits[i].normal);
      EXPECT_EQ(face[i], std::int64_t(hits[i].faceIndex));
    } else {
      EXPECT_EQ(distance[i], std::numeric_limits<T>::infinity());
      EXPECT_EQ(face[i], -1);
      EXPECT_EQ(position[3 * i], T(0));
    }
  }
  // Only the columns asked for are written.
  RayHitColumns<T> facesOnly;
  std::vector<std::int64_t> face2(rays.size(), 9);
  facesOnly.faceIndex = face2.data();
  ASSERT_TRUE(raycastBatch(batch, mesh, Transform<T>(), facesOnly).ok());
  EXPECT_EQ(face2, face);
}

TYPED_TEST(Batch, NormalizedDirectionsAreDividedByTheirLengthAndZeroLengthFailsItsItem) {
  using T = TypeParam;
  Rng rng(67);
  const Shape<T> mesh = icosphereShape<T>();
  std::vector<Vec3<T>> origins, raw, unit;
  for (int i = 0; i < 400; ++i) {
    origins.push_back(rng.inBox<T>(3));
    raw.push_back(rng.unitVector<T>() * T(0.01 + 50.0 * double(i % 7)));
    const Vec3<T>& d = raw.back();
    const T length = std::sqrt(d.x() * d.x() + d.y() * d.y() + d.z() * d.z());
    unit.emplace_back(d.x() / length, d.y() / length, d.z() / length);
  }
  raw[9] = Vec3<T>::Zero();
  unit[9] = Vec3<T>::UnitX();
  for (const BatchSettings& settings : kSettings) {
    RayBatch<T> batch;
    batch.origins = StridedArray<Vec3<T>>(origins.data(), origins.size());
    batch.unitDirs = StridedArray<Vec3<T>>(raw.data(), raw.size());
    batch.maxDist = T(10);
    batch.normalizeDirections = true;
    std::vector<std::int64_t> got(origins.size(), 5), expected(origins.size(), 5);
    std::vector<Status> statuses(origins.size());
    RayHitColumns<T> out;
    out.faceIndex = got.data();
    const Status s = raycastBatch(batch, mesh, Transform<T>(), out, statuses.data(), settings);
    EXPECT_EQ(s.code, StatusCode::Warning);
    EXPECT_EQ(s.index(), 1u);
    EXPECT_EQ(statuses[9].code, StatusCode::InvalidArgument);
    EXPECT_NE(std::string(statuses[9].message()).find("zero-length"), std::string::npos);
    EXPECT_EQ(got[9], 5) << "the failed item is untouched";
    batch.unitDirs = StridedArray<Vec3<T>>(unit.data(), unit.size());
    batch.normalizeDirections = false;
    out.faceIndex = expected.data();
    ASSERT_TRUE(raycastBatch(batch, mesh, Transform<T>(), out, nullptr, settings).ok());
    got[9] = expected[9];
    EXPECT_EQ(got, expected);
  }
}

TYPED_TEST(Batch, RaysIntoASceneEqualSceneRaycastsAndAllHitsCountThenFill) {
  using T = TypeParam;
  Rng rng(61);
  Library<T> lib(rng);
  World<T> w;
  scenetest::populate(w, rng, lib, 150);
  const auto rays = randomRays<T>(rng, 500, 15);
  const RayBatch<T> batch = rayBatch(rays, T(40));
  const HitFlags flags = kDefaultHitFlags | HitFlag::MeshMultiple;
  RayBatch<T> multi = batch;
  multi.hitFlags = flags;
  for (const BatchSettings& settings : kSettings) {
    std::vector<SceneRaycastHit<T>> hits(rays.size());
    std::vector<std::uint8_t> has(rays.size(), 0);
    std::vector<Status> statuses(rays.size());
    const Status s = raycastBatch(batch, w.scene, hits.data(), has.data(), statuses.data(), settings);
    EXPECT_EQ(s.index(), 2u);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      SceneRaycastHit<T> ref;
      bool refHas = false;
      const Status r = w.scene.raycastClosest(rays[i].origin, rays[i].dir, T(40), ref, refHas);
      ASSERT_EQ(statuses[i].code, r.code) << i;
      if (!r.ok()) continue;
      ASSERT_EQ(has[i] != 0, refHas) << i;
      if (refHas) {
        EXPECT_EQ(hits[i].id, ref.id);
        expectSameHit(hits[i].hit, ref.hit);
      }
    }

    // All hits, up to 4 a ray: counts first, then the fill at the offsets.
    std::vector<std::uint32_t> counts(rays.size(), 0);
    SceneHitsOutput<T> countPass;
    countPass.counts = counts.data();
    ASSERT_EQ(raycastAllBatch(multi, w.scene, 4u, countPass, statuses.data(), settings).index(), 2u);
    std::vector<std::uint64_t> offsets(rays.size(), 0);
    std::uint64_t total = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      offsets[i] = total;
      total += counts[i];
    }
    std::vector<SceneRaycastHit<T>> all(total);
    std::vector<std::uint32_t> counts2(rays.size(), 0);
    SceneHitsOutput<T> fillPass;
    fillPass.counts = counts2.data();
    fillPass.offsets = offsets.data();
    fillPass.hits = all.data();
    ASSERT_TRUE(raycastAllBatch(multi, w.scene, 4u, fillPass, statuses.data(), settings).ok());
    EXPECT_EQ(counts2, counts);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      SceneRaycastHit<T> ref[4];
      std::uint32_t n = 0;
      if (!w.scene.raycastAll(rays[i].origin, rays[i].dir, T(40), flags, 4u, ref, n).ok()) continue;
      ASSERT_EQ(counts[i], n) << i;
      for (std::uint32_t k = 0; k < n; ++k) {
        EXPECT_EQ(all[offsets[i] + k].id, ref[k].id);
        EXPECT_EQ(all[offsets[i] + k].hit.distance, ref[k].hit.distance);
      }
    }
  }
}

TYPED_TEST(Batch, PosePairsEqualSingleOverlapDistanceAndPenetration) {
  using T = TypeParam;
  Rng rng(62);
  Shape<T> hull, box;
  ASSERT_TRUE(Shape<T>::make(ConvexMeshGeometry<T>(test::ellipsoidHull<T>(30, rng)), hull).ok());
  ASSERT_TRUE(Shape<T>::make(BoxGeometry<T>(T(0.5), T(0.8), T(0.3)), box).ok());
  const std::size_t n = 600;
  std::vector<Transform<T>> p0(n), p1(n);
  for (std::size_t i = 0; i < n; ++i) {
    p0[i] = rng.pose<T>(1);
    p1[i] = rng.pose<T>(1.5);
  }
  p1[11].q.coeffs() *= T(3);  // a non-unit rotation
  const StridedArray<Transform<T>> a(p0.data(), n), b(p1.data(), n);
  for (const BatchSettings& settings : kSettings) {
    std::vector<std::uint8_t> over(n, 9);
    std::vector<DistanceResult<T>> dist(n);
    std::vector<PenetrationResult<T>> pen(n);
    std::vector<Status> so(n), sd(n), sp(n);
    EXPECT_EQ(overlapBatch(hull, a, box, b, over.data(), so.data(), settings).index(), 1u);
    EXPECT_EQ(distanceBatch(hull, a, box, b, dist.data(), sd.data(), settings).index(), 1u);
    EXPECT_EQ(penetrationBatch(hull, a, box, b, pen.data(), sp.data(), settings).index(), 1u);
    std::size_t overlapping = 0;
    for (std::size_t i = 0; i < n; ++i) {
      bool refOver = false;
      DistanceResult<T> refDist;
      PenetrationResult<T> refPen;
      const Status ro = overlap(hull, p0[i], box, p1[i], refOver);
      const Status rd = distance(refDist, hull, p0[i], box, p1[i]);
      const Status rp = computePenetration(refPen, hull, p0[i], box, p1[i]);
      ASSERT_EQ(so[i].code, ro.code) << i;
      ASSERT_EQ(sd[i].code, rd.code) << i;
      ASSERT_EQ(sp[i].code, rp.code) << i;
      if (!ro.ok()) {
        EXPECT_EQ(over[i], 9);
        continue;
      }
      EXPECT_EQ(over[i] != 0, refOver);
      overlapping += refOver;
      EXPECT_EQ(dist[i].distance, refDist.distance);
      EXPECT_EQ(dist[i].point0, refDist.point0);
      EXPECT_EQ(dist[i].normal, refDist.normal);
      EXPECT_EQ(pen[i].penetrating, refPen.penetrating);
      EXPECT_EQ(pen[i].depth, refPen.depth);
      EXPECT_EQ(pen[i].direction, refPen.direction);
    }
    EXPECT_GT(overlapping, 0u);
    EXPECT_LT(overlapping, n);
  }
}

TYPED_TEST(Batch, PointsEqualSinglePointDistance) {
  using T = TypeParam;
  Rng rng(63);
  Shape<T> hull;
  ASSERT_TRUE(Shape<T>::make(ConvexMeshGeometry<T>(test::ellipsoidHull<T>(40, rng)), hull).ok());
  const Transform<T> pose = rng.pose<T>(1);
  // A flat numpy-like buffer of n x 3 scalars.
  const std::size_t n = 1000;
  std::vector<T> flat(3 * n);
  for (auto& x : flat) x = T(rng.uniform(-3, 3));
  flat[3 * 17 + 1] = std::numeric_limits<T>::infinity();
  const auto points = StridedArray<Vec3<T>>::fromBytes(flat.data(), n, 3 * sizeof(T));
  for (const BatchSettings& settings : kSettings) {
    std::vector<PointDistanceResult<T>> out(n);
    std::vector<Status> st(n);
    EXPECT_EQ(pointDistanceBatch(points, hull, pose, out.data(), st.data(), settings).index(), 1u);
    for (std::size_t i = 0; i < n; ++i) {
      PointDistanceResult<T> ref;
      const Vec3<T> p(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]);
      const Status r = pointDistance(p, hull, pose, ref);
      ASSERT_EQ(st[i].code, r.code) << i;
      if (!r.ok()) continue;
      EXPECT_EQ(out[i].distance, ref.distance);
      EXPECT_EQ(out[i].closestPoint, ref.closestPoint);
    }
    EXPECT_EQ(st[17].code, StatusCode::InvalidArgument);
  }
}

TYPED_TEST(Batch, ResultsAreTheSameBytesForEveryThreadCount) {
  using T = TypeParam;
  Rng rng(64);
  Library<T> lib(rng);
  World<T> w;
  scenetest::populate(w, rng, lib, 100);
  const auto rays = randomRays<T>(rng, 2000, 15);
  const RayBatch<T> batch = rayBatch(rays, T(40));
  std::vector<SceneRaycastHit<T>> first;
  for (const BatchSettings& settings : kSettings) {
    std::vector<SceneRaycastHit<T>> hits(rays.size());
    std::vector<std::uint8_t> has(rays.size(), 0);
    (void)raycastBatch(batch, w.scene, hits.data(), has.data(), nullptr, settings);
    if (first.empty()) {
      first = hits;
      continue;
    }
    for (std::size_t i = 0; i < rays.size(); ++i) {
      EXPECT_EQ(std::memcmp(&hits[i].hit.distance, &first[i].hit.distance, sizeof(T)), 0) << i;
      EXPECT_EQ(hits[i].id, first[i].id) << i;
      EXPECT_EQ(hits[i].hit.position, first[i].hit.position) << i;
    }
  }
}

TYPED_TEST(Batch, BadArraysAreRejectedAndNothingIsWritten) {
  using T = TypeParam;
  Shape<T> ball;
  ASSERT_TRUE(Shape<T>::make(SphereGeometry<T>(T(1)), ball).ok());
  std::vector<Vec3<T>> pts(4, Vec3<T>(T(2), T(0), T(0)));
  std::vector<PointDistanceResult<T>> out(4);
  out[0].distance = T(-7);
  auto expectInvalid = [&](const Status& s, const char* message) {
    EXPECT_EQ(s.code, StatusCode::InvalidArgument);
    EXPECT_STREQ(s.message(), message);
    EXPECT_EQ(out[0].distance, T(-7));
  };
  expectInvalid(pointDistanceBatch(StridedArray<Vec3<T>>(pts.data(), 4, sizeof(T)), ball, Transform<T>(), out.data()),
                "a batch input stride is smaller than the element size");
  expectInvalid(pointDistanceBatch(StridedArray<Vec3<T>>(nullptr, 4), ball, Transform<T>(), out.data()),
                "a batch input array is null but its count is not 0");
  expectInvalid(pointDistanceBatch(
                    StridedArray<Vec3<T>>::fromBytes(reinterpret_cast<const char*>(pts.data()) + 1, 3, sizeof(Vec3<T>)),
                    ball, Transform<T>(), out.data()),
                "a batch input array or stride is not aligned for its element type");
  expectInvalid(pointDistanceBatch(StridedArray<Vec3<T>>(pts.data(), 4), ball, Transform<T>(),
                                   static_cast<PointDistanceResult<T>*>(nullptr)),
                "a batch output array is null");
  expectInvalid(pointDistanceBatch(StridedArray<Vec3<T>>(pts.data(), 4), Shape<T>(), Transform<T>(), out.data()),
                "the shape is empty (not made by Shape::make)");
  std::vector<RaycastHit<T>> hits(4);
  std::vector<std::uint8_t> has(4, 0);
  RayBatch<T> mismatched;
  mismatched.origins = StridedArray<Vec3<T>>(pts.data(), 4);
  mismatched.unitDirs = StridedArray<Vec3<T>>(pts.data(), 3);
  mismatched.maxDist = T(1);
  const Status s = raycastBatch(mismatched, ball, Transform<T>(), hits.data(), has.data());
  EXPECT_EQ(s.code, StatusCode::InvalidArgument);
  EXPECT_STREQ(s.message(), "batch input arrays have different counts");
  // An empty batch is fine with null arrays.
  EXPECT_EQ(
      pointDistanceBatch(StridedArray<Vec3<T>>(), ball, Transform<T>(), static_cast<PointDistanceResult<T>*>(nullptr))
          .code,
      StatusCode::Ok);
  // Every other element: a stride of two elements.
  pts[2] = Vec3<T>(T(0), T(3), T(0));
  ASSERT_TRUE(
      pointDistanceBatch(StridedArray<Vec3<T>>(pts.data(), 2, 2 * sizeof(Vec3<T>)), ball, Transform<T>(), out.data())
          .ok());
  EXPECT_EQ(out[0].distance, T(1));
  EXPECT_EQ(out[1].distance, T(2));
}

}  // namespace
}  // namespace gq
