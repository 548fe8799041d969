// rotatedX(q, s), the capsule half axis of the sphere-capsule kernels, against the general rotation q * (s, 0, 0):
// the same value in every component (only the sign of a zero may differ), for unit and slightly non-unit rotations
// and lengths over many magnitudes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/rotated_axis.h"
#include "overlap_test_support.h"

namespace gq::test {
namespace {

template <class T> class RotatedAxis : public ::testing::Test {};
TYPED_TEST_SUITE(RotatedAxis, Scalars);

TYPED_TEST(RotatedAxis, EqualsTheGeneralRotationOfTheXAxis) {
  using T = TypeParam;
  std::mt19937_64 gen(39);
  std::normal_distribution<T> normal;
  std::uniform_real_distribution<T> exponent(-6, 6), stretch(T(0.9995), T(1.0005));
  int checked = 0;
  for (int i = 0; i < 20000; ++i) {
    Quat<T> q(normal(gen), normal(gen), normal(gen), normal(gen));
    q.normalize();
    if (i % 3 == 0) q.coeffs() *= stretch(gen);   // validation accepts |q| within 1e-3 of 1
    if (i % 7 == 0) q.coeffs()[i % 4] = T(0);     // axis-aligned rotations
    const T s = std::pow(T(10), exponent(gen)) * (i % 5 == 0 ? T(-1) : T(1));
    const Vec3<T> general = q * Vec3<T>(s, T(0), T(0)), fast = detail::rotatedX(q, s);
    ASSERT_EQ(general.x(), fast.x()) << "i " << i;
    ASSERT_EQ(general.y(), fast.y()) << "i " << i;
    ASSERT_EQ(general.z(), fast.z()) << "i " << i;
    ++checked;
  }
  EXPECT_EQ(checked, 20000);
  // The identity and a half turn about Z: exact.
  EXPECT_EQ(detail::rotatedX(Quat<T>::Identity(), T(2)), Vec3<T>(2, 0, 0));
  EXPECT_EQ(detail::rotatedX(Quat<T>(T(0), T(0), T(0), T(1)), T(2)), Vec3<T>(-2, 0, 0));
}

}  // namespace
}  // namespace gq::test
