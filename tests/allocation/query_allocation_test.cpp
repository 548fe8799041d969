// No query allocates: every query family, on valid input and on rejected input (non-finite pose, non-unit
// direction, unsupported pair), runs without a call to operator new (scratch buffers kept per thread aside, see
// allocationsDuring). A Status is a code, a static message and inline
// details, so even a failing query builds no string. This program replaces the global operator new and delete with
// counting versions (its own executable, so the other tests keep the sanitizers' allocators); shapes are cooked
// before counting starts.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "gq/contacts.h"
#include "gq/cooking.h"
#include "gq/custom_shapes.h"
#include "gq/mesh_query.h"
#include "gq/query.h"

namespace {

std::atomic<bool> gCounting{false};
std::atomic<long> gAllocations{0};

void* allocate(std::size_t size, std::size_t alignment, bool nothrow) {
  if (gCounting.load(std::memory_order_relaxed)) gAllocations.fetch_add(1, std::memory_order_relaxed);
  if (size == 0) size = 1;
  void* p = nullptr;
  if (alignment <= alignof(std::max_align_t)) {
    p = std::malloc(size);
  } else if (posix_memalign(&p, alignment, size) != 0) {
    p = nullptr;
  }
  if (!p && !nothrow) throw std::bad_alloc();
  return p;
}

}  // namespace

void* operator new(std::size_t n) { return allocate(n, 0, false); }
void* operator new[](std::size_t n) { return allocate(n, 0, false); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return allocate(n, 0, true); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return allocate(n, 0, true); }
void* operator new(std::size_t n, std::align_val_t a) { return allocate(n, std::size_t(a), false); }
void* operator new[](std::size_t n, std::align_val_t a) { return allocate(n, std::size_t(a), false); }
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return allocate(n, std::size_t(a), true);
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return allocate(n, std::size_t(a), true);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

namespace gq {
namespace {

// The calls to operator new made while `body` runs, after one uncounted run: mesh and heightfield queries and triangle
// contacts keep their scratch buffers per thread (they grow on a thread's first calls, then are reused), so a call
// allocates nothing once a thread has run it.
template <class F> long allocationsDuring(F&& body) {
  body();
  gAllocations.store(0);
  gCounting.store(true);
  body();
  gCounting.store(false);
  return gAllocations.load();
}

template <class T> struct NamedGeometry {
  const char* name;
  Geometry<T> geom;
};

// One geometry of every kind the queries take, cooked up front.
template <class T> std::vector<NamedGeometry<T>> makeShapes() {
  std::vector<NamedGeometry<T>> out;
  out.push_back({"sphere", SphereGeometry<T>(T(0.5))});
  out.push_back({"plane", PlaneGeometry<T>()});
  out.push_back({"capsule", CapsuleGeometry<T>(T(0.3), T(0.6))});
  out.push_back({"box", BoxGeometry<T>(T(0.4), T(0.5), T(0.6))});

  std::vector<Vec3<T>> points;
  for (int i = 0; i < 8; ++i)
    points.emplace_back(T(i & 1 ? 0.5 : -0.5), T(i & 2 ? 0.4 : -0.4), T(i & 4 ? 0.3 : -0.3));
  points.emplace_back(T(0), T(0), T(0.7));
  points.emplace_back(T(0.7), T(0), T(0));
  std::shared_ptr<const ConvexMesh<T>> hull;
  EXPECT_TRUE(cookConvexMesh(points, hull).ok());
  out.push_back({"convex", ConvexMeshGeometry<T>(hull)});

  // A bumpy 8 x 8 grid in the z = 0 plane (128 triangles: several BVH levels).
  const int n = 9;
  std::vector<Vec3<T>> verts;
  std::vector<TriangleIndices> tris;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      verts.emplace_back(T(-2 + 0.5 * i), T(-2 + 0.5 * j), T(0.1 * std::sin(double(i * j))));
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const std::uint32_t a = std::uint32_t(i * n + j), b = a + 1, c = a + std::uint32_t(n), d = c + 1;
      tris.push_back({a, c, b});
      tris.push_back({b, c, d});
    }
  std::shared_ptr<const TriangleMesh<T>> mesh;
  EXPECT_TRUE(cookTriangleMesh(verts, tris, mesh).ok());
  out.push_back({"mesh", TriangleMeshGeometry<T>(mesh)});

  HeightFieldDesc<T> desc;
  desc.rows = 12;
  desc.columns = 12;
  for (std::uint32_t k = 0; k < desc.rows * desc.columns; ++k) desc.heights.push_back(T(0.2 * std::cos(double(k))));
  std::shared_ptr<const HeightField<T>> hf;
  EXPECT_TRUE(cookHeightField(desc, hf).ok());
  out.push_back({"heightfield", HeightFieldGeometry<T>(hf, T(1), T(0.4), T(0.4))});

  CustomGeometry<T> cylinder;
  EXPECT_TRUE(makeCylinder(T(0.4), T(0.5), cylinder).ok());
  out.push_back({"cylinder", cylinder});
  return out;
}

template <class T> Transform<T> rotated(const Vec3<T>& p) {
  return Transform<T>(p, Quat<T>(Eigen::AngleAxis<T>(T(0.3), Vec3<T>(T(1), T(2), T(3)).normalized())));
}

// Poses of geom1 relative to geom0 at the origin: overlapping, near (within GJK's reach) and far.
template <class T> std::vector<Transform<T>> otherPoses() {
  return {rotated<T>(Vec3<T>(T(0.3), T(0.2), T(0.1))), rotated<T>(Vec3<T>(T(1.2), T(0.4), T(0.3))),
          rotated<T>(Vec3<T>(T(6), T(-5), T(4)))};
}

template <class T> Transform<T> nanPose() { return Transform<T>(Vec3<T>(std::numeric_limits<T>::quiet_NaN(), T(0), T(0))); }

template <class T> class QueryAllocation : public ::testing::Test {
 protected:
  std::vector<NamedGeometry<T>> shapes = makeShapes<T>();
  const Transform<T> origin = rotated<T>(Vec3<T>(T(0.05), T(-0.02), T(0.01)));
};

using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(QueryAllocation, Scalars);

std::string where(const char* family, const char* a, const char* b = "") {
  return std::string(family) + " " + a + (*b ? std::string(" / ") + b : std::string());
}

TYPED_TEST(QueryAllocation, StatusFitsSixteenBytes) { EXPECT_LE(sizeof(Status), 16u); }

// The counter sees allocations: an owned message (the loading paths' form) is one, and its copies share it.
TYPED_TEST(QueryAllocation, CounterSeesTheOwnedMessageAllocation) {
  Status owned, copy;
  EXPECT_EQ(allocationsDuring([&] {
              owned = Status::owned(StatusCode::FileError, "cannot open mesh file 'a.obj'");
              copy = owned;
            }),
            1);
  EXPECT_STREQ(copy.message(), "cannot open mesh file 'a.obj'");
}

TYPED_TEST(QueryAllocation, RaycastAllocatesNothing) {
  using T = TypeParam;
  const Vec3<T> origin(T(-5), T(0.1), T(0.05));
  const Vec3<T> dir(T(1), T(0), T(0)), badDir(T(2), T(0), T(0));
  RaycastHit<T> hits[4];
  std::uint32_t count = 0;
  for (const auto& s : this->shapes) {
    for (const auto& dirPose : {this->origin, rotated<T>(Vec3<T>(T(0), T(0), T(-0.5)))}) {
      Status st;
      EXPECT_EQ(allocationsDuring([&] {
                  st = raycast(origin, dir, s.geom, dirPose, T(100), kDefaultHitFlags | HitFlag::MeshMultiple, 4u,
                               hits, count);
                }),
                0)
          << where("raycast", s.name);
      EXPECT_TRUE(st.ok()) << st.toString();
    }
    Status bad;
    EXPECT_EQ(allocationsDuring([&] { bad = raycast(origin, badDir, s.geom, this->origin, T(100), kDefaultHitFlags,
                                                    4u, hits, count); }),
              0)
        << where("raycast (non-unit direction)", s.name);
    EXPECT_EQ(bad.code, StatusCode::InvalidArgument);
  }
}

TYPED_TEST(QueryAllocation, PairQueriesAllocateNothing) {
  using T = TypeParam;
  const Vec3<T> dir(T(1), T(0), T(0));
  for (const auto& a : this->shapes)
    for (const auto& b : this->shapes) {
      for (const Transform<T>& pose1 : otherPoses<T>()) {
        Status st;
        bool flag = false;
        PenetrationResult<T> pen;
        DistanceResult<T> dist;
        SweepHit<T> hit;
        EXPECT_EQ(allocationsDuring([&] { st = overlap(a.geom, this->origin, b.geom, pose1, flag); }), 0)
            << where("overlap", a.name, b.name);
        EXPECT_TRUE(st.ok() || st.code == StatusCode::Unsupported) << st.toString();
        EXPECT_EQ(allocationsDuring([&] { st = computePenetration(pen, a.geom, this->origin, b.geom, pose1); }), 0)
            << where("computePenetration", a.name, b.name);
        EXPECT_TRUE(st.ok() || st.code == StatusCode::Unsupported) << st.toString();
        EXPECT_EQ(allocationsDuring([&] { st = distance(dist, a.geom, this->origin, b.geom, pose1); }), 0)
            << where("distance", a.name, b.name);
        EXPECT_TRUE(st.ok() || st.code == StatusCode::Unsupported) << st.toString();
        EXPECT_EQ(allocationsDuring([&] {
                    st = distanceWithin(dist, flag, T(0.5), a.geom, this->origin, b.geom, pose1);
                  }),
                  0)
            << where("distanceWithin", a.name, b.name);
        EXPECT_TRUE(st.ok() || st.code == StatusCode::Unsupported) << st.toString();
        EXPECT_EQ(allocationsDuring([&] {
                    st = sweep(dir, T(3), a.geom, this->origin, b.geom, pose1, hit, flag,
                               kDefaultHitFlags | HitFlag::Mtd);
                  }),
                  0)
            << where("sweep", a.name, b.name);
        EXPECT_TRUE(st.ok() || st.code == StatusCode::Unsupported) << st.toString();
      }
      // Rejected input: a non-finite pose, a non-unit sweep direction.
      Status bad;
      bool flag = false;
      PenetrationResult<T> pen;
      DistanceResult<T> dist;
      SweepHit<T> hit;
      EXPECT_EQ(allocationsDuring([&] {
                  bad = overlap(a.geom, nanPose<T>(), b.geom, this->origin, flag);
                  EXPECT_EQ(bad.code, StatusCode::InvalidArgument);
                  bad = computePenetration(pen, a.geom, this->origin, b.geom, nanPose<T>());
                  EXPECT_EQ(bad.code, StatusCode::InvalidArgument);
                  bad = distance(dist, a.geom, nanPose<T>(), b.geom, this->origin);
                  EXPECT_EQ(bad.code, StatusCode::InvalidArgument);
                  bad = distanceWithin(dist, flag, T(1), a.geom, this->origin, b.geom, nanPose<T>());
                  EXPECT_EQ(bad.code, StatusCode::InvalidArgument);
                  bad = sweep(Vec3<T>(T(0), T(2), T(0)), T(1), a.geom, this->origin, b.geom, this->origin, hit, flag);
                  EXPECT_EQ(bad.code, StatusCode::InvalidArgument);
                }),
                0)
          << where("pair queries (rejected input)", a.name, b.name);
    }
}

TYPED_TEST(QueryAllocation, PointDistanceAndBoundsAllocateNothing) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  for (const auto& s : this->shapes) {
    Status st;
    PointDistanceResult<T> pd;
    Bounds3<T> bounds;
    for (const Vec3<T>& point : {Vec3<T>(T(0.3), T(2), T(0.1)), Vec3<T>(T(0.05), T(0.02), T(-0.01))}) {
      EXPECT_EQ(allocationsDuring([&] { st = pointDistance(point, s.geom, this->origin, pd); }), 0)
          << where("pointDistance", s.name);
      EXPECT_TRUE(st.ok() || st.code == StatusCode::Unsupported) << st.toString();
    }
    EXPECT_EQ(allocationsDuring([&] { st = computeGeomBounds(bounds, s.geom, this->origin); }), 0)
        << where("computeGeomBounds", s.name);
    EXPECT_TRUE(st.ok()) << st.toString();
    EXPECT_EQ(allocationsDuring([&] {
                st = pointDistance(Vec3<T>(nan, T(0), T(0)), s.geom, this->origin, pd);
                EXPECT_EQ(st.code, StatusCode::InvalidArgument);
                st = computeGeomBounds(bounds, s.geom, nanPose<T>());
                EXPECT_EQ(st.code, StatusCode::InvalidArgument);
              }),
              0)
        << where("pointDistance, computeGeomBounds (rejected input)", s.name);
  }
}

TYPED_TEST(QueryAllocation, MeshQueriesAllocateNothing) {
  using T = TypeParam;
  const TriangleMeshGeometry<T>& mesh = this->shapes[5].geom.template get<TriangleMeshGeometry<T>>();
  const HeightFieldGeometry<T>& hf = this->shapes[6].geom.template get<HeightFieldGeometry<T>>();
  const Transform<T> hfPose = rotated<T>(Vec3<T>(T(-2), T(0), T(-2)));
  Triangle<T> tri;
  std::uint32_t results[8];
  bool overflow = false, found = false;
  std::uint32_t count = 0, iterations = 0;
  PenetrationResult<T> pen;
  long pairs = 0;
  const TrianglePairCallback onPair = [&pairs](std::uint32_t, std::uint32_t) { return ++pairs < 1000; };
  Status st;
  EXPECT_EQ(allocationsDuring([&] {
              st = getTriangle(mesh, this->origin, 3u, tri);
              EXPECT_TRUE(st.ok());
              st = getTriangle(hf, hfPose, 3u, tri);
              EXPECT_TRUE(st.ok());
              st = getTriangle(mesh, this->origin, 100000u, tri);
              EXPECT_EQ(st.code, StatusCode::InvalidArgument);
              st = getTriangle(hf, hfPose, 100000u, tri);
              EXPECT_EQ(st.code, StatusCode::InvalidArgument);
              st = findOverlapTriangleMeshPairs(onPair, mesh, this->origin, mesh, rotated<T>(Vec3<T>(T(0.1), T(0.2),
                                                                                                       T(0))),
                                                found, T(0.01));
              EXPECT_TRUE(st.ok());
              st = findOverlapTriangleMeshPairs(onPair, mesh, this->origin, mesh, nanPose<T>(), found);
              EXPECT_EQ(st.code, StatusCode::InvalidArgument);
            }),
            0)
      << "getTriangle, findOverlapTriangleMeshPairs";
  for (const auto& s : this->shapes) {
    const Transform<T> pose = rotated<T>(Vec3<T>(T(0.2), T(0.1), T(0.15)));
    const bool pagingShape = s.name == std::string("sphere") || s.name == std::string("capsule") ||
                             s.name == std::string("box");
    EXPECT_EQ(allocationsDuring([&] {
                st = findOverlapTriangleMesh(s.geom, pose, mesh, this->origin, results, 8u, 0u, overflow, count);
                EXPECT_EQ(st.ok(), pagingShape) << st.toString();
                st = findOverlapHeightField(s.geom, pose, hf, hfPose, results, 8u, 0u, overflow, count);
                EXPECT_EQ(st.ok(), pagingShape) << st.toString();
                st = findOverlapTriangleMesh(s.geom, nanPose<T>(), mesh, this->origin, results, 8u, 0u, overflow,
                                             count);
                EXPECT_EQ(st.code, StatusCode::InvalidArgument);
              }),
              0)
        << where("findOverlapTriangleMesh, findOverlapHeightField", s.name);
    EXPECT_EQ(allocationsDuring([&] {
                st = computeTriangleMeshPenetration(pen, s.geom, pose, mesh, this->origin, 4u, &iterations);
                EXPECT_TRUE(st.ok() || st.code == StatusCode::Unsupported) << st.toString();
                st = computeHeightFieldPenetration(pen, s.geom, pose, hf, hfPose, 4u, &iterations);
                EXPECT_TRUE(st.ok() || st.code == StatusCode::Unsupported) << st.toString();
                st = computeTriangleMeshPenetration(pen, s.geom, pose, mesh, nanPose<T>());
                EXPECT_FALSE(st.ok());  // InvalidArgument, or Unsupported for a shape it does not take
              }),
              0)
        << where("computeTriangleMeshPenetration, computeHeightFieldPenetration", s.name);
  }
}

TYPED_TEST(QueryAllocation, TriangleContactsAndTriangleSweepsAllocateNothing) {
  using T = TypeParam;
  Triangle<T> tris[4];
  for (int k = 0; k < 4; ++k) {
    const T x = T(-1 + 0.6 * k);
    tris[k].verts[0] = Vec3<T>(x, T(-1), T(-0.2));
    tris[k].verts[1] = Vec3<T>(x + T(1), T(-1), T(-0.2));
    tris[k].verts[2] = Vec3<T>(x, T(1), T(-0.1));
  }
  Triangle<T> nanTri = tris[0];
  nanTri.verts[1].x() = std::numeric_limits<T>::quiet_NaN();
  const Vec3<T> down(T(0), T(0), T(-1));
  for (const auto& s : this->shapes) {
    const Transform<T> pose = rotated<T>(Vec3<T>(T(0.1), T(0), T(0.3)));
    Status st;
    ContactBuffer<T> contacts;
    bool has = false;
    SweepHit<T> hit;
    EXPECT_EQ(allocationsDuring([&] {
                for (const Triangle<T>& tri : tris) {
                  st = generateTriangleContacts(s.geom, pose, tri, 0u, T(0.5), T(0.01), T(1), contacts, has);
                  EXPECT_TRUE(st.ok() || st.code == StatusCode::Unsupported) << st.toString();
                }
                st = generateTriangleContacts(s.geom, pose, nanTri, 0u, T(0.5), T(0.01), T(1), contacts, has);
                EXPECT_TRUE(st.code == StatusCode::InvalidArgument || st.code == StatusCode::Unsupported);
              }),
              0)
        << where("generateTriangleContacts", s.name);
    EXPECT_EQ(allocationsDuring([&] {
                st = sweepTriangles(down, T(2), s.geom, pose, tris, 4u, hit, has);
                EXPECT_TRUE(st.ok() || st.code == StatusCode::Unsupported) << st.toString();
                const std::uint32_t cached = 2;
                st = sweepTriangles(down, T(2), s.geom, pose, tris, 4u, hit, has, kDefaultHitFlags, &cached, T(0.05));
                EXPECT_TRUE(st.ok() || st.code == StatusCode::Unsupported) << st.toString();
                st = sweepTriangles(Vec3<T>(T(0), T(0), T(-3)), T(2), s.geom, pose, tris, 4u, hit, has);
                EXPECT_EQ(st.code, StatusCode::InvalidArgument);
              }),
              0)
        << where("sweepTriangles", s.name);
  }
}

}  // namespace
}  // namespace gq
