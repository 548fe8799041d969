// Forward kinematics on a hand-written chain (revolute, prismatic, mimic, continuous, fixed), checked against the
// closed-form poses, and the configuration checks.
#include <gtest/gtest.h>

#include <cmath>

#include "robot_paths.h"

namespace gq::urdf::test {
namespace {

const char* kChain = R"(<robot name="chain">
  <link name="base"/><link name="l1"/><link name="l2"/><link name="l3"/><link name="l4"/><link name="l5"/>
  <joint name="rev" type="revolute"><parent link="base"/><child link="l1"/><origin xyz="0 0 1"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="pri" type="prismatic"><parent link="l1"/><child link="l2"/><origin xyz="1 0 0"/>
    <axis xyz="1 0 0"/><limit lower="0" upper="0.5" effort="1" velocity="1"/></joint>
  <joint name="mim" type="revolute"><parent link="l2"/><child link="l3"/><axis xyz="0 1 0"/>
    <limit lower="-10" upper="10" effort="1" velocity="1"/><mimic joint="rev" multiplier="-2" offset="0.1"/></joint>
  <joint name="cont" type="continuous"><parent link="l3"/><child link="l4"/><origin xyz="0 0 0.5"/>
    <axis xyz="1 0 0"/></joint>
  <joint name="fix" type="fixed"><parent link="l4"/><child link="l5"/><origin xyz="0 0.25 0" rpy="0 0 1.5707963267948966"/></joint>
</robot>)";

Mat3<double> rotZ(double a) { return Eigen::AngleAxisd(a, Vec3<double>::UnitZ()).toRotationMatrix(); }
Mat3<double> rotY(double a) { return Eigen::AngleAxisd(a, Vec3<double>::UnitY()).toRotationMatrix(); }
Mat3<double> rotX(double a) { return Eigen::AngleAxisd(a, Vec3<double>::UnitX()).toRotationMatrix(); }

template <class T> class Kinematics : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(loadRobotFromStrings(kChain, "", "/", testOptions(Representation::Hull), m).ok()); }
  RobotModel<T> m;
  T tol() const { return T(100) * std::numeric_limits<T>::epsilon(); }
};
TYPED_TEST_SUITE(Kinematics, Scalars);

TYPED_TEST(Kinematics, ConfigurationHoldsOnlyActiveJoints) {
  EXPECT_EQ(this->m.variables, (std::vector<std::string>{"rev", "pri", "cont"}));  // mimic and fixed excluded
}

TYPED_TEST(Kinematics, ChainPosesMatchClosedForm) {
  using T = TypeParam;
  const double a = 0.7, d = 0.3, c = -2.5;
  std::vector<Transform<T>> poses;
  ASSERT_TRUE(forwardKinematics(this->m, std::vector<T>{T(a), T(d), T(c)}, poses).ok());
  // l1 = Tz(1) Rz(a); l2 = l1 Tx(1 + d); l3 = l2 Ry(-2a + 0.1) (mimic); l4 = l3 Tz(0.5) Rx(c); l5 = l4 Ty(.25) Rz(pi/2)
  const Mat3<double> r1 = rotZ(a), r3 = r1 * rotY(-2 * a + 0.1), r4 = r3 * rotX(c), r5 = r4 * rotZ(M_PI / 2);
  const Vec3<double> p2 = Vec3<double>(0, 0, 1) + r1 * Vec3<double>(1 + d, 0, 0);
  const Vec3<double> p4 = p2 + r3 * Vec3<double>(0, 0, 0.5), p5 = p4 + r4 * Vec3<double>(0, 0.25, 0);
  const auto expectPose = [&](std::uint32_t link, const Vec3<double>& p, const Mat3<double>& r) {
    EXPECT_LT((poses[link].p.template cast<double>() - p).norm(), double(this->tol())) << link;
    EXPECT_LT((poses[link].q.toRotationMatrix().template cast<double>() - r).norm(), double(this->tol())) << link;
  };
  expectPose(std::uint32_t(this->m.findLink("l1")), Vec3<double>(0, 0, 1), r1);
  expectPose(std::uint32_t(this->m.findLink("l2")), p2, r1);
  expectPose(std::uint32_t(this->m.findLink("l3")), p2, r3);
  expectPose(std::uint32_t(this->m.findLink("l4")), p4, r4);
  expectPose(std::uint32_t(this->m.findLink("l5")), p5, r5);
}

TYPED_TEST(Kinematics, ValuesOutsideLimitsWrongSizeOrNaNAreRejectedWithoutOutput) {
  using T = TypeParam;
  std::vector<Transform<T>> poses(1);
  for (const std::vector<T>& bad : {std::vector<T>{T(3.5), T(0), T(0)}, std::vector<T>{T(0), T(-0.1), T(0)},
                                    std::vector<T>{T(0), T(0)}, std::vector<T>{T(std::nan("")), T(0), T(0)}}) {
    const Status s = forwardKinematics(this->m, bad, poses);
    EXPECT_EQ(s.code, StatusCode::InvalidArgument) << s.toString();
    EXPECT_EQ(poses.size(), 1u);
  }
  // A continuous joint has no limits.
  EXPECT_TRUE(forwardKinematics(this->m, std::vector<T>{T(0), T(0), T(40)}, poses).ok());
}

TYPED_TEST(Kinematics, RandomConfigurationsStayWithinLimits) {
  using T = TypeParam;
  std::uint64_t rng = 7;
  for (int k = 0; k < 1000; ++k) {
    const std::vector<T> q = randomConfiguration(this->m, rng);
    EXPECT_TRUE(q[0] >= T(-3) && q[0] <= T(3) && q[1] >= T(0) && q[1] <= T(0.5));
    EXPECT_TRUE(q[2] >= T(-M_PI) && q[2] <= T(M_PI));
  }
}

// On Panda from the shared data folder (skipped when it does not hold it).
template <class T> class KinematicsData : public RobotDataTest {};
TYPED_TEST_SUITE(KinematicsData, Scalars);

TYPED_TEST(KinematicsData, PandaFingersMirrorThroughTheMimicJoint) {
  using T = TypeParam;
  const auto m = loadCached<T>(kPandaPrimitives, Representation::Hull);
  ASSERT_TRUE(m);
  std::vector<Transform<T>> poses;
  const std::vector<T> q = namedConfiguration(*m, {{"panda_finger_joint1", 0.03}});
  ASSERT_TRUE(forwardKinematics(*m, q, poses).ok());
  const auto& hand = poses[std::size_t(m->findLink("panda_hand"))];
  const Vec3<T> left = hand.transformInv(poses[std::size_t(m->findLink("panda_leftfinger"))].p);
  const Vec3<T> right = hand.transformInv(poses[std::size_t(m->findLink("panda_rightfinger"))].p);
  // Both fingers slide along the hand's y axis by 0.03 (the right one's axis is -y), 0.0584 above the hand.
  EXPECT_NEAR(left.y(), T(0.03), T(1e-5));
  EXPECT_NEAR(right.y(), T(-0.03), T(1e-5));
  EXPECT_NEAR(left.z(), T(0.0584), T(1e-5));
}

}  // namespace
}  // namespace gq::urdf::test
