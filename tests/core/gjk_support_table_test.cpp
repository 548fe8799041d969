// Support start tables (gjk/support_table.h): every cell stores the exhaustive support vertex of its centre
// direction, a settled cell's vertex is the support of its whole cell, a lookup lands in the cell that contains the
// direction (cube-map cell computed here in long double),
// hull supports through the table stay exact, and the per-mesh registry hands out one table per live mesh, also
// under concurrent first use and when a new mesh reuses a freed mesh's address.
#include <atomic>
#include <thread>

#include "gjk_test_shapes.h"

#include "gjk/gjk.h"
#include "gjk/support_map.h"
#include "gjk/support_table.h"
#include "gq/cooking.h"

namespace {

using namespace gjktest;
using gq::detail::SupportStartTable;

template <class T> class GjkSupportTable : public ::testing::Test {};
TYPED_TEST_SUITE(GjkSupportTable, Scalars);

template <class T> std::shared_ptr<const gq::ConvexMesh<T>> cookedHull(Rng& rng, int n) {
  std::shared_ptr<const gq::ConvexMesh<T>> hull;
  EXPECT_TRUE(gq::cookConvexMesh(pointsOnEllipsoid<T>(rng, n, Eigen::Vector3d(1, 0.8, 0.6)), hull).ok());
  return hull;
}

template <class T> L exhaustiveMaximum(const gq::ConvexMesh<T>& hull, const VL& d) {
  L best = -std::numeric_limits<L>::infinity();
  for (const auto& v : hull.vertices) best = std::max(best, toL(v).dot(d));
  return best;
}

// A direction of face f at cube-map coordinates (u, v) in [-1, 1], unnormalised, written from the cube-map
// definition: face 2a + s is axis a with sign (-1)^s, the other two axes in increasing order carry u and v.
VL faceDirection(std::uint32_t face, L u, L v) {
  const int axis = int(face / 2);
  const std::array<int, 2> others = axis == 0 ? std::array<int, 2>{1, 2} : axis == 1 ? std::array<int, 2>{0, 2} : std::array<int, 2>{0, 1};
  VL d;
  d[axis] = face % 2 == 0 ? 1 : -1;
  d[others[0]] = u;
  d[others[1]] = v;
  return d;
}

// Cell centre of (face, i, j) of a table with k cells a side (unit).
VL cellCentre(std::uint32_t face, std::uint32_t i, std::uint32_t j, std::uint32_t k) {
  return faceDirection(face, L(2 * i + 1) / L(k) - 1, L(2 * j + 1) / L(k) - 1).normalized();
}

// Calls visit(face, i, j) for every cell of a table with k cells a side; stops at the first fatal failure (an ASSERT
// in visit ends the walk as it would end a loop in the test body).
template <class Visit> void forEachCell(std::uint32_t k, Visit visit) {
  for (std::uint32_t f = 0; f < 6; ++f)
    for (std::uint32_t i = 0; i < k; ++i)
      for (std::uint32_t j = 0; j < k; ++j) {
        visit(f, i, j);
        if (::testing::Test::HasFatalFailure()) return;
      }
}

// Tolerance of a support value compared in long double: rounding of the vertices' dot products in T.
template <class T> L supportSlack() { return std::is_same_v<T, float> ? L(1e-5) : L(1e-13); }

TYPED_TEST(GjkSupportTable, EveryCellStoresTheExhaustiveSupportOfItsCentreDirection) {
  using T = TypeParam;
  Rng rng(401);
  for (const int n : {9, 30, 100, 300}) {
    const auto hull = cookedHull<T>(rng, n);
    ASSERT_TRUE(hull);
    const SupportStartTable<T> table(*hull);
    const std::uint32_t k = table.cellsPerSide();
    ASSERT_EQ(k, gq::detail::kStartTableCells);
    forEachCell(k, [&](std::uint32_t f, std::uint32_t i, std::uint32_t j) {
      const VL d = cellCentre(f, i, j, k);
      const std::uint32_t v = table.startOfCell(f, i, j);
      ASSERT_LT(v, hull->vertices.size());
      EXPECT_GE(toL(hull->vertices[v]).dot(d), exhaustiveMaximum(*hull, d) - supportSlack<T>())
          << "hull of " << n << " points, cell " << f << "/" << i << "/" << j;
    });
    if (this->HasFatalFailure()) return;
  }
}

// The cell of d in long double: face of the largest |component|, then the two others over it cut into k slabs.
struct Cell {
  std::uint32_t face, i, j;
  bool nearBoundary;  // within rounding of a cell or face boundary: either neighbour is a correct answer
};
Cell cellOf(const VL& d, std::uint32_t k) {
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(d[a]) > std::abs(d[axis])) axis = a;
  const std::array<int, 2> others = axis == 0 ? std::array<int, 2>{1, 2} : axis == 1 ? std::array<int, 2>{0, 2} : std::array<int, 2>{0, 1};
  const L m = std::abs(d[axis]);
  Cell c{std::uint32_t(2 * axis + (d[axis] < 0)), 0, 0, false};
  const auto slab = [&](L t, std::uint32_t& index) {
    const L x = (t / m + 1) * L(k) / 2;  // in [0, k]
    index = std::min<std::uint32_t>(k - 1, std::uint32_t(std::max<L>(0, std::floor(x))));
    c.nearBoundary = c.nearBoundary || std::abs(x - std::round(x)) < 1e-4L;
  };
  slab(d[others[0]], c.i);
  slab(d[others[1]], c.j);
  for (const int o : others) c.nearBoundary = c.nearBoundary || std::abs(std::abs(d[o]) - m) < 1e-4L * m;
  return c;
}

TYPED_TEST(GjkSupportTable, LookupReturnsTheVertexOfTheCellContainingTheDirection) {
  using T = TypeParam;
  Rng rng(402);
  const auto hull = cookedHull<T>(rng, 100);
  ASSERT_TRUE(hull);
  const SupportStartTable<T> table(*hull);
  int checked = 0;
  for (int s = 0; s < 20000; ++s) {
    // Lengths far from 1 too: the lookup must only depend on the direction.
    const double length = std::pow(10.0, rng.uniform(-20, 20));
    const Eigen::Vector3d u = rng.unit();
    const gq::Vec3<T> d = (u * length).cast<T>();
    const Cell c = cellOf(toL(d), table.cellsPerSide());
    if (c.nearBoundary) continue;
    ++checked;
    ASSERT_EQ(table.lookup(d), table.startOfCell(c.face, c.i, c.j)) << "direction " << u.transpose() << " x " << length;
  }
  EXPECT_GT(checked, 19000);
}

// A settled cell answers its vertex without a neighbour scan: that must be what the climb from it answers, for every
// direction the lookup places in the cell (corners and edges of the cell included, where rounding decides the cell),
// and the exhaustive support. Fails if settling ignores a neighbour or a corner, or if its margin is dropped.
TYPED_TEST(GjkSupportTable, ASettledCellsVertexIsTheClimbsAndTheExhaustiveSupportOfEveryDirectionInIt) {
  using T = TypeParam;
  Rng rng(406);
  for (const int n : {12, 30, 100, 300}) {
    const auto hull = cookedHull<T>(rng, n);
    ASSERT_TRUE(hull);
    const SupportStartTable<T> table(*hull);
    const std::uint32_t k = table.cellsPerSide();
    int settledCells = 0, settledLookups = 0;
    forEachCell(k, [&](std::uint32_t f, std::uint32_t i, std::uint32_t j) {
      settledCells += table.cellSettled(f, i, j);
      for (int sample = 0; sample < 12; ++sample) {
        // The four corners, then points of the cell's edges and interior.
        const L a = sample < 4 ? L(sample / 2) : sample < 8 ? L(rng.uniform(0, 1)) * (sample % 2) : L(rng.uniform(0, 1));
        const L b = sample < 4 ? L(sample % 2) : sample < 8 ? L(sample % 4 < 2) : L(rng.uniform(0, 1));
        const VL dl = faceDirection(f, (L(2 * i) + 2 * a) / L(k) - 1, (L(2 * j) + 2 * b) / L(k) - 1);
        const gq::Vec3<T> d = (dl * L(rng.uniform(0.01, 100))).template cast<T>();
        const std::uint32_t entry = table.lookupEntry(d);
        if (!SupportStartTable<T>::settled(entry)) continue;
        ++settledLookups;
        const std::uint32_t v = SupportStartTable<T>::vertexOf(entry);
        ASSERT_EQ(table.climb(*hull, d, v), v) << "hull of " << n << ", cell " << f << "/" << i << "/" << j;
        ASSERT_GE(toL(hull->vertices[v]).dot(toL(d)), exhaustiveMaximum(*hull, toL(d)) - supportSlack<T>() * toL(d).norm())
            << "hull of " << n << ", cell " << f << "/" << i << "/" << j;
      }
    });
    if (this->HasFatalFailure()) return;
    // Most cells of these hulls are settled (their speed depends on it).
    EXPECT_GT(settledCells, int(6 * k * k) / 2) << "hull of " << n;
    EXPECT_GT(settledLookups, 0);
  }
}

TYPED_TEST(GjkSupportTable, LookupOfZeroOrNonFiniteDirectionIsVertexZero) {
  using T = TypeParam;
  Rng rng(403);
  const auto hull = cookedHull<T>(rng, 30);
  ASSERT_TRUE(hull);
  const SupportStartTable<T> table(*hull);
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  for (const gq::Vec3<T>& d : {gq::Vec3<T>(0, 0, 0), gq::Vec3<T>(nan, 1, 0), gq::Vec3<T>(1, nan, 0), gq::Vec3<T>(0, 0, nan),
                               gq::Vec3<T>(inf, 1, 0), gq::Vec3<T>(1, -inf, 2), gq::Vec3<T>(nan, nan, nan)})
    EXPECT_EQ(table.lookup(d), 0u) << d.transpose();
  // A major component so small that k/2 over it overflows: still a cell of the right face, no overflowing conversion.
  const T tiny = std::numeric_limits<T>::denorm_min();
  for (const gq::Vec3<T>& d : {gq::Vec3<T>(tiny, 0, 0), gq::Vec3<T>(-tiny, tiny, 0), gq::Vec3<T>(0, 0, -tiny)})
    EXPECT_LT(table.lookup(d), hull->vertices.size()) << d.transpose();
}

TYPED_TEST(GjkSupportTable, HullSupportThroughTheTableIsExactUnderScaleAndPose) {
  using T = TypeParam;
  Rng rng(404);
  for (const int n : {30, 300}) {
    const auto hull = cookedHull<T>(rng, n);
    ASSERT_TRUE(hull);
    for (int g = 0; g < 20; ++g) {
      const gq::MeshScale<T> scale = randomScale<T>(rng, 0.2, 3);
      const gq::Transform<T> pose = randomPose<T>(rng, 5);
      const gq::Geometry<T> geom(gq::ConvexMeshGeometry<T>(hull, scale));
      const auto shape = gq::detail::makeConvexShape(geom, pose);
      ASSERT_NE(shape.startTable, nullptr);
      // World vertices in long double, the way the reference sees the shape.
      std::vector<VL> world;
      const Eigen::Matrix<L, 3, 3> s = scale.toMatrix().template cast<L>();
      for (const auto& v : hull->vertices) world.push_back(toL(pose).apply(s * toL(v)));
      for (int k = 0; k < 200; ++k) {
        const VL d = toL(gq::Vec3<T>(rng.unit().cast<T>()));
        L best = -std::numeric_limits<L>::infinity();
        for (const auto& w : world) best = std::max(best, w.dot(d));
        const L got = toL(shape.support(d.template cast<T>())).dot(d);
        ASSERT_NEAR(double(got), double(best), double(supportSlack<T>() * 100)) << "hull " << n << " geometry " << g;
      }
    }
  }
}

// Packed climb (neighbour coordinates in padded SIMD runs): from every start vertex it must reach a vertex whose d.v
// equals the exhaustive maximum bit for bit (values are formed as dot3 forms them), also where ties are whole faces.
TYPED_TEST(GjkSupportTable, PackedClimbReachesTheExhaustiveMaximumFromAnyStart) {
  using T = TypeParam;
  Rng rng(407);
  std::vector<std::vector<gq::Vec3<T>>> clouds;
  for (const int n : {9, 13, 30, 100}) clouds.push_back(pointsOnEllipsoid<T>(rng, n, Eigen::Vector3d(1, 0.8, 0.6)));
  std::vector<gq::Vec3<T>> prism;  // two hexagons: axis directions make faces and edges maximal
  for (int k = 0; k < 6; ++k)
    for (const double z : {-0.5, 0.5}) prism.emplace_back(T(std::cos(k * M_PI / 3)), T(std::sin(k * M_PI / 3)), T(z));
  clouds.push_back(prism);
  for (const auto& pts : clouds) {
    std::shared_ptr<const gq::ConvexMesh<T>> hull;
    ASSERT_TRUE(gq::cookConvexMesh(pts, hull).ok());
    const SupportStartTable<T> table(*hull);
    ASSERT_TRUE(table.hasClimbGraph());
    const auto n = static_cast<std::uint32_t>(hull->vertices.size());
    std::vector<gq::Vec3<T>> dirs;
    for (int i = 0; i < 500; ++i) dirs.push_back(rng.unit().cast<T>());
    for (int k = 0; k < 3; ++k)
      for (const T sgn : {T(-1), T(1)}) dirs.push_back(sgn * gq::Vec3<T>::Unit(k));
    for (const auto& d : dirs) {
      T best = -std::numeric_limits<T>::infinity();
      for (const auto& v : hull->vertices) best = std::max(best, gq::detail::dot3(v, d));
      for (std::uint32_t start = 0; start < n; ++start) {
        const std::uint32_t v = table.climb(*hull, d, start);
        ASSERT_LT(v, n);
        ASSERT_EQ(gq::detail::dot3(hull->vertices[v], d), best) << "hull of " << n << " vertices from " << start;
      }
    }
  }
}

TYPED_TEST(GjkSupportTable, PackedClimbStopsAtTheStartForNonFiniteDirections) {
  using T = TypeParam;
  Rng rng(408);
  const auto hull = cookedHull<T>(rng, 30);
  ASSERT_TRUE(hull);
  const SupportStartTable<T> table(*hull);
  const T nan = std::numeric_limits<T>::quiet_NaN();
  for (std::uint32_t start = 0; start < hull->vertices.size(); ++start) {
    EXPECT_EQ(table.climb(*hull, gq::Vec3<T>(nan, 0, 1), start), start);
    EXPECT_EQ(table.climb(*hull, gq::Vec3<T>(0, 0, 0), start), start);
  }
}

TYPED_TEST(GjkSupportTable, SmallHullsGetNoTable) {
  using T = TypeParam;
  std::vector<gq::Vec3<T>> cube;
  for (int c = 0; c < 8; ++c) cube.emplace_back(T(c & 1 ? 1 : -1), T(c & 2 ? 1 : -1), T(c & 4 ? 1 : -1));
  std::shared_ptr<const gq::ConvexMesh<T>> hull;
  ASSERT_TRUE(gq::cookConvexMesh(cube, hull).ok());
  ASSERT_EQ(hull->vertices.size(), 8u);
  EXPECT_EQ(gq::detail::supportStartTable(hull), nullptr);
  EXPECT_EQ(gq::detail::supportStartTable(std::shared_ptr<const gq::ConvexMesh<T>>()), nullptr);
}

TYPED_TEST(GjkSupportTable, ConcurrentFirstUseOfOneMeshSharesOneTable) {
  using T = TypeParam;
  Rng rng(405);
  for (int round = 0; round < 10; ++round) {
    const auto hull = cookedHull<T>(rng, 100);
    ASSERT_TRUE(hull);
    constexpr int kThreads = 8;
    std::array<const SupportStartTable<T>*, kThreads> seen{};
    std::atomic<int> ready{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
      threads.emplace_back([&, t] {
        ++ready;
        while (ready.load() < kThreads) {}
        seen[t] = gq::detail::supportStartTable(hull);
      });
    for (auto& th : threads) th.join();
    for (int t = 0; t < kThreads; ++t) EXPECT_EQ(seen[t], seen[0]) << "round " << round << " thread " << t;
    ASSERT_NE(seen[0], nullptr);
    EXPECT_EQ(gq::detail::supportStartTable(hull), seen[0]);
  }
}

// Threads meeting a freshly cooked hull at once (the table is built under the registry's lock by one of them) get
// the bits a single thread gets afterwards, for gq::overlap and gq::distance on the same poses.
TYPED_TEST(GjkSupportTable, ConcurrentQueriesOnAFreshHullMatchTheSingleThreadedBits) {
  using T = TypeParam;
  Rng rng(409);
  const auto hull = cookedHull<T>(rng, 100);
  ASSERT_TRUE(hull);
  const gq::Geometry<T> g{gq::ConvexMeshGeometry<T>(hull)};
  std::vector<gq::Transform<T>> p0, p1;
  for (int i = 0; i < 100; ++i) {
    p0.push_back(randomPose<T>(rng, 1));
    p1.push_back(randomPose<T>(rng, 1));
  }
  const auto run = [&](std::vector<T>& out) {
    for (std::size_t i = 0; i < p0.size(); ++i) {
      bool hit = false;
      gq::DistanceResult<T> d;
      out.push_back(gq::overlap(g, p0[i], g, p1[i], hit).ok() && hit ? T(1) : T(0));
      out.push_back(gq::distance(d, g, p0[i], g, p1[i]).ok() ? d.distance : T(-1000));
    }
  };
  constexpr int kThreads = 8;
  std::vector<std::vector<T>> results(kThreads);
  std::atomic<int> ready{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      ++ready;
      while (ready.load() < kThreads) {}
      run(results[t]);
    });
  for (auto& th : threads) th.join();
  std::vector<T> single;
  run(single);
  for (int t = 0; t < kThreads; ++t) EXPECT_EQ(results[t], single) << "thread " << t;
}

TYPED_TEST(GjkSupportTable, NewMeshAtAFreedMeshAddressGetsItsOwnTable) {
  using T = TypeParam;
  Rng rng(406);
  for (int round = 0; round < 40; ++round) {
    // Same vertex count every round, so the allocator tends to hand out the freed addresses again.
    const auto hull = cookedHull<T>(rng, 40);
    ASSERT_TRUE(hull);
    const SupportStartTable<T>* table = gq::detail::supportStartTable(hull);
    ASSERT_NE(table, nullptr);
    const std::uint32_t k = table->cellsPerSide();
    forEachCell(k, [&](std::uint32_t f, std::uint32_t i, std::uint32_t j) {
      const VL d = cellCentre(f, i, j, k);
      const std::uint32_t v = table->startOfCell(f, i, j);
      ASSERT_LT(v, hull->vertices.size());
      ASSERT_GE(toL(hull->vertices[v]).dot(d), exhaustiveMaximum(*hull, d) - supportSlack<T>()) << "round " << round;
    });
    if (this->HasFatalFailure()) return;
  }
}

}  // namespace
