// Heightfield cooking, getTriangle and bounds (gq/cooking.h layout; spec "Geometry": triangle index = face index).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "bounds/bounds.h"
#include "gq/cooking.h"
#include "gq/mesh_query.h"

namespace {

template <class T> class HeightFieldCook : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(HeightFieldCook, Scalars);

template <class T> gq::HeightFieldDesc<T> rampDesc(std::uint32_t rows, std::uint32_t columns) {
  gq::HeightFieldDesc<T> d;
  d.rows = rows;
  d.columns = columns;
  for (std::uint32_t r = 0; r < rows; ++r)
    for (std::uint32_t c = 0; c < columns; ++c) d.heights.push_back(T(int(r * 3 + c * 7) % 11) - T(4));
  return d;
}

template <class T> void expectRejected(const gq::HeightFieldDesc<T>& d) {
  auto sentinel = std::make_shared<const gq::HeightField<T>>();
  std::shared_ptr<const gq::HeightField<T>> out = sentinel;
  const gq::Status s = gq::cookHeightField(d, out);
  EXPECT_EQ(s.code, gq::StatusCode::InvalidArgument);
  EXPECT_STRNE(s.message(), "");
  EXPECT_EQ(out, sentinel) << "a failed cook must not write the output";
}

TYPED_TEST(HeightFieldCook, FewerThanTwoRowsOrColumnsIsRejected) {
  using T = TypeParam;
  expectRejected(rampDesc<T>(1, 5));
  expectRejected(rampDesc<T>(5, 1));
  expectRejected(rampDesc<T>(0, 0));
}

TYPED_TEST(HeightFieldCook, HeightCountNotRowsTimesColumnsIsRejected) {
  using T = TypeParam;
  auto d = rampDesc<T>(4, 5);
  d.heights.pop_back();
  expectRejected(d);
  d.heights.push_back(T(0));
  d.heights.push_back(T(0));
  expectRejected(d);
}

TYPED_TEST(HeightFieldCook, NonFiniteHeightIsRejected) {
  using T = TypeParam;
  for (T bad : {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                -std::numeric_limits<T>::infinity()}) {
    auto d = rampDesc<T>(4, 5);
    d.heights[7] = bad;
    expectRejected(d);
  }
}

TYPED_TEST(HeightFieldCook, HoleIndexOutOfRangeIsRejected) {
  using T = TypeParam;
  auto d = rampDesc<T>(4, 5);
  d.holes = {0, 3 * 4};  // 12 cells: index 12 is one past the end
  expectRejected(d);
}

TYPED_TEST(HeightFieldCook, AbsurdSizeIsRejectedBeforeReadingHeights) {
  using T = TypeParam;
  gq::HeightFieldDesc<T> d;
  d.rows = 1u << 15;
  d.columns = (1u << 14) + 1;  // rows * columns > kMaxHeightFieldSamples = 2^28
  expectRejected(d);
  d.rows = 0xffffffffu;
  d.columns = 0xffffffffu;  // the product overflows 32 bits
  expectRejected(d);
}

TYPED_TEST(HeightFieldCook, CookStoresRangesHolesAndBlockRanges) {
  using T = TypeParam;
  const std::uint32_t rows = 21, columns = 11;  // 20 x 10 cells: 3 x 2 blocks of 8, the last ones partial
  auto d = rampDesc<T>(rows, columns);
  d.holes = {5, 17, 5};
  std::shared_ptr<const gq::HeightField<T>> hf;
  ASSERT_TRUE(gq::cookHeightField(d, hf).ok());
  EXPECT_EQ(hf->rows, rows);
  EXPECT_EQ(hf->columns, columns);
  EXPECT_EQ(hf->minHeight, T(-4));
  EXPECT_EQ(hf->maxHeight, T(6));
  ASSERT_EQ(hf->hole.size(), 200u);
  for (std::uint32_t cell = 0; cell < 200; ++cell) EXPECT_EQ(hf->hole[cell] != 0, cell == 5 || cell == 17);
  EXPECT_TRUE(hf->isHole(0, 5));
  EXPECT_TRUE(hf->isHole(1, 7));
  ASSERT_EQ(hf->blockRows, 3u);
  ASSERT_EQ(hf->blockColumns, 2u);
  // Brute force: every block's range over the samples of its cells' corners.
  for (std::uint32_t br = 0; br < 3; ++br)
    for (std::uint32_t bc = 0; bc < 2; ++bc) {
      T lo = std::numeric_limits<T>::max(), hi = -lo;
      for (std::uint32_t r = 0; r < rows - 1; ++r)
        for (std::uint32_t c = 0; c < columns - 1; ++c) {
          if (r / 8 != br || c / 8 != bc) continue;
          for (std::uint32_t s : {r * columns + c, r * columns + c + 1, (r + 1) * columns + c, (r + 1) * columns + c + 1}) {
            lo = std::min(lo, d.heights[s]);
            hi = std::max(hi, d.heights[s]);
          }
        }
      EXPECT_EQ(hf->blockMin[br * 2 + bc], lo) << br << "," << bc;
      EXPECT_EQ(hf->blockMax[br * 2 + bc], hi) << br << "," << bc;
    }
}

TYPED_TEST(HeightFieldCook, GetTriangleFollowsTheDocumentedLayoutInWorldSpace) {
  using T = TypeParam;
  const std::uint32_t rows = 4, columns = 5;
  auto d = rampDesc<T>(rows, columns);
  std::shared_ptr<const gq::HeightField<T>> hf;
  ASSERT_TRUE(gq::cookHeightField(d, hf).ok());
  const gq::HeightFieldGeometry<T> g(hf, T(0.5), T(2), T(0.25));
  const gq::Transform<T> pose(gq::Vec3<T>(1, -2, 3), gq::Quat<T>(Eigen::AngleAxis<T>(T(0.7), gq::Vec3<T>(1, 2, 3).normalized())));
  for (std::uint32_t tri = 0; tri < 2 * (rows - 1) * (columns - 1); ++tri) {
    const std::uint32_t cell = tri / 2, r = cell / (columns - 1), c = cell % (columns - 1);
    // Corners (dr, dc) of the documented triangles: (00, 01, 10) and (01, 11, 10).
    const int corners[2][3][2] = {{{0, 0}, {0, 1}, {1, 0}}, {{0, 1}, {1, 1}, {1, 0}}};
    gq::Triangle<T> t;
    std::uint32_t idx[3] = {99, 99, 99};
    ASSERT_TRUE(gq::getTriangle(g, pose, tri, t, idx).ok());
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t rr = r + corners[tri % 2][k][0], cc = c + corners[tri % 2][k][1];
      EXPECT_EQ(idx[k], rr * columns + cc);
      const gq::Vec3<T> local(T(rr) * T(2), d.heights[rr * columns + cc] * T(0.5), T(cc) * T(0.25));
      const gq::Vec3<T> expected = pose.q * local + pose.p;
      EXPECT_LT((t.verts[k] - expected).norm(), T(1e-5) * T(10)) << tri << " vertex " << k;
    }
    // Both triangles face +Y in shape space.
    EXPECT_GT(pose.rotateInv(t.normal()).y(), T(0));
  }
}

TYPED_TEST(HeightFieldCook, GetTriangleRejectsOutOfRangeIndexAndWritesNothing) {
  using T = TypeParam;
  std::shared_ptr<const gq::HeightField<T>> hf;
  ASSERT_TRUE(gq::cookHeightField(rampDesc<T>(3, 3), hf).ok());
  const gq::HeightFieldGeometry<T> g(hf, T(1), T(1), T(1));
  gq::Triangle<T> t;
  t.verts[0] = gq::Vec3<T>::Constant(T(42));
  std::uint32_t idx[3] = {7, 7, 7};
  const gq::Status s = gq::getTriangle(g, gq::Transform<T>(), 8u, t, idx);  // 2*2*2 = 8 triangles
  EXPECT_EQ(s.code, gq::StatusCode::InvalidArgument);
  EXPECT_STRNE(s.message(), "");
  EXPECT_EQ(t.verts[0], gq::Vec3<T>::Constant(T(42)));
  EXPECT_EQ(idx[0], 7u);
  gq::HeightFieldGeometry<T> noData = g;
  noData.heightField = nullptr;
  EXPECT_EQ(gq::getTriangle(noData, gq::Transform<T>(), 0u, t, idx).code, gq::StatusCode::InvalidArgument);
  EXPECT_EQ(idx[0], 7u);
}

TYPED_TEST(HeightFieldCook, BoundsAreTheExactBoxOfTheLocalExtentUnderThePose) {
  using T = TypeParam;
  std::shared_ptr<const gq::HeightField<T>> hf;
  const std::uint32_t rows = 6, columns = 9;
  ASSERT_TRUE(gq::cookHeightField(rampDesc<T>(rows, columns), hf).ok());  // heights in [-4, 6]
  const T hs = T(0.5), rs = T(2), cs = T(0.25);
  const gq::HeightFieldGeometry<T> g(hf, hs, rs, cs);
  // Local box [0,10] x [-2,3] x [0,2]; centre/extent closed form: world half extents = |R| * local half extents.
  const Eigen::Matrix<long double, 3, 1> lo(0, -4 * 0.5L, 0), hi(5 * 2.0L, 6 * 0.5L, 8 * 0.25L);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 20; ++trial) {
    const double ax = u(rng), ay = u(rng), az = u(rng), px = u(rng), py = u(rng), pz = u(rng), angle = u(rng);
    const gq::Vec3<T> axis = gq::Vec3<T>(T(ax), T(ay), T(az)).normalized();
    const gq::Transform<T> pose(gq::Vec3<T>(T(3 * px), T(3 * py), T(3 * pz)),
                                gq::Quat<T>(Eigen::AngleAxis<T>(T(3 * angle), axis)));
    const gq::Bounds3<T> b = gq::detail::boundsHeightField(g, pose);
    const Eigen::Matrix<long double, 3, 3> R = pose.q.toRotationMatrix().template cast<long double>();
    const Eigen::Matrix<long double, 3, 1> centre = R * ((lo + hi) / 2) + pose.p.template cast<long double>();
    const Eigen::Matrix<long double, 3, 1> half = R.cwiseAbs() * ((hi - lo) / 2);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(double(b.min[k]), double(centre[k] - half[k]), 1e-5);
      EXPECT_NEAR(double(b.max[k]), double(centre[k] + half[k]), 1e-5);
    }
  }
  // Identity pose: the local box itself, exactly.
  const gq::Bounds3<T> b = gq::detail::boundsHeightField(g, gq::Transform<T>());
  EXPECT_EQ(b.min, gq::Vec3<T>(0, -2, 0));
  EXPECT_EQ(b.max, gq::Vec3<T>(10, 3, 2));
}

}  // namespace
