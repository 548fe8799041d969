// The bad-input contract (issue item: "NaN/Inf origin or direction, |dir| off unit by more than 1e-4, negative
// maxDist, maxHits 0, missing output buffer, empty or all-degenerate mesh, malformed mesh file returns a status with
// a message and writes nothing"), for every geometry type, plus the cooking and file-loading entries.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>
#include <unistd.h>

#include "gq/cooking.h"
#include "gq/custom.h"
#include "gq/io.h"
#include "gq/query.h"
#include "gq/shape.h"

namespace {

template <class T> class RaycastBadInput : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(RaycastBadInput, Scalars);

template <class T> constexpr T kNaN = std::numeric_limits<T>::quiet_NaN();
template <class T> constexpr T kInf = std::numeric_limits<T>::infinity();

// A unit sphere through callbacks: a valid custom geometry (only reached by the valid baseline call).
template <class T> class UnitSphereCallbacks : public gq::CustomGeometryCallbacks<T> {
 public:
  const char* name() const override { return "unit sphere"; }
  gq::Bounds3<T> localBounds() const override {
    return gq::Bounds3<T>::fromMinMax(gq::Vec3<T>::Constant(T(-1)), gq::Vec3<T>::Constant(T(1)));
  }
  gq::Vec3<T> support(const gq::Vec3<T>& dir) const override { return dir.normalized(); }
  bool raycast(const gq::Vec3<T>& o, const gq::Vec3<T>& d, T maxDist, gq::HitFlags, gq::RaycastHit<T>& hit) const override {
    const T b = o.dot(d), c = o.squaredNorm() - T(1), disc = b * b - c;
    if (c <= T(0)) {
      hit.distance = T(0);
      hit.flags = gq::HitFlags();
      return true;
    }
    if (disc < T(0) || b > T(0)) return false;
    const T t = -b - std::sqrt(disc);
    if (t > maxDist) return false;
    hit.distance = t;
    hit.flags = gq::HitFlags();
    return true;
  }
};

template <class T> std::vector<gq::Vec3<T>> cubeVertices() {
  std::vector<gq::Vec3<T>> v;
  for (int i = 0; i < 8; ++i) v.emplace_back(T(i & 1 ? 1 : -1), T(i & 2 ? 1 : -1), T(i & 4 ? 1 : -1));
  return v;
}

// Closed cube surface, outward winding: 12 triangles over cubeVertices().
inline std::vector<gq::TriangleIndices> cubeTriangles() {
  return {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
          {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
}

// One valid instance of every geometry type, in GeometryType order.
template <class T> std::vector<gq::Geometry<T>> validGeometries() {
  std::shared_ptr<const gq::ConvexMesh<T>> hull;
  EXPECT_TRUE(gq::cookConvexMesh(cubeVertices<T>(), hull).ok());
  std::shared_ptr<const gq::TriangleMesh<T>> mesh;
  EXPECT_TRUE(gq::cookTriangleMesh(cubeVertices<T>(), cubeTriangles(), mesh).ok());
  gq::HeightFieldDesc<T> desc;
  desc.rows = 3;
  desc.columns = 3;
  desc.heights = {T(0), T(1), T(0), T(1), T(2), T(1), T(0), T(1), T(0)};
  std::shared_ptr<const gq::HeightField<T>> hf;
  EXPECT_TRUE(gq::cookHeightField(desc, hf).ok());
  std::vector<gq::Geometry<T>> out = {
      gq::SphereGeometry<T>(T(1)),
      gq::PlaneGeometry<T>(),
      gq::CapsuleGeometry<T>(T(0.5), T(1)),
      gq::BoxGeometry<T>(T(1), T(2), T(3)),
      gq::ConvexMeshGeometry<T>(hull),
      gq::TriangleMeshGeometry<T>(mesh),
      gq::HeightFieldGeometry<T>(hf, T(1), T(1), T(1)),
      gq::CustomGeometry<T>(std::make_shared<UnitSphereCallbacks<T>>()),
  };
  EXPECT_EQ(out.size(), gq::kGeometryTypeCount);
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_EQ(std::size_t(out[i].type()), i);
  return out;
}

// One raycast call; every argument valid unless a test overrides it.
template <class T> struct RayCall {
  gq::Vec3<T> origin = gq::Vec3<T>(T(-5), T(0.25), T(0.5));
  gq::Vec3<T> dir = gq::Vec3<T>(T(1), T(0), T(0));
  gq::Transform<T> pose;
  T maxDist = T(100);
  gq::HitFlags flags = gq::kDefaultHitFlags;
  std::uint32_t maxHits = 4;
  bool nullBuffer = false;
};

constexpr std::uint32_t kCountSentinel = 0xdeadbeefu;

template <class T> std::vector<gq::RaycastHit<T>> sentinelHits() {
  std::vector<gq::RaycastHit<T>> hits(4);
  for (gq::RaycastHit<T>& h : hits) {
    h.position = gq::Vec3<T>::Constant(T(-123.5));
    h.normal = gq::Vec3<T>::Constant(T(7.25));
    h.distance = T(-99);
    h.flags = gq::HitFlags(std::uint16_t(0xabcd));
    h.faceIndex = 0x12345678u;
    h.u = T(3);
    h.v = T(4);
  }
  return hits;
}

// Target: a gq::Geometry<T> or a prepared gq::Shape<T> (whose mesh raycast calls the mesh kernel directly).
template <class T, class Target>
gq::Status run(const RayCall<T>& call, const Target& target, std::vector<gq::RaycastHit<T>>& hits,
               std::uint32_t& count) {
  return gq::raycast<T>(call.origin, call.dir, target, call.pose, call.maxDist, call.flags, call.maxHits,
                        call.nullBuffer ? nullptr : hits.data(), count);
}

template <class T> std::string nameOf(const gq::Geometry<T>& geom) { return gq::toString(geom.type()); }
template <class T> std::string nameOf(const gq::Shape<T>& shape) {
  return std::string("prepared ") + gq::toString(shape.geometry().type());
}

// The call is rejected with a message and leaves the hit buffer and the count bit-identical.
template <class T, class Target> void expectRejected(const RayCall<T>& call, const Target& target, const std::string& what) {
  std::vector<gq::RaycastHit<T>> hits = sentinelHits<T>();
  std::vector<unsigned char> before(hits.size() * sizeof(gq::RaycastHit<T>));
  std::memcpy(before.data(), static_cast<const void*>(hits.data()), before.size());
  std::uint32_t count = kCountSentinel;
  const gq::Status s = run(call, target, hits, count);
  const std::string where = what + " on " + nameOf(target);
  EXPECT_FALSE(s.ok()) << where;
  EXPECT_STRNE(s.message(), "") << where;
  EXPECT_EQ(count, kCountSentinel) << where;
  EXPECT_EQ(std::memcmp(before.data(), static_cast<const void*>(hits.data()), before.size()), 0)
      << where << ": the hit buffer was written";
}

// Applies `corrupt` to a valid call and expects rejection for every geometry type, as a geometry and as a prepared
// shape; the uncorrupted call is accepted, so the rejection is due to the corrupted argument.
template <class T, class Target, class Corrupt>
void expectRejectedFor(const Target& target, const std::string& what, Corrupt& corrupt) {
  RayCall<T> good;
  std::vector<gq::RaycastHit<T>> hits = sentinelHits<T>();
  std::uint32_t count = kCountSentinel;
  const gq::Status s = run(good, target, hits, count);
  EXPECT_TRUE(s.ok()) << "baseline on " << nameOf(target) << ": " << s.toString();
  RayCall<T> bad = good;
  corrupt(bad);
  expectRejected(bad, target, what);
}

template <class T, class Corrupt> void expectRejectedForEveryType(const std::string& what, Corrupt&& corrupt) {
  for (const gq::Geometry<T>& geom : validGeometries<T>()) {
    expectRejectedFor<T>(geom, what, corrupt);
    gq::Shape<T> shape;
    ASSERT_TRUE(gq::Shape<T>::make(geom, shape).ok()) << nameOf(geom);
    expectRejectedFor<T>(shape, what, corrupt);
  }
}

TYPED_TEST(RaycastBadInput, NonFiniteOriginIsRejectedForEveryGeometryType) {
  using T = TypeParam;
  expectRejectedForEveryType<T>("NaN origin", [](RayCall<T>& c) { c.origin.y() = kNaN<T>; });
  expectRejectedForEveryType<T>("Inf origin", [](RayCall<T>& c) { c.origin.x() = -kInf<T>; });
}

TYPED_TEST(RaycastBadInput, NonFiniteDirectionIsRejectedForEveryGeometryType) {
  using T = TypeParam;
  expectRejectedForEveryType<T>("NaN direction", [](RayCall<T>& c) { c.dir.z() = kNaN<T>; });
  expectRejectedForEveryType<T>("Inf direction", [](RayCall<T>& c) { c.dir.x() = kInf<T>; });
}

TYPED_TEST(RaycastBadInput, DirectionOffUnitByMoreThan1e4IsRejectedForEveryGeometryType) {
  using T = TypeParam;
  expectRejectedForEveryType<T>("|dir| = 1 + 2e-4", [](RayCall<T>& c) { c.dir.x() = T(1.0002); });
  expectRejectedForEveryType<T>("|dir| = 1 - 2e-4", [](RayCall<T>& c) { c.dir.x() = T(0.9998); });
  expectRejectedForEveryType<T>("zero direction", [](RayCall<T>& c) { c.dir.setZero(); });
}

TYPED_TEST(RaycastBadInput, DirectionWithin1e4OfUnitIsAccepted) {
  using T = TypeParam;
  for (const gq::Geometry<T>& geom : validGeometries<T>()) {
    RayCall<T> c;
    c.dir.x() = T(1.00005);
    std::vector<gq::RaycastHit<T>> hits = sentinelHits<T>();
    std::uint32_t count = kCountSentinel;
    EXPECT_TRUE(run(c, geom, hits, count).ok()) << gq::toString(geom.type());
    EXPECT_LE(count, c.maxHits);
  }
}

TYPED_TEST(RaycastBadInput, NegativeOrNaNMaxDistIsRejectedForEveryGeometryType) {
  using T = TypeParam;
  expectRejectedForEveryType<T>("maxDist -1", [](RayCall<T>& c) { c.maxDist = T(-1); });
  expectRejectedForEveryType<T>("maxDist -inf", [](RayCall<T>& c) { c.maxDist = -kInf<T>; });
  expectRejectedForEveryType<T>("maxDist NaN", [](RayCall<T>& c) { c.maxDist = kNaN<T>; });
}

TYPED_TEST(RaycastBadInput, MaxHitsZeroIsRejectedForEveryGeometryType) {
  using T = TypeParam;
  expectRejectedForEveryType<T>("maxHits 0", [](RayCall<T>& c) { c.maxHits = 0; });
  expectRejectedForEveryType<T>("maxHits 0 with meshMultiple", [](RayCall<T>& c) {
    c.maxHits = 0;
    c.flags |= gq::HitFlag::MeshMultiple;
  });
}

TYPED_TEST(RaycastBadInput, MissingHitBufferIsRejectedForEveryGeometryType) {
  using T = TypeParam;
  expectRejectedForEveryType<T>("null hit buffer", [](RayCall<T>& c) { c.nullBuffer = true; });
}

TYPED_TEST(RaycastBadInput, SweepOnlyFlagsAreRejectedForEveryGeometryType) {
  using T = TypeParam;
  expectRejectedForEveryType<T>("mtd flag", [](RayCall<T>& c) { c.flags |= gq::HitFlag::Mtd; });
  expectRejectedForEveryType<T>("preciseSweep flag", [](RayCall<T>& c) { c.flags |= gq::HitFlag::PreciseSweep; });
}

TYPED_TEST(RaycastBadInput, NonFinitePoseIsRejectedForEveryGeometryType) {
  using T = TypeParam;
  expectRejectedForEveryType<T>("NaN pose position", [](RayCall<T>& c) { c.pose.p.x() = kNaN<T>; });
  expectRejectedForEveryType<T>("Inf pose position", [](RayCall<T>& c) { c.pose.p.z() = kInf<T>; });
  expectRejectedForEveryType<T>("NaN pose rotation", [](RayCall<T>& c) { c.pose.q.w() = kNaN<T>; });
}

TYPED_TEST(RaycastBadInput, NonUnitPoseQuaternionIsRejectedForEveryGeometryType) {
  using T = TypeParam;
  expectRejectedForEveryType<T>("|q| = 1.01", [](RayCall<T>& c) { c.pose.q = gq::Quat<T>(T(1.01), T(0), T(0), T(0)); });
  expectRejectedForEveryType<T>("|q| = 0.5", [](RayCall<T>& c) { c.pose.q = gq::Quat<T>(T(0.5), T(0), T(0), T(0)); });
  expectRejectedForEveryType<T>("|q| = 0", [](RayCall<T>& c) { c.pose.q = gq::Quat<T>(T(0), T(0), T(0), T(0)); });
}

// ---- Invalid geometries ----------------------------------------------------------------------------------------

template <class T> std::vector<std::pair<std::string, gq::Geometry<T>>> invalidGeometries() {
  const std::vector<gq::Geometry<T>> valid = validGeometries<T>();
  const auto& convex = valid[4].template get<gq::ConvexMeshGeometry<T>>();
  const auto& mesh = valid[5].template get<gq::TriangleMeshGeometry<T>>();
  const auto& hf = valid[6].template get<gq::HeightFieldGeometry<T>>();
  std::vector<std::pair<std::string, gq::Geometry<T>>> out = {
      {"default geometry", gq::Geometry<T>()},
      {"sphere radius 0", gq::SphereGeometry<T>(T(0))},
      {"sphere radius -1", gq::SphereGeometry<T>(T(-1))},
      {"sphere radius NaN", gq::SphereGeometry<T>(kNaN<T>)},
      {"sphere radius inf", gq::SphereGeometry<T>(kInf<T>)},
      {"capsule radius 0", gq::CapsuleGeometry<T>(T(0), T(1))},
      {"capsule halfHeight -1", gq::CapsuleGeometry<T>(T(1), T(-1))},
      {"capsule halfHeight NaN", gq::CapsuleGeometry<T>(T(1), kNaN<T>)},
      {"box half extent 0", gq::BoxGeometry<T>(T(1), T(0), T(1))},
      {"box half extent -1", gq::BoxGeometry<T>(T(1), T(1), T(-1))},
      {"box half extent NaN", gq::BoxGeometry<T>(kNaN<T>, T(1), T(1))},
      {"convex without cooked mesh", gq::ConvexMeshGeometry<T>(nullptr)},
      {"convex zero scale", gq::ConvexMeshGeometry<T>(convex.mesh, gq::MeshScale<T>(T(0)))},
      {"convex negative scale", gq::ConvexMeshGeometry<T>(convex.mesh, gq::MeshScale<T>(gq::Vec3<T>(T(1), T(-1), T(1))))},
      {"convex NaN scale", gq::ConvexMeshGeometry<T>(convex.mesh, gq::MeshScale<T>(kNaN<T>))},
      {"mesh without cooked mesh", gq::TriangleMeshGeometry<T>(nullptr)},
      {"mesh zero scale", gq::TriangleMeshGeometry<T>(mesh.mesh, gq::MeshScale<T>(gq::Vec3<T>(T(1), T(0), T(1))))},
      {"mesh non-unit scale rotation",
       gq::TriangleMeshGeometry<T>(mesh.mesh, gq::MeshScale<T>(gq::Vec3<T>::Ones(), gq::Quat<T>(T(2), T(0), T(0), T(0))))},
      {"heightfield without cooked data", gq::HeightFieldGeometry<T>(nullptr, T(1), T(1), T(1))},
      {"heightfield heightScale 0", gq::HeightFieldGeometry<T>(hf.heightField, T(0), T(1), T(1))},
      {"heightfield rowScale -1", gq::HeightFieldGeometry<T>(hf.heightField, T(1), T(-1), T(1))},
      {"heightfield columnScale NaN", gq::HeightFieldGeometry<T>(hf.heightField, T(1), T(1), kNaN<T>)},
      {"custom without callbacks", gq::CustomGeometry<T>(nullptr)},
  };
  return out;
}

TYPED_TEST(RaycastBadInput, InvalidGeometrySizesScalesAndMissingCookedDataAreRejected) {
  using T = TypeParam;
  for (const auto& [what, geom] : invalidGeometries<T>()) expectRejected(RayCall<T>(), geom, what);
}

// Cooked data that cookers can never produce (empty): a query must reject it, not read out of bounds or report Ok.
TYPED_TEST(RaycastBadInput, EmptyCookedDataIsRejectedForMeshesAndHeightFields) {
  using T = TypeParam;
  expectRejected(RayCall<T>(), gq::Geometry<T>(gq::ConvexMeshGeometry<T>(std::make_shared<const gq::ConvexMesh<T>>())),
                 "empty convex mesh");
  expectRejected(RayCall<T>(), gq::Geometry<T>(gq::TriangleMeshGeometry<T>(std::make_shared<const gq::TriangleMesh<T>>())),
                 "empty triangle mesh");
  expectRejected(RayCall<T>(),
                 gq::Geometry<T>(gq::HeightFieldGeometry<T>(std::make_shared<const gq::HeightField<T>>(), T(1), T(1), T(1))),
                 "empty heightfield");
}

// ---- Cooking and files ---------------------------------------------------------------------------------------

template <class T> void expectMeshCookRejected(const std::vector<gq::Vec3<T>>& v, const std::vector<gq::TriangleIndices>& t,
                                               gq::StatusCode code, const std::string& what) {
  const auto sentinel = std::make_shared<const gq::TriangleMesh<T>>();
  std::shared_ptr<const gq::TriangleMesh<T>> out = sentinel;
  gq::MeshCookReport report;
  report.inputTriangles = 4242;
  const gq::Status s = gq::cookTriangleMesh(v, t, out, &report);
  EXPECT_EQ(s.code, code) << what << ": " << s.toString();
  EXPECT_STRNE(s.message(), "") << what;
  EXPECT_EQ(out, sentinel) << what << ": output written";
}

TYPED_TEST(RaycastBadInput, CookTriangleMeshRejectsEmptyDegenerateAndOutOfRangeInput) {
  using T = TypeParam;
  expectMeshCookRejected<T>({}, {}, gq::StatusCode::DegenerateMesh, "empty input");
  expectMeshCookRejected<T>(cubeVertices<T>(), {}, gq::StatusCode::DegenerateMesh, "no triangles");
  // Collinear and repeated-vertex triangles only.
  const std::vector<gq::Vec3<T>> line = {gq::Vec3<T>(0, 0, 0), gq::Vec3<T>(1, 1, 1), gq::Vec3<T>(2, 2, 2),
                                         gq::Vec3<T>(0, 1, 0)};
  expectMeshCookRejected<T>(line, {{0, 1, 2}, {3, 3, 0}, {1, 1, 1}}, gq::StatusCode::DegenerateMesh, "all degenerate");
  expectMeshCookRejected<T>(cubeVertices<T>(), {{0, 1, 8}}, gq::StatusCode::InvalidArgument, "index out of range");
  auto nanVertices = cubeVertices<T>();
  nanVertices[3].y() = kNaN<T>;
  expectMeshCookRejected<T>(nanVertices, cubeTriangles(), gq::StatusCode::InvalidArgument, "NaN vertex");
}

TYPED_TEST(RaycastBadInput, CookConvexMeshRejectsTooFewCoplanarAndNonFinitePoints) {
  using T = TypeParam;
  auto check = [](const std::vector<gq::Vec3<T>>& pts, gq::StatusCode code, const std::string& what) {
    const auto sentinel = std::make_shared<const gq::ConvexMesh<T>>();
    std::shared_ptr<const gq::ConvexMesh<T>> out = sentinel;
    const gq::Status s = gq::cookConvexMesh(pts, out);
    EXPECT_EQ(s.code, code) << what << ": " << s.toString();
    EXPECT_STRNE(s.message(), "") << what;
    EXPECT_EQ(out, sentinel) << what << ": output written";
  };
  check({}, gq::StatusCode::DegenerateMesh, "no points");
  check({gq::Vec3<T>(0, 0, 0), gq::Vec3<T>(1, 0, 0), gq::Vec3<T>(0, 1, 0)}, gq::StatusCode::DegenerateMesh, "3 points");
  check({gq::Vec3<T>(0, 0, 0), gq::Vec3<T>(1, 0, 0), gq::Vec3<T>(0, 1, 0), gq::Vec3<T>(1, 1, 0), gq::Vec3<T>(2, 3, 0)},
        gq::StatusCode::DegenerateMesh, "coplanar");
  auto pts = cubeVertices<T>();
  pts[2].x() = kInf<T>;
  check(pts, gq::StatusCode::InvalidArgument, "Inf point");
}

class TempDir {
 public:
  TempDir() {
    path_ = std::filesystem::temp_directory_path() /
            ("gq_bad_input_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::filesystem::path file(const std::string& name, const std::string& content) const {
    const std::filesystem::path p = path_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p;
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

template <class T> void expectLoadRejected(const std::string& path, gq::StatusCode code, const std::string& what) {
  gq::MeshData<T> out;
  out.vertices = {gq::Vec3<T>(1, 2, 3)};
  out.triangles = {{0, 0, 0}};
  const gq::Status s = gq::loadMeshFile(path, out);
  EXPECT_EQ(s.code, code) << what << ": " << s.toString();
  EXPECT_STRNE(s.message(), "") << what;
  ASSERT_EQ(out.vertices.size(), 1u) << what << ": output written";
  EXPECT_EQ(out.vertices[0], gq::Vec3<T>(1, 2, 3)) << what;
  EXPECT_EQ(out.triangles.size(), 1u) << what;
}

TYPED_TEST(RaycastBadInput, LoadMeshFileReportsMissingAndMalformedFiles) {
  using T = TypeParam;
  const TempDir dir;
  expectLoadRejected<T>((dir.path() / "does_not_exist.obj").string(), gq::StatusCode::FileError, "missing file");
  // Binary STL whose header announces 1000 triangles but holds only a few bytes.
  std::string stl(80, 'x');
  const std::uint32_t n = 1000;
  stl.append(reinterpret_cast<const char*>(&n), 4);
  stl.append("trunc");
  expectLoadRejected<T>(dir.file("truncated.stl", stl).string(), gq::StatusCode::ParseError, "truncated STL");
  expectLoadRejected<T>(dir.file("garbage.dae", "<COLLADA><library_geometries><geometry><mesh>oops").string(),
                        gq::StatusCode::ParseError, "broken DAE");
  expectLoadRejected<T>(dir.file("nonsense.obj", "this is not\nan obj file at all\nf 1 2 99999\n").string(),
                        gq::StatusCode::ParseError, "malformed OBJ");
}

}  // namespace
