// Box-box contact sets answered by gq against FCL 0.7's own box routine, float and double, on seeded poses of a box
// resting on another box's face (both orders, ground turned at random), by default and with each of Options'
// corrections: the same count for each num_max_contacts, and each contact one of FCL's full set with the same depth,
// normal and position.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <sstream>
#include <vector>

#include "gq/fcl/fcl.h"

namespace {

template <class S> using V3 = ::fcl::Vector3<S>;
template <class S> using Tf = ::fcl::Transform3<S>;

template <class S> struct FclBoxContactSets : ::testing::Test {
  static constexpr double kTol = std::is_same_v<S, double> ? 1e-9 : 2e-4;
};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(FclBoxContactSets, Scalars);

template <class S> Tf<S> turned(const Eigen::Quaterniond& q, const Eigen::Vector3d& t) {
  Tf<S> tf = Tf<S>::Identity();
  tf.linear() = q.toRotationMatrix().cast<S>();
  tf.translation() = t.cast<S>();
  return tf;
}

// Each of FCL's contacts has a gq contact with the same depth, normal and position (the sets as sets). `fcl` may be
// a larger set than `gq` (FCL's full set, when num_max_contacts keeps only some of equally deep points: which ones
// FCL keeps then depends on its sort's order among equals), then each of gq's contacts is one of FCL's.
template <class S>
void expectSameContacts(const ::fcl::CollisionResult<S>& fcl, const ::fcl::CollisionResult<S>& gq, double tol,
                        int trial) {
  if (gq.numContacts() < fcl.numContacts()) {
    ::fcl::CollisionResult<S> some;
    for (std::size_t j = 0; j < gq.numContacts(); ++j) some.addContact(gq.getContact(j));
    ::fcl::CollisionResult<S> chosen;
    for (std::size_t j = 0; j < gq.numContacts(); ++j)
      for (std::size_t i = 0; i < fcl.numContacts(); ++i)
        if ((fcl.getContact(i).pos - gq.getContact(j).pos).template cast<double>().norm() < tol) {
          chosen.addContact(fcl.getContact(i));
          break;
        }
    expectSameContacts(chosen, some, tol, trial);
    return;
  }
  ASSERT_EQ(gq.numContacts(), fcl.numContacts()) << "trial " << trial;
  std::vector<bool> used(gq.numContacts(), false);
  for (std::size_t i = 0; i < fcl.numContacts(); ++i) {
    const ::fcl::Contact<S>& f = fcl.getContact(i);
    bool found = false;
    for (std::size_t j = 0; j < gq.numContacts() && !found; ++j) {
      const ::fcl::Contact<S>& g = gq.getContact(j);
      if (used[j]) continue;
      if (std::abs(double(f.penetration_depth - g.penetration_depth)) < tol &&
          (f.normal - g.normal).template cast<double>().norm() < tol &&
          (f.pos - g.pos).template cast<double>().norm() < tol)
        used[j] = found = true;
    }
    if (!found) {
      std::ostringstream gqContacts;
      for (std::size_t j = 0; j < gq.numContacts(); ++j)
        gqContacts << "\n  gq depth " << gq.getContact(j).penetration_depth << " normal "
                   << gq.getContact(j).normal.transpose() << " pos " << gq.getContact(j).pos.transpose();
      ADD_FAILURE() << "trial " << trial << " FCL contact " << i << " depth " << f.penetration_depth << " normal "
                    << f.normal.transpose() << " pos " << f.pos.transpose() << gqContacts.str();
    }
  }
}

// The box-box contact set is the same with the opt-in corrections (its deepest point is already the exact minimum
// translation they ask for).
std::vector<gq::fcl::Options> boxOptions() {
  std::vector<gq::fcl::Options> all(3);
  all[1].minimumTranslation = true;
  all[2].exactContainedBoxDepth = true;
  return all;
}

TYPED_TEST(FclBoxContactSets, RestingBoxMatchesFclsFaceSet) {
  using S = TypeParam;
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(-1, 1), size(0.3, 1.2), depth(0.001, 0.05);
  int compared = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Quaterniond groundTurn =
        Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized();
    const Eigen::Vector3d groundAt(u(rng), u(rng), u(rng));
    const double hx = size(rng), hy = size(rng), hz = size(rng);
    auto ground = std::make_shared<::fcl::Box<S>>(S(6), S(6), S(1));
    auto top = std::make_shared<::fcl::Box<S>>(S(2 * hx), S(2 * hy), S(2 * hz));
    // Resting on the ground's +z face, well inside it (the footprint stays within the face), turned about z.
    const double yaw = 3 * u(rng), d = depth(rng);
    const Eigen::Vector3d local(1.2 * u(rng), 1.2 * u(rng), 0.5 + hz - d);
    const Eigen::Quaterniond topTurn = groundTurn * Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
    const Tf<S> pg = turned<S>(groundTurn, groundAt), pt = turned<S>(topTurn, groundAt + groundTurn * local);
    for (std::size_t maxContacts : {std::size_t(1), std::size_t(2), std::size_t(4), std::size_t(8)}) {
      const ::fcl::CollisionRequest<S> request(maxContacts, true);
      for (bool topFirst : {true, false}) {
        ::fcl::CollisionResult<S> fcl, fullFcl;
        const ::fcl::CollisionRequest<S> full(4, true);
        const auto* o1 = topFirst ? top.get() : ground.get();
        const auto* o2 = topFirst ? ground.get() : top.get();
        const Tf<S>& p1 = topFirst ? pt : pg;
        const Tf<S>& p2 = topFirst ? pg : pt;
        ::fcl::collide(o1, p1, o2, p2, request, fcl);
        ::fcl::collide(o1, p1, o2, p2, full, fullFcl);
        ASSERT_EQ(fcl.numContacts(), std::min<std::size_t>(maxContacts, 4)) << "trial " << trial;
        for (const gq::fcl::Options& options : boxOptions()) {
          ::fcl::CollisionResult<S> gq;
          gq::fcl::collide(o1, p1, o2, p2, request, gq, options);
          ASSERT_EQ(gq.numContacts(), fcl.numContacts()) << "trial " << trial;
          expectSameContacts(fullFcl, gq, this->kTol, trial);
          ++compared;
        }
      }
    }
  }
  EXPECT_EQ(compared, 300 * 4 * 2 * int(boxOptions().size()));
}

// A box turned on a smaller box's face, both overlapping its edges: the clipped polygon has up to 8 corners, culled to
// FCL's 4 (the deepest, then by angle about the centroid); the same 4 points as FCL for each num_max_contacts.
TYPED_TEST(FclBoxContactSets, ClippedPolygonIsCulledAsFcl) {
  using S = TypeParam;
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u(-1, 1), yaw(0.2, 1.3), tilt(-0.02, 0.02), depth(0.001, 0.02);
  int culled = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Quaterniond groundTurn = Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized();
    const Eigen::Vector3d groundAt(u(rng), u(rng), u(rng));
    auto ground = std::make_shared<::fcl::Box<S>>(S(1), S(1), S(1));
    auto top = std::make_shared<::fcl::Box<S>>(S(1.2), S(1.1), S(0.5));
    // Slightly tilted about two axes so that no two clipped points are equally deep (FCL's deepest is then its
    // polygon's first in order, which need not be gq's); centred over the face, turned about its normal.
    const Eigen::Quaterniond topTurn = groundTurn * Eigen::Quaterniond(Eigen::AngleAxisd(yaw(rng), Eigen::Vector3d::UnitZ())) *
                                       Eigen::Quaterniond(Eigen::AngleAxisd(tilt(rng), Eigen::Vector3d::UnitX())) *
                                       Eigen::Quaterniond(Eigen::AngleAxisd(tilt(rng), Eigen::Vector3d::UnitY()));
    const Eigen::Vector3d local(0.05 * u(rng), 0.05 * u(rng), 0.5 + 0.25 - depth(rng));
    const Tf<S> pg = turned<S>(groundTurn, groundAt), pt = turned<S>(topTurn, groundAt + groundTurn * local);
    for (std::size_t maxContacts : {std::size_t(1), std::size_t(3), std::size_t(4), std::size_t(8)}) {
      const ::fcl::CollisionRequest<S> request(maxContacts, true);
      ::fcl::CollisionResult<S> fcl, gq, fullFcl;
      ::fcl::collide(top.get(), pt, ground.get(), pg, request, fcl);
      ::fcl::collide(top.get(), pt, ground.get(), pg, ::fcl::CollisionRequest<S>(4, true), fullFcl);
      gq::fcl::collide(top.get(), pt, ground.get(), pg, request, gq);
      ASSERT_GT(gq.numContacts(), 0u) << "trial " << trial;
      ASSERT_GT(fcl.numContacts(), 0u) << "trial " << trial;
      // An overhanging edge pair can be the minimum translation, which FCL's face bias passes over (the listed
      // box-box-face-bias, FclFullResults): compared where FCL's normal is gq's exact one.
      if ((gq.getContact(0).normal - fcl.getContact(0).normal).template cast<double>().norm() > this->kTol) continue;
      ASSERT_EQ(gq.numContacts(), fcl.numContacts()) << "trial " << trial;
      expectSameContacts(fullFcl, gq, this->kTol, trial);
      culled += maxContacts == 4 && fullFcl.numContacts() == 4;
    }
  }
  EXPECT_GE(culled, 5);  // 8 of 200 poses in double, 93 in float: the others' minimum translation is an edge pair
}

// Separated boxes: no contact, as FCL.
TYPED_TEST(FclBoxContactSets, SeparatedBoxesHaveNone) {
  using S = TypeParam;
  ::fcl::Box<S> a(S(1), S(1), S(1)), b(S(1), S(1), S(1));
  Tf<S> pb = Tf<S>::Identity();
  pb.translation() = V3<S>(S(0), S(0), S(1.01));
  ::fcl::CollisionResult<S> gq;
  EXPECT_EQ(gq::fcl::collide(&a, Tf<S>::Identity(), &b, pb, ::fcl::CollisionRequest<S>(4, true), gq), 0u);
}

}  // namespace
