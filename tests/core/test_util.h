#pragma once
// Shared test helpers: the typed-test scalar list, per-scalar tolerances, seeded random poses and vectors, and
// long-double conversions for independent references.
#include <gtest/gtest.h>

#include <random>

#include "gq/geometry.h"
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

// One draw per statement: argument evaluation order is unspecified (GCC and clang differ).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : gen_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen_); }
  bool chance(double p) { return uniform(0, 1) < p; }
  // Each coordinate uniform in [lo, hi), drawn x, y, z.
  template <class T> Vec3<T> vec(double lo, double hi) {
    std::uniform_real_distribution<double> u(lo, hi);
    return draw3(u).cast<T>();
  }
  template <class T> Vec3<T> inBox(double half) { return vec<T>(-half, half); }
  template <class T> Vec3<T> unitVector() {
    std::normal_distribution<double> n;
    Eigen::Vector3d v;
    do v = draw3(n);
    while (v.norm() < 1e-6);
    return v.normalized().cast<T>();
  }
  template <class T> Quat<T> rotation() {
    std::normal_distribution<double> n;
    const double w = n(gen_);
    const Eigen::Vector3d xyz = draw3(n);
    return Eigen::Quaterniond(w, xyz.x(), xyz.y(), xyz.z()).normalized().cast<T>();
  }
  template <class T> Transform<T> pose(double translation) {
    const Vec3<T> p = inBox<T>(translation);
    return Transform<T>(p, rotation<T>());
  }
  // Per-axis stretch in [lo, hi) along randomly rotated axes.
  template <class T> MeshScale<T> meshScale(double lo, double hi) {
    const Vec3<T> s = vec<T>(lo, hi);
    return MeshScale<T>(s, rotation<T>());
  }

 private:
  template <class Distribution> Eigen::Vector3d draw3(Distribution& d) {
    const double x = d(gen_);
    const double y = d(gen_);
    const double z = d(gen_);
    return {x, y, z};
  }

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
