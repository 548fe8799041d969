#pragma once
// Shared test helpers: the typed-test scalar list, per-scalar tolerances, seeded random poses and vectors, and
// long-double conversions for independent references.
#include <gtest/gtest.h>

#include <random>

#include "gq/math.h"
#include "gq/transform.h"

namespace gq::test {

using Scalars = ::testing::Types<float, double>;
using LD = long double;
using Vec3L = Eigen::Matrix<LD, 3, 1>;
using Mat3L = Eigen::Matrix<LD, 3, 3>;

// Relative agreement required against a long-double reference (the acceptance numbers).
template <class T> struct Tol;
template <> struct Tol<float> { static constexpr double kRel = 1e-4; };
template <> struct Tol<double> { static constexpr double kRel = 1e-9; };

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : gen_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen_); }
  bool chance(double p) { return uniform(0, 1) < p; }
  template <class T> Vec3<T> inBox(double half) {
    return Vec3<T>(T(uniform(-half, half)), T(uniform(-half, half)), T(uniform(-half, half)));
  }
  template <class T> Vec3<T> unitVector() {
    std::normal_distribution<double> n;
    Eigen::Vector3d v;
    do v = Eigen::Vector3d(n(gen_), n(gen_), n(gen_));
    while (v.norm() < 1e-6);
    return v.normalized().cast<T>();
  }
  template <class T> Quat<T> rotation() {
    std::normal_distribution<double> n;
    Eigen::Quaterniond q(n(gen_), n(gen_), n(gen_), n(gen_));
    return q.normalized().cast<T>();
  }
  template <class T> Transform<T> pose(double translation) { return Transform<T>(inBox<T>(translation), rotation<T>()); }

 private:
  std::mt19937_64 gen_;
};

template <class T> Vec3L toLD(const Vec3<T>& v) { return v.template cast<LD>(); }
// The rotation matrix of q in long double, by the unit-quaternion formula (q as given, in T).
template <class T> Mat3L rotationLD(const Quat<T>& q) {
  const LD w = q.w(), x = q.x(), y = q.y(), z = q.z();
  Mat3L r;
  r << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
       2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
       2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return r;
}

}  // namespace gq::test
