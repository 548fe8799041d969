// The BVH node test must enter every child box the ray enters: the float slab test pads its near and far distances
// (folded into the inverse direction) and, for double rays, the origin's rounding to float. Checked against the same
// slab test in long double on the box the node stores (faces included), with rays aimed at the box's faces, edges and
// corners (grazing rays), origins that float does not represent (double), zero direction components of either sign
// with the origin on a face's plane (the ray lies in the face) and the tightest exit bound the walk uses (the entry
// distance itself, rounded up to float). Every node test the CPU runs is checked: the scalar
// lanes, the SSE4.2 halves and, where the CPU has it, AVX2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "bvh/build.h"
#include "bvh/traverse.h"
#include "mesh_test_helpers.h"

namespace gq {
namespace {

using meshtest::Scalars;

template <class T> class BvhSlab : public ::testing::Test {};
TYPED_TEST_SUITE(BvhSlab, Scalars);

// The entry distance of the ray into the box in long double, or -1 when it misses it within [0, tMax].
long double exactEntry(const Vec3<long double>& o, const Vec3<long double>& d, const Bounds3<float>& box,
                       long double tMax) {
  long double enter = 0, exit = tMax;
  for (int a = 0; a < 3; ++a) {
    const long double lo = box.min[a], hi = box.max[a];
    if (d[a] == 0) {
      if (o[a] < lo || o[a] > hi) return -1;
      continue;
    }
    const long double t0 = (lo - o[a]) / d[a], t1 = (hi - o[a]) / d[a];
    enter = std::max(enter, std::min(t0, t1));
    exit = std::min(exit, std::max(t0, t1));
  }
  return enter <= exit ? enter : -1;
}

// A float upper bound of x (as the walk rounds its exit bound).
float floatAbove(long double x) {
  float f = static_cast<float>(x);
  while (static_cast<long double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

// The node with `box` in `lane` and the other lanes empty (as the build leaves unused lanes).
Bvh8Node nodeWith(const Bounds3<float>& box, int lane) {
  Bvh8Node n;
  for (int i = 0; i < 8; ++i) {
    const bool used = i == lane;
    setBvhLaneBox(n, i, used ? box : emptyBvhLaneBox());
    n.child[i] = used ? Bvh8Node::makeLeaf(0, 1) : Bvh8Node::kEmpty;
  }
  return n;
}

// The masks and entry distances of every node test this build and CPU run on this ray (the AVX2 walk's short form on
// the rays it is chosen for).
template <bool kFarOrigin> struct NodeTests {
  int masks[4] = {0, 0, 0, 0};
  float entry[4] = {0, 0, 0, 0};
  int count = 0;
  void run(const Bvh8Node& node, const detail::BvhRay<8>& ray, float tMax, int lane) {
    alignas(32) float tn[8];
    masks[count] = detail::BvhLanesScalar<8>::test<kFarOrigin>(node, ray, tMax, tn);
    entry[count++] = tn[lane];
#ifdef GQ_SSE42
    const detail::BvhRaySse sse = detail::Bvh8LanesSse::prepare(ray);
    masks[count] = detail::Bvh8LanesSse::test<kFarOrigin>(node, sse, tMax, tn);
    entry[count++] = tn[lane];
    if (detail::hasAvx2()) {
      masks[count] = runAvx2<detail::Bvh8LanesAvx2>(node, ray, tMax, tn);
      entry[count++] = tn[lane];
      if (ray.mayGiveNaN == 0) {
        masks[count] = runAvx2<detail::Bvh8LanesAvx2NaNFree>(node, ray, tMax, tn);
        entry[count++] = tn[lane];
      }
    }
#endif
  }
#ifdef GQ_SSE42
  template <class Lanes>
  __attribute__((target("avx2"))) static int runAvx2(const Bvh8Node& node, const detail::BvhRay<8>& ray, float tMax,
                                                     float* tn) {
    return Lanes::template test<kFarOrigin>(node, ray, tMax, tn);
  }
#endif
};

TYPED_TEST(BvhSlab, NodeTestsEnterEveryBoxTheRayEntersWithAConservativeEntryDistance) {
  using T = TypeParam;
  constexpr bool kFarOrigin = !std::is_same_v<T, float>;  // as the mesh walks: float origins are exact
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> n;
  auto logUniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, u(rng)); };
  int entered = 0, missed = 0, lateEntry = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    // A box of sides 1e-4 .. 10 around a centre up to 1e4 from the origin, stored in float rounded outward.
    const Vec3<double> centre = Vec3<double>(n(rng), n(rng), n(rng)) * logUniform(1e-2, 1e4);
    const Vec3<double> half(logUniform(5e-5, 5), logUniform(5e-5, 5), logUniform(5e-5, 5));
    const Bounds3<float> box = detail::roundOutward<double>(centre - half, centre + half);
    // A target on the box's surface (a face, an edge or a corner: the rays that graze), then the origin away from it.
    Vec3<double> target;
    for (int a = 0; a < 3; ++a) {
      const double lo = box.min[a], hi = box.max[a];
      const double r = u(rng);
      target[a] = r < 0.3 ? lo : r < 0.6 ? hi : lo + (hi - lo) * u(rng);
    }
    Vec3<double> dir(n(rng), n(rng), n(rng));
    // Parallel to a face: a zero component of either sign (its origin coordinate is the target's, often on a face
    // plane: the ray lies in the face), or along an axis.
    if (trial % 10 == 0) dir[trial % 3] = u(rng) < 0.5 ? -0.0 : 0.0;
    if (trial % 50 == 0) dir = Vec3<double>::Unit(trial % 3) * (u(rng) < 0.5 ? -1.0 : 1.0);
    dir.normalize();
    // A component below the walk's 1e-20 clamp but not zero (its far inverse is infinite).
    if (trial % 10 == 5) dir[trial % 3] = u(rng) < 0.5 ? -1e-25 : 1e-25;
    const double dist = logUniform(1e-3, 1e3);
    Vec3<T> org = (target - dir * dist).cast<T>();
    // A double origin of a ray parallel to a face within a float unit of the face's plane, on either side: between
    // two floats, the node test takes the one on each side of it.
    if (!std::is_same_v<T, float> && trial % 20 == 0) {
      const int a = trial % 3;
      const float face = static_cast<float>(org[a]);
      const double unit = double(std::nextafter(face, std::numeric_limits<float>::infinity())) - double(face);
      org[a] = T(double(face) + (u(rng) - 0.5) * unit);
    }
    const Vec3<T> dirT = dir.cast<T>();
    const Vec3<long double> oL = org.template cast<long double>(), dL = dirT.template cast<long double>();
    const long double tEnter = exactEntry(oL, dL, box, std::numeric_limits<long double>::infinity());
    if (tEnter < 0) continue;
    ++entered;
    // The walk's tightest exit bound: a hit at the entry distance itself, rounded up to float.
    // Every kind of direction above meets both a tight and an infinite bound.
    const float tMax = (trial / 10) % 2 == 0 ? floatAbove(tEnter) : std::numeric_limits<float>::infinity();
    const int lane = trial % 8;
    const Bvh8Node node = nodeWith(box, lane);
    const detail::BvhRay<8> ray = detail::makeBvhRay<8>(org, dirT);
    NodeTests<kFarOrigin> tests;
    tests.run(node, ray, tMax, lane);
    for (int k = 0; k < tests.count; ++k) {
      missed += ((tests.masks[k] >> lane) & 1) == 0;
      lateEntry += static_cast<long double>(tests.entry[k]) > tEnter;  // the walk drops entries by this distance
      EXPECT_EQ(tests.masks[k] & ~(1 << lane), 0) << "an empty lane was entered";
      // Every form gives the same mask and entry distance, so every CPU walks the same nodes in the same order.
      EXPECT_EQ(tests.masks[k], tests.masks[0]);
      EXPECT_EQ(std::memcmp(&tests.entry[k], &tests.entry[0], sizeof(float)), 0) << tests.entry[k];
    }
  }
  EXPECT_EQ(missed, 0);
  EXPECT_EQ(lateEntry, 0);
  EXPECT_GT(entered, 100000);  // most rays enter: the check is not vacuous
}

// A ray parallel to two axes (a vertical sensor ray) whose origin lies on a box's plane of one of them: the slab
// distance on that plane is NaN (0 * inf), so BvhRay::mayGiveNaN sends the ray to the NaN-first node test, which still
// rejects the boxes beside the ray along the other axis (a max taking two NaN-able operands would pass over the
// rejecting distance); ordinary rays can take the short form. Checked on every node test the ray would get.
TYPED_TEST(BvhSlab, RaysParallelToTwoAxesWithTheOriginOnAPlaneMissTheBoxesBesideThem) {
  using T = TypeParam;
  constexpr bool kFarOrigin = !std::is_same_v<T, float>;
  const Bounds3<float> box = detail::roundOutward<double>(Vec3<double>(1, 0, -2), Vec3<double>(2, 1, -1));
  const Bvh8Node node = nodeWith(box, 3);
  int rays = 0;
  for (const T x : {T(0.5), T(3), T(1.5)})    // beside the box below x, beside it above x, over it
    for (const T y : {T(0), T(1), T(0.5)})    // on the box's min y plane, on its max y plane, between them
      for (const T dz : {T(-1), T(1)}) {
        const Vec3<T> org(x, y, T(5) * -dz), dir(T(0), T(0), dz);
        const detail::BvhRay<8> ray = detail::makeBvhRay<8>(org, dir);
        EXPECT_NE(ray.mayGiveNaN, 0u);
        NodeTests<kFarOrigin> tests;
        tests.run(node, ray, std::numeric_limits<float>::infinity(), 3);
        const bool over = x == T(1.5);
        for (int k = 0; k < tests.count; ++k) EXPECT_EQ(tests.masks[k], over ? 1 << 3 : 0) << x << " " << y;
        ++rays;
      }
  EXPECT_EQ(rays, 18);
  // An ordinary ray has no NaN slab distance; a component below the clamp, or (double) an origin beyond float's
  // range, may.
  EXPECT_NE(detail::makeBvhRay<8>(Vec3<T>(T(0.5), T(0), T(5)), Vec3<T>(T(0.6), T(0), T(-0.8))).mayGiveNaN, 0u);
  EXPECT_EQ(detail::makeBvhRay<8>(Vec3<T>(T(0.5), T(0.25), T(5)), Vec3<T>(T(0.6), T(0.48), T(-0.64))).mayGiveNaN, 0u);
  EXPECT_NE(detail::makeBvhRay<8>(Vec3<T>(T(0.5), T(0.25), T(5)), Vec3<T>(T(1e-25), T(0.6), T(-0.8))).mayGiveNaN, 0u);
  if constexpr (std::is_same_v<T, double>)
    EXPECT_NE(detail::makeBvhRay<8>(Vec3<T>(T(1e39), T(0.25), T(5)), Vec3<T>(T(0.6), T(0.48), T(-0.64))).mayGiveNaN,
              0u);
}

// A double origin gives the node tests two floats: the near planes' origin on the side that makes entries earlier and
// the far planes' on the side that makes exits later (for a positive component the entry (min - org) / dir falls as
// the origin rises: the float above it for the near planes, the one below for the far planes). A float origin is both.
TYPED_TEST(BvhSlab, NearAndFarOriginsAreTheFloatsAroundTheOriginOnTheConservativeSides) {
  using T = TypeParam;
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0), u(0, 1);
  std::uniform_int_distribution<int> exponent(-160, 140);
  const float inf = std::numeric_limits<float>::infinity();
  int between = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Vec3<T> org, dir;
    for (int a = 0; a < 3; ++a) {
      const double x = std::ldexp(mantissa(rng), exponent(rng));
      org[a] = trial % 7 == 0 ? T(static_cast<float>(x)) : static_cast<T>(x);  // some exactly float
      dir[a] = T(mantissa(rng));
      if (trial % 11 == a) dir[a] = u(rng) < 0.5 ? T(-0.0) : T(0.0);
    }
    if (trial == 0) org = Vec3<T>(T(-0.0), T(1e-300), T(-1e-300));
    if (trial == 1) org = Vec3<T>(T(1e39), T(-1e39), T(3.4028235e38));
    const detail::BvhRay<8> ray = detail::makeBvhRay<8>(org, dir);
    for (int a = 0; a < 3; ++a) {
      const float f = static_cast<float>(org[a]);
      const float below = double(f) > double(org[a]) ? std::nextafter(f, -inf) : f;
      const float above = double(f) < double(org[a]) ? std::nextafter(f, inf) : f;
      between += below != above;
      const bool negative = std::signbit(dir[a]);
      EXPECT_EQ(std::memcmp(&ray.org[a], negative ? &below : &above, sizeof(float)), 0) << org[a] << " " << dir[a];
      EXPECT_EQ(std::memcmp(&ray.farOrg[a], negative ? &above : &below, sizeof(float)), 0) << org[a] << " " << dir[a];
    }
  }
  if (std::is_same_v<T, float>) {
    EXPECT_EQ(between, 0);
  } else {
    EXPECT_GT(between, 40000);  // most double origins lie between two floats
  }
}

#ifdef GQ_SSE42
// The SSE form of the BVH ray computes the portable loop's constants bit for bit (lanes 0-2): origins, inverses and
// plane offsets, for exact zeros of both signs, components below and at the clamp, and origins of every magnitude.
TYPED_TEST(BvhSlab, SseRayConstantsAreTheScalarLoopsBitForBit) {
  using T = TypeParam;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0), u(0, 1);
  std::uniform_int_distribution<int> exponent(-150, 127);
  const double special[] = {0.0, -0.0, 1e-25, -1e-25, 1e-20, -1e-20, 9.99999e-21, 1.0, -1.0};
  int zeros = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Vec3<T> org, dir;
    for (int a = 0; a < 3; ++a) {
      org[a] = static_cast<T>(std::ldexp(mantissa(rng), exponent(rng)));
      dir[a] = static_cast<T>(u(rng) < 0.2 ? special[std::size_t(u(rng) * 9) % 9] : mantissa(rng));
      zeros += dir[a] == T(0);
    }
    const detail::BvhRay<8> sse = detail::makeBvhRay<8>(org, dir), loop = detail::makeBvhRayScalar<8>(org, dir);
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(std::memcmp(&sse.org[a], &loop.org[a], sizeof(float)), 0) << org[a];
      EXPECT_EQ(std::memcmp(&sse.farOrg[a], &loop.farOrg[a], sizeof(float)), 0) << org[a];
      EXPECT_EQ(std::memcmp(&sse.negInvDir[a], &loop.negInvDir[a], sizeof(float)), 0) << dir[a];
      EXPECT_EQ(std::memcmp(&sse.nearInv[a], &loop.nearInv[a], sizeof(float)), 0) << dir[a];
      EXPECT_EQ(std::memcmp(&sse.farInv[a], &loop.farInv[a], sizeof(float)), 0) << dir[a];
      EXPECT_EQ(sse.nearOffset[a], loop.nearOffset[a]);
      EXPECT_EQ(sse.farOffset[a], loop.farOffset[a]);
    }
    EXPECT_EQ(sse.mayGiveNaN != 0, loop.mayGiveNaN != 0) << dir.transpose() << " " << org.transpose();
  }
  EXPECT_GT(zeros, 1000);  // exact zeros of both signs are among the components
}
#endif

}  // namespace
}  // namespace gq

// floatCeil (the walk's float bound for a T distance) is the least float at or above it: std::nextafter's value
// wherever the conversion rounds down, on both signs, at powers of two, at the float range's ends and below it.
TEST(BvhFloatCeil, IsTheLeastFloatAtOrAboveTheDistance) {
  auto reference = [](double t) {
    const float f = static_cast<float>(t);
    return double(f) < t ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
  };
  std::vector<double> ts = {0.0, -0.0, 1.0, 1.0 + 1e-12, 1.0 - 1e-12, -1.0 - 1e-12, -1.0 + 1e-12, 1e-45, 1e-46,
                            -1e-46, -1.5e-45, 3.4028234663852886e38, 3.40282356e38, -3.40282356e38, 1e300, -1e300,
                            std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                            std::numeric_limits<double>::denorm_min()};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-160, 140);
  for (int i = 0; i < 100000; ++i) ts.push_back(std::ldexp(mantissa(rng), exponent(rng)));
  int roundedDown = 0;
  for (double t : ts) {
    const float c = gq::detail::floatCeil(t), r = reference(t);
    roundedDown += double(static_cast<float>(t)) < t ? 1 : 0;
    ASSERT_EQ(std::memcmp(&c, &r, sizeof c), 0) << t;
    if (!std::isnan(t)) {
      ASSERT_GE(double(c), t) << t;
    }
  }
  EXPECT_GT(roundedDown, 40000);  // the case under test is common in the sample
  const float nan = gq::detail::floatCeil(std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(std::isnan(nan));
  EXPECT_EQ(gq::detail::floatCeil(2.5f), 2.5f);  // a float distance is its own bound
}
