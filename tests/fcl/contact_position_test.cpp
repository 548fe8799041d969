// Contact positions by FCL 0.7's rules, compared with FCL itself on seeded random and on axis-aligned poses (where
// FCL's "equally deep face / side line / disc" rules apply), in float and double: sphere-sphere, sphere-capsule, and
// sphere, box, capsule, cylinder and cone against a half-space and a plane, both orders. Depths and normals agree
// too; the deliberate differences are listed (fclConeDepthIsWrong, FCL's cylinder-plane depths).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "deliberate_differences.h"
#include "gq/fcl/fcl.h"

namespace {

template <class S> using V3 = ::fcl::Vector3<S>;
template <class S> using Tf = ::fcl::Transform3<S>;

template <class S> Tf<S> randomPose(std::mt19937& rng, double extent) {
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::Quaterniond q;
  const double a = u(rng), b = u(rng), c = u(rng), d = u(rng);
  q = Eigen::Quaterniond(a, b, c, d);
  q.normalize();
  const double x = u(rng) * extent, y = u(rng) * extent, z = u(rng) * extent;
  Tf<S> tf = Tf<S>::Identity();
  tf.linear() = q.toRotationMatrix().cast<S>();
  tf.translation() = V3<S>(S(x), S(y), S(z));
  return tf;
}

// A pose whose rotation is one of the 24 axis permutations (faces, sides and discs parallel to the half-space).
template <class S> Tf<S> alignedPose(std::mt19937& rng, double extent) {
  std::uniform_int_distribution<int> pick(0, 23);
  std::uniform_real_distribution<double> u(-1, 1);
  const int k = pick(rng);
  Eigen::Matrix3d r = Eigen::Matrix3d::Zero();
  const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}};
  const int* p = perms[k % 6];
  const double s0 = (k / 6) & 1 ? -1 : 1, s1 = (k / 12) & 1 ? -1 : 1;
  r(p[0], 0) = s0;
  r(p[1], 1) = s1;
  r.col(2) = r.col(0).cross(r.col(1));
  Tf<S> tf = Tf<S>::Identity();
  tf.linear() = r.cast<S>();
  tf.translation() = V3<S>(S(u(rng) * extent), S(u(rng) * extent), S(u(rng) * extent));
  return tf;
}

enum class Kind { Sphere, Box, Capsule, Cylinder, Cone };
const char* name(Kind k) {
  static const char* names[] = {"Sphere", "Box", "Capsule", "Cylinder", "Cone"};
  return names[int(k)];
}

template <class S> std::shared_ptr<::fcl::CollisionGeometry<S>> makeShape(Kind k) {
  switch (k) {
    case Kind::Sphere: return std::make_shared<::fcl::Sphere<S>>(S(0.6));
    case Kind::Box: return std::make_shared<::fcl::Box<S>>(S(1.2), S(0.8), S(0.5));
    case Kind::Capsule: return std::make_shared<::fcl::Capsule<S>>(S(0.3), S(1.4));
    case Kind::Cylinder: return std::make_shared<::fcl::Cylinder<S>>(S(0.4), S(1.1));
    case Kind::Cone: return std::make_shared<::fcl::Cone<S>>(S(0.5), S(1.2));
  }
  return nullptr;
}

// FCL's cone-half-space closed form takes the base rim as the deepest point whenever the axis does not point along
// the half-space's outward normal (cosa < its tolerance), also when the apex is deeper: its depth and position are
// then not the exact ones. gq keeps the exact depth and the apex (docs/fcl.md, deliberate differences).
template <class S> bool fclConeDepthIsWrong(const Tf<S>& cone, const V3<S>& n) {
  return cone.linear().col(2).dot(n) <= -S(std::is_same_v<S, float> ? 1e-4 : 1e-7);
}

template <class S> class FclContactPosition : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(FclContactPosition, Scalars);

template <class S> S tolerance() { return std::is_same_v<S, float> ? S(2e-3) : S(1e-9); }

template <class S>
void expectSameContact(const ::fcl::Contact<S>& gq, const ::fcl::Contact<S>& fcl, const std::string& what) {
  const S tol = tolerance<S>();
  EXPECT_NEAR(gq.penetration_depth, fcl.penetration_depth, tol) << what;
  EXPECT_NEAR((gq.normal - fcl.normal).norm(), S(0), tol) << what;
  EXPECT_NEAR((gq.pos - fcl.pos).norm(), S(0), tol) << what;
}

TYPED_TEST(FclContactPosition, ShapeAgainstHalfspaceIsPlacedAsFcl) {
  using S = TypeParam;
  std::mt19937 rng(4203);
  const auto halfspace = std::make_shared<::fcl::Halfspace<S>>(V3<S>(S(0.3), S(-0.2), S(1)).normalized(), S(0.1));
  int compared = 0, aligned = 0, wrongInFcl = 0;
  for (Kind k : {Kind::Sphere, Kind::Box, Kind::Capsule, Kind::Cylinder, Kind::Cone}) {
    const auto shape = makeShape<S>(k);
    for (int i = 0; i < 400; ++i) {
      const bool align = i % 2 == 1;
      // Aligned poses put the half-space at identity, so that a face or axis is parallel to its boundary.
      const Tf<S> ps = align ? alignedPose<S>(rng, 0.8) : randomPose<S>(rng, 0.8);
      const Tf<S> ph = align ? Tf<S>::Identity() : randomPose<S>(rng, 0.3);
      const auto* hs = halfspace.get();
      const ::fcl::Halfspace<S> flat(V3<S>(S(0), S(0), S(1)), S(0));
      const ::fcl::CollisionGeometry<S>* h = align ? static_cast<const ::fcl::CollisionGeometry<S>*>(&flat) : hs;
      const V3<S> n = ph.linear() * (align ? flat.n : hs->n);
      for (bool shapeFirst : {true, false}) {
        const std::string what = std::string(name(k)) + (shapeFirst ? "-Halfspace" : " (Halfspace first)") +
                                 " pose " + std::to_string(i);
        const ::fcl::CollisionRequest<S> request(1, true);
        ::fcl::CollisionResult<S> gq, fcl;
        if (shapeFirst) {
          gq::fcl::collide(shape.get(), ps, h, ph, request, gq);
          ::fcl::collide(shape.get(), ps, h, ph, request, fcl);
        } else {
          gq::fcl::collide(h, ph, shape.get(), ps, request, gq);
          ::fcl::collide(h, ph, shape.get(), ps, request, fcl);
        }
        if (k == Kind::Cone && fclConeDepthIsWrong(ps, n)) {
          ++wrongInFcl;
          continue;
        }
        ASSERT_EQ(gq.numContacts(), fcl.numContacts()) << what;
        if (gq.numContacts() == 0) continue;
        expectSameContact(gq.getContact(0), fcl.getContact(0), what);
        ++compared;
        aligned += align;
      }
    }
  }
  EXPECT_GT(compared, 1000);
  EXPECT_GT(aligned, 400);
  EXPECT_GT(wrongInFcl, 50);
}

TYPED_TEST(FclContactPosition, ARestingBoxTouchesAtItsFaceCentreAsFcl) {
  using S = TypeParam;
  ::fcl::Box<S> box(S(2), S(2), S(1));
  ::fcl::Halfspace<S> floor(V3<S>(S(0), S(0), S(1)), S(0));
  Tf<S> pose = Tf<S>::Identity();
  pose.translation() = V3<S>(S(3), S(-1), S(0.4));  // 0.1 deep
  ::fcl::CollisionResult<S> gq, fcl;
  gq::fcl::collide(&box, pose, &floor, Tf<S>::Identity(), ::fcl::CollisionRequest<S>(1, true), gq);
  ::fcl::collide(&box, pose, &floor, Tf<S>::Identity(), ::fcl::CollisionRequest<S>(1, true), fcl);
  ASSERT_EQ(gq.numContacts(), 1u);
  EXPECT_NEAR((gq.getContact(0).pos - V3<S>(S(3), S(-1), S(-0.05))).norm(), S(0), S(1e-6));
  expectSameContact(gq.getContact(0), fcl.getContact(0), "resting box");
}

// A two-sided Plane: FCL puts the point on the plane, by its rule per shape. Aligned poses put the plane at identity
// (faces, side lines and discs parallel to it). Where FCL's cylinder depth is not gq's (listed "cylinder-plane"),
// the contact is not compared.
TYPED_TEST(FclContactPosition, ShapeAgainstPlaneIsPlacedOnThePlaneAsFcl) {
  using S = TypeParam;
  std::mt19937 rng(4205);
  const ::fcl::Plane<S> tilted(V3<S>(S(-0.4), S(0.5), S(1)).normalized(), S(-0.1)), flat(V3<S>(S(0), S(0), S(1)), S(0));
  int compared = 0, aligned = 0;
  for (Kind k : {Kind::Sphere, Kind::Box, Kind::Capsule, Kind::Cylinder, Kind::Cone}) {
    const auto shape = makeShape<S>(k);
    for (int i = 0; i < 400; ++i) {
      const bool align = i % 2 == 1;
      const Tf<S> ps = align ? alignedPose<S>(rng, 0.8) : randomPose<S>(rng, 0.8);
      const Tf<S> pp = align ? Tf<S>::Identity() : randomPose<S>(rng, 0.3);
      const ::fcl::Plane<S>& plane = align ? flat : tilted;
      const V3<S> n = pp.linear() * plane.n;
      const S d = plane.d + n.dot(pp.translation());
      for (bool shapeFirst : {true, false}) {
        const std::string what = std::string(name(k)) + (shapeFirst ? "-Plane" : " (Plane first)") + " pose " +
                                 std::to_string(i);
        const ::fcl::CollisionRequest<S> request(1, true);
        ::fcl::CollisionResult<S> gq, fcl;
        if (shapeFirst) {
          gq::fcl::collide(shape.get(), ps, &plane, pp, request, gq);
          ::fcl::collide(shape.get(), ps, &plane, pp, request, fcl);
        } else {
          gq::fcl::collide(&plane, pp, shape.get(), ps, request, gq);
          ::fcl::collide(&plane, pp, shape.get(), ps, request, fcl);
        }
        if (gq.numContacts() == 0 || fcl.numContacts() == 0) continue;
        const ::fcl::Contact<S>& g = gq.getContact(0);
        EXPECT_NEAR(n.dot(g.pos) - d, S(0), tolerance<S>()) << what << ": not on the plane";
        if (k == Kind::Cylinder &&
            std::abs(g.penetration_depth - fcl.getContact(0).penetration_depth) > tolerance<S>())
          continue;
        expectSameContact(g, fcl.getContact(0), what);
        ++compared;
        aligned += align;
      }
    }
  }
  EXPECT_GT(compared, 800);
  EXPECT_GT(aligned, 300);
}

// Sphere against capsule: FCL's point lies on the line from the nearest axis point to the sphere's centre, the
// depth away from the axis.
TYPED_TEST(FclContactPosition, SphereCapsulePointIsFcls) {
  using S = TypeParam;
  std::mt19937 rng(4206);
  ::fcl::Sphere<S> sphere(S(0.5));
  ::fcl::Capsule<S> capsule(S(0.3), S(1.4));
  int compared = 0;
  for (int i = 0; i < 500; ++i) {
    const Tf<S> ps = randomPose<S>(rng, 0.6), pc = randomPose<S>(rng, 0.6);
    for (bool sphereFirst : {true, false}) {
      ::fcl::CollisionResult<S> gq, fcl;
      const ::fcl::CollisionRequest<S> request(1, true);
      if (sphereFirst) {
        gq::fcl::collide(&sphere, ps, &capsule, pc, request, gq);
        ::fcl::collide(&sphere, ps, &capsule, pc, request, fcl);
      } else {
        gq::fcl::collide(&capsule, pc, &sphere, ps, request, gq);
        ::fcl::collide(&capsule, pc, &sphere, ps, request, fcl);
      }
      ASSERT_EQ(gq.numContacts(), fcl.numContacts()) << i;
      if (gq.numContacts() == 0) continue;
      // The exact point: the nearest axis point moved towards the centre by the depth.
      const V3<S> z = pc.linear().col(2), t = pc.translation(), c = ps.translation();
      const S along = std::clamp(z.dot(c - t), -capsule.lz / 2, capsule.lz / 2);
      const V3<S> axis = t + z * along;
      const V3<S> expected = axis + (c - axis).normalized() * gq.getContact(0).penetration_depth;
      EXPECT_NEAR((gq.getContact(0).pos - expected).norm(), S(0), tolerance<S>()) << i;
      expectSameContact(gq.getContact(0), fcl.getContact(0), "pose " + std::to_string(i));
      ++compared;
    }
  }
  EXPECT_GT(compared, 100);
}

TYPED_TEST(FclContactPosition, SphereSpherePointIsFcls) {
  using S = TypeParam;
  std::mt19937 rng(4204);
  ::fcl::Sphere<S> a(S(0.7)), b(S(0.4));
  int compared = 0;
  for (int i = 0; i < 500; ++i) {
    const Tf<S> pa = randomPose<S>(rng, 0.5), pb = randomPose<S>(rng, 0.5);
    ::fcl::CollisionResult<S> gq, fcl;
    gq::fcl::collide(&a, pa, &b, pb, ::fcl::CollisionRequest<S>(1, true), gq);
    ::fcl::collide(&a, pa, &b, pb, ::fcl::CollisionRequest<S>(1, true), fcl);
    ASSERT_EQ(gq.numContacts(), fcl.numContacts()) << i;
    if (gq.numContacts() == 0) continue;
    const V3<S> c1 = pa.translation(), c2 = pb.translation();
    EXPECT_NEAR((gq.getContact(0).pos - (c1 + (c2 - c1) * (a.radius / (a.radius + b.radius)))).norm(), S(0),
                tolerance<S>());
    expectSameContact(gq.getContact(0), fcl.getContact(0), "pose " + std::to_string(i));
    ++compared;
  }
  EXPECT_GT(compared, 100);
}

TYPED_TEST(FclContactPosition, ConcentricSpheresKeepAUnitNormalWhereFclsIsZero) {
  using S = TypeParam;
  ::fcl::Sphere<S> a(S(0.7)), b(S(0.4));
  const Tf<S> same = Tf<S>::Identity();
  ::fcl::CollisionResult<S> gq, fcl;
  gq::fcl::collide(&a, same, &b, same, ::fcl::CollisionRequest<S>(1, true), gq);
  ::fcl::collide(&a, same, &b, same, ::fcl::CollisionRequest<S>(1, true), fcl);
  ASSERT_EQ(gq.numContacts(), 1u);
  ASSERT_EQ(fcl.numContacts(), 1u);
  EXPECT_EQ(fcl.getContact(0).normal, V3<S>::Zero());
  EXPECT_NEAR(gq.getContact(0).normal.norm(), S(1), S(1e-6));
  EXPECT_NEAR(gq.getContact(0).penetration_depth, S(1.1), S(1e-6));
  EXPECT_NEAR(gq.getContact(0).pos.norm(), S(0), S(1e-6));  // FCL's point, c1
}

using gq::fcltest::Difference;
using gq::fcltest::readDifferences;

// Each listed difference names the test that checks it, and that test exists in this program.
TEST(FclDeliberateDifferences, EachListedDifferenceNamesAnExistingTest) {
  const std::vector<Difference> list = readDifferences();
  ASSERT_FALSE(list.empty()) << "tests/fcl/deliberate_differences.txt";
  std::set<std::string> tests;
  const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
  for (int i = 0; i < unit.total_test_suite_count(); ++i) {
    const ::testing::TestSuite& suite = *unit.GetTestSuite(i);
    // "Suite", "Suite/0" (typed) or "Prefix/Suite" (parameterized); "Test" or "Test/Param".
    const std::string full = suite.name();
    const std::size_t slash = full.find('/');
    const std::vector<std::string> suiteNames = {full.substr(0, slash),
                                                 slash == std::string::npos ? full : full.substr(slash + 1)};
    for (int j = 0; j < suite.total_test_count(); ++j) {
      const std::string testName = suite.GetTestInfo(j)->name();
      for (const std::string& s : suiteNames) tests.insert(s + "." + testName.substr(0, testName.find('/')));
    }
  }
  std::set<std::string> ids;
  for (const Difference& d : list) {
    EXPECT_TRUE(ids.insert(d.id).second) << "listed twice: " << d.id;
    EXPECT_TRUE(tests.count(d.test)) << d.id << " names " << d.test << ", which is not a test of gq_fcl_tests";
  }
}

}  // namespace
