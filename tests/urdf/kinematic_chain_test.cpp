// The compiled forward kinematics both checkers run (plugins/urdf/src/kinematic_chain.h) against the public
// forwardKinematics, link by link, and its sin/cos against long double libm.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../../plugins/urdf/src/kinematic_chain.h"
#include "../../plugins/urdf/src/sincos.h"
#include "robot_paths.h"

namespace gq::urdf::test {
namespace {

// Every joint kind and axis the chain special-cases: coordinate axes (+ and -), a general axis, quarter-turn and
// general origin rotations, prismatic, mimic, continuous, fixed chains through shapeless links.
const char* kMixedChain = R"(<robot name="mixed">
  <link name="base"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
  <link name="l1"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
  <link name="l2"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
  <link name="l3"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
  <link name="bare"/>
  <link name="l4"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
  <link name="l5"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
  <link name="l6"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
  <joint name="a" type="revolute"><parent link="base"/><child link="l1"/><origin xyz="0 0 0.3" rpy="1.5707963267948966 0 0"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="b" type="revolute"><parent link="l1"/><child link="l2"/><origin xyz="0.2 -0.1 0" rpy="0 1.5707963267948966 0"/>
    <axis xyz="0 -1 0"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="c" type="revolute"><parent link="l2"/><child link="l3"/><origin xyz="0.1 0.2 0.3" rpy="0.3 -0.2 0.7"/>
    <axis xyz="0.6 0 0.8"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="f1" type="fixed"><parent link="l3"/><child link="bare"/><origin xyz="0 0.1 0" rpy="0 0 0.4"/></joint>
  <joint name="f2" type="fixed"><parent link="bare"/><child link="l4"/><origin xyz="0.05 0 0" rpy="-1.5707963267948966 0 0"/></joint>
  <joint name="p" type="prismatic"><parent link="l4"/><child link="l5"/><origin xyz="0 0 0.1" rpy="0 0 3.141592653589793"/>
    <axis xyz="1 0 0"/><limit lower="0" upper="0.5" effort="1" velocity="1"/></joint>
  <joint name="m" type="revolute"><parent link="l5"/><child link="l6"/><axis xyz="-1 0 0"/>
    <limit lower="-10" upper="10" effort="1" velocity="1"/><mimic joint="a" multiplier="-2" offset="0.1"/></joint>
  <joint name="cont" type="continuous"><parent link="base"/><child link="tip"/><axis xyz="0 0 -1"/></joint>
  <link name="tip"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
</robot>)";

template <class T> class CompiledKinematics : public ::testing::Test {};
TYPED_TEST_SUITE(CompiledKinematics, Scalars);

// body frame * (link in body) must be the link pose forwardKinematics computes, for every link with shapes.
template <class T> void expectChainMatchesForwardKinematics(const RobotModel<T>& m, int configurations) {
  const internal::KinematicChain<T> chain(m);
  std::vector<Mat3<T>> rotations;
  std::vector<Vec3<T>> positions;
  std::vector<Transform<T>> poses;
  const double tol = 200 * double(std::numeric_limits<T>::epsilon());
  std::uint64_t rng = 11;
  for (int k = 0; k < configurations; ++k) {
    std::vector<T> q = randomConfiguration(m, rng);
    if (k == 0) q = m.home;
    ASSERT_TRUE(forwardKinematics(m, q, poses).ok());
    ASSERT_TRUE(chain.place(q, rotations, positions).ok());
    for (std::uint32_t l = 0; l < m.links.size(); ++l) {
      if (m.links[l].shapes.empty()) continue;
      const std::uint32_t b = chain.bodyOf(l);
      const Transform<T>& inBody = chain.linkInBody(l);
      const Mat3<double> r = (rotations[b] * inBody.q.toRotationMatrix()).template cast<double>();
      const Vec3<double> p = (rotations[b] * inBody.p + positions[b]).template cast<double>();
      EXPECT_LT((r - poses[l].q.toRotationMatrix().template cast<double>()).norm(), tol) << m.links[l].name;
      EXPECT_LT((p - poses[l].p.template cast<double>()).norm(), tol) << m.links[l].name;
    }
  }
}

TYPED_TEST(CompiledKinematics, BodyFramesTimesLinkOffsetsAreTheForwardKinematicsPosesOnEveryJointKind) {
  RobotModel<TypeParam> m;
  ASSERT_TRUE(loadRobotFromStrings(kMixedChain, "", "/", testOptions(Representation::Hull), m).ok());
  expectChainMatchesForwardKinematics(m, 500);
}

TYPED_TEST(CompiledKinematics, FixedJointsJoinLinksIntoOneBody) {
  RobotModel<TypeParam> m;
  ASSERT_TRUE(loadRobotFromStrings(kMixedChain, "", "/", testOptions(Representation::Hull), m).ok());
  const internal::KinematicChain<TypeParam> chain(m);
  EXPECT_EQ(chain.bodyOf(std::uint32_t(m.findLink("l4"))), chain.bodyOf(std::uint32_t(m.findLink("l3"))));
  EXPECT_NE(chain.bodyOf(std::uint32_t(m.findLink("l5"))), chain.bodyOf(std::uint32_t(m.findLink("l4"))));
  EXPECT_EQ(chain.bodyCount(), 7u);  // base, l1, l2, l3 (+bare, l4), l5, l6, tip
}

TYPED_TEST(CompiledKinematics, InvalidConfigurationsGiveTheForwardKinematicsStatusAndWriteNothing) {
  using T = TypeParam;
  RobotModel<T> m;
  ASSERT_TRUE(loadRobotFromStrings(kMixedChain, "", "/", testOptions(Representation::Hull), m).ok());
  const internal::KinematicChain<T> chain(m);
  std::vector<Mat3<T>> rotations(1, Mat3<T>::Constant(T(7)));
  std::vector<Vec3<T>> positions(1, Vec3<T>::Constant(T(7)));
  std::vector<Transform<T>> poses;
  const std::vector<std::vector<T>> bads{
      namedConfiguration(m, {{"a", 3.5}}), namedConfiguration(m, {{"p", -0.1}}),
      namedConfiguration(m, {{"cont", std::numeric_limits<double>::infinity()}}),
      namedConfiguration(m, {{"c", std::nan("")}}), std::vector<T>(2, T(0))};
  for (const std::vector<T>& bad : bads) {
    const Status expected = forwardKinematics(m, bad, poses);
    const Status s = chain.place(bad, rotations, positions);
    EXPECT_EQ(s.code, StatusCode::InvalidArgument);
    EXPECT_EQ(s.toString(), expected.toString());
    ASSERT_EQ(rotations.size(), 1u);
    EXPECT_EQ(rotations[0](0, 0), T(7));
    EXPECT_EQ(positions[0].x(), T(7));
  }
}

// On Panda and UR5 from the shared data folder (skipped when it does not hold them).
template <class T> class CompiledKinematicsData : public RobotDataTest {};
TYPED_TEST_SUITE(CompiledKinematicsData, Scalars);

TYPED_TEST(CompiledKinematicsData, BodyFramesTimesLinkOffsetsAreTheForwardKinematicsPosesOnPandaAndUr5) {
  for (const RobotFiles* robot : {&kPanda, &kUr5}) {
    const auto m = loadCached<TypeParam>(*robot, Representation::BestPrimitive);
    ASSERT_TRUE(m);
    expectChainMatchesForwardKinematics(*m, 200);
  }
}

// The exact value rounded once is within half an ulp; the reduction and the Taylor sums add about one more.
TEST(FastSinCos, WithinTwoUlpsOfLongDoubleAcrossQuadrantsAndBeyondTheJointRange) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  double worst = 0;
  const auto ulpError = [](double got, long double exact) {
    const long double ulp = std::ldexp(1.0L, std::ilogb(double(exact)) - 52);
    return double(std::abs((long double)got - exact) / std::max(ulp, std::ldexp(1.0L, -1074)));
  };
  for (int k = 0; k < 200000; ++k) {
    // Mostly joint angles; some around quadrant boundaries k pi/4; some large (continuous joints, libm fallback).
    const double u = uniform(rng);
    double x = (u - 0.5) * 20;
    if (k % 4 == 1) x = std::round(x / (M_PI / 4)) * (M_PI / 4) + (u - 0.5) * 1e-9;
    if (k % 16 == 3) x = (u - 0.5) * 4e6;
    double s, c;
    internal::sinCos(x, s, c);
    const long double xl = x;
    if (std::abs(std::sin(xl)) > 1e-300) worst = std::max(worst, ulpError(s, std::sin(xl)));
    if (std::abs(std::cos(xl)) > 1e-300) worst = std::max(worst, ulpError(c, std::cos(xl)));
  }
  EXPECT_LE(worst, 2.0);
}

TEST(FastSinCos, ExactAtZeroAndOddAtOppositeAngles) {
  double s, c;
  internal::sinCos(0.0, s, c);
  EXPECT_EQ(s, 0.0);
  EXPECT_EQ(c, 1.0);
  for (double x : {0.3, 1.2, 2.9, 7.5, 100.25}) {
    double sn, cn;
    internal::sinCos(x, s, c);
    internal::sinCos(-x, sn, cn);
    EXPECT_EQ(sn, -s) << x;
    EXPECT_EQ(cn, c) << x;
  }
}

}  // namespace
}  // namespace gq::urdf::test
