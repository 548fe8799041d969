// The solid-pair fast path (adapters/fcl/src/solid_pairs.h): FCL parameters and matrices read in place.
//  - Capsule/box distance (core's closed form, new with the fast path) against an independent long-double
//    reference: the distance from the capsule's segment to the box is convex along the segment, so a ternary search
//    of |p(s) - clamp(p(s))| over s converges to the exact minimum.
//  - Penetrating capsule/box: the reported depth is the exact minimum translation along the reported normal (moving
//    o2 by depth +- 1e-7 along it separates / does not), checked with the same reference.
//  - Overlapping boxes (core's SAT with witnesses from the touching configuration): the exact SAT depth
//    (exact_reference.h), and witnesses on both box surfaces, point1 = point0 - depth * normal.
//  - What the fast path validates (reflections of symmetric shapes, scaled linear parts) and computes (no nearest
//    points unless asked).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "exact_reference.h"
#include "fcl_scenes.h"
#include "gq/cooking.h"
#include "gq/fcl/fcl.h"

namespace {

using ::fcl::Vector3d;
using gq::fcltest::randomPose;
using Vec3L = Eigen::Matrix<long double, 3, 1>;

constexpr int kPoses = 1000;
constexpr double kExactTolerance = 1e-9;

// Exact distance from the capsule's segment (FCL: local Z, full length lz) to the box (sides `side`), long double.
long double segmentBoxDistance(double lz, const ::fcl::Transform3d& capsulePose, const Vector3d& side,
                               const ::fcl::Transform3d& boxPose) {
  const Eigen::Matrix<long double, 3, 3> rb = boxPose.linear().cast<long double>();
  const Vec3L tb = boxPose.translation().cast<long double>();
  const Vec3L centre = rb.transpose() * (capsulePose.translation().cast<long double>() - tb);
  const Vec3L half = rb.transpose() * (capsulePose.linear().col(2).cast<long double>() * (lz / 2.0L));
  const Vec3L h = side.cast<long double>() / 2.0L;
  const auto at = [&](long double s) {
    const Vec3L p = centre + s * half;
    return (p - p.cwiseMax(-h).cwiseMin(h)).norm();
  };
  long double lo = -1, hi = 1;
  for (int i = 0; i < 300; ++i) {
    const long double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (at(m1) <= at(m2)) hi = m2; else lo = m1;
  }
  return std::min({at(-1), at(1), at((lo + hi) / 2)});
}

struct CapsuleBox {
  ::fcl::Capsuled capsule{0.3, 0.9};
  ::fcl::Boxd box{1.0, 0.6, 0.8};
  long double exactSigned(const ::fcl::Transform3d& pc, const ::fcl::Transform3d& pb) const {
    return segmentBoxDistance(capsule.lz, pc, box.side, pb) - capsule.radius;
  }
};

TEST(FclSolidPairs, CapsuleBoxDistanceEqualsTheExactSegmentBoxDistance) {
  const CapsuleBox s;
  std::mt19937 rng(17);
  int separated = 0;
  for (int i = 0; i < kPoses; ++i) {
    const ::fcl::Transform3d pc = randomPose(rng, 1.0), pb = randomPose(rng, 1.0);
    const long double exact = s.exactSigned(pc, pb);
    if (exact <= 1e-7L) continue;
    for (bool capsuleFirst : {true, false}) {
      ::fcl::DistanceResultd r;
      const double d = capsuleFirst ? gq::fcl::distance<double>(&s.capsule, pc, &s.box, pb, ::fcl::DistanceRequestd(true), r)
                                    : gq::fcl::distance<double>(&s.box, pb, &s.capsule, pc, ::fcl::DistanceRequestd(true), r);
      EXPECT_NEAR(d, double(exact), kExactTolerance) << "pose " << i;
      // The witnesses realise the distance and lie on the shapes: on the box surface and at the capsule radius.
      const Vector3d onCapsule = r.nearest_points[capsuleFirst ? 0 : 1], onBox = r.nearest_points[capsuleFirst ? 1 : 0];
      EXPECT_NEAR((onCapsule - onBox).norm(), double(exact), 1e-9) << "pose " << i;
      const Vector3d local = pb.inverse() * onBox;
      EXPECT_NEAR((local.cwiseAbs() - s.box.side / 2).maxCoeff(), 0.0, 1e-12) << "pose " << i;
    }
    ++separated;
  }
  EXPECT_GT(separated, 100);
}

TEST(FclSolidPairs, CapsuleBoxPenetrationDepthIsTheExactTranslationAlongItsNormal) {
  const CapsuleBox s;
  std::mt19937 rng(18);
  int penetrating = 0;
  for (int i = 0; i < kPoses; ++i) {
    const ::fcl::Transform3d pc = randomPose(rng, 0.8), pb = randomPose(rng, 0.8);
    if (s.exactSigned(pc, pb) >= -1e-6L) continue;
    ::fcl::DistanceRequestd request(true);
    request.enable_signed_distance = true;
    ::fcl::CollisionRequestd contactRequest(1, true);
    gq::fcl::Options minimumTranslation;
    minimumTranslation.minimumTranslation = true;
    ::fcl::CollisionResultd c;
    gq::fcl::collide<double>(&s.capsule, pc, &s.box, pb, contactRequest, c, minimumTranslation);
    ASSERT_EQ(c.numContacts(), 1u) << "pose " << i;
    const ::fcl::Contactd& contact = c.getContact(0);
    ::fcl::DistanceResultd r;
    EXPECT_NEAR(gq::fcl::distance<double>(&s.capsule, pc, &s.box, pb, request, r), -contact.penetration_depth, 1e-12);
    ::fcl::Transform3d apart = pb, still = pb;
    apart.translation() += contact.normal * (contact.penetration_depth + 1e-7);
    still.translation() += contact.normal * (contact.penetration_depth - 1e-7);
    EXPECT_GT(s.exactSigned(pc, apart), 0.0L) << "pose " << i << ": moving o2 by the depth does not separate";
    EXPECT_LT(s.exactSigned(pc, still), 0.0L) << "pose " << i << ": the depth is more than needed";
    ++penetrating;
  }
  EXPECT_GT(penetrating, 100);
}

// Largest |local coordinate| - half side: 0 on the box surface.
double surfaceOffset(const Vector3d& world, const ::fcl::Transform3d& pose, const Vector3d& side) {
  return ((pose.inverse() * world).cwiseAbs() - side / 2).maxCoeff();
}

TEST(FclSolidPairs, OverlappingBoxesGetTheExactDepthWithWitnessesOnBothSurfaces) {
  std::mt19937 rng(20);
  const gq::fcltest::TestShape a = gq::fcltest::makeShape(gq::fcltest::Kind::Box, rng);
  const gq::fcltest::TestShape b = gq::fcltest::makeShape(gq::fcltest::Kind::Box, rng);
  int penetrating = 0;
  for (int i = 0; i < kPoses; ++i) {
    const ::fcl::Transform3d pa = randomPose(rng, 0.8), pb = randomPose(rng, 0.8);
    long double exact = 0;
    if (!gq::fcltest::exactDepth(a, pa, b, pb, exact) || exact < 1e-7L) continue;
    ::fcl::DistanceRequestd request(true);
    request.enable_signed_distance = true;
    ::fcl::DistanceResultd r;
    const double d = gq::fcl::distance<double>(a.geometry.get(), pa, b.geometry.get(), pb, request, r);
    EXPECT_NEAR(d, -double(exact), kExactTolerance) << "pose " << i;
    EXPECT_NEAR(surfaceOffset(r.nearest_points[0], pa, a.size), 0.0, 1e-9) << "pose " << i;
    EXPECT_NEAR(surfaceOffset(r.nearest_points[1], pb, b.size), 0.0, 1e-9) << "pose " << i;
    EXPECT_NEAR((r.nearest_points[1] - r.nearest_points[0]).norm(), double(exact), 1e-9) << "pose " << i;
    ++penetrating;
  }
  EXPECT_GT(penetrating, 100);
}

TEST(FclSolidPairs, AReflectedLinearPartPlacesTheSameSymmetricShape) {
  ::fcl::Boxd box(1.0, 0.6, 0.8);
  ::fcl::Capsuled capsule(0.3, 0.9);
  std::mt19937 rng(19);
  for (int i = 0; i < 100; ++i) {
    const ::fcl::Transform3d pc = randomPose(rng, 1.0), pb = randomPose(rng, 1.0);
    ::fcl::Transform3d mirrored = pb;
    mirrored.linear() = pb.linear() * Eigen::Vector3d(1, 1, -1).asDiagonal();
    ::fcl::DistanceResultd d1, d2;
    const double a = gq::fcl::distance<double>(&capsule, pc, &box, pb, ::fcl::DistanceRequestd(true), d1);
    const double b = gq::fcl::distance<double>(&capsule, pc, &box, mirrored, ::fcl::DistanceRequestd(true), d2);
    EXPECT_NEAR(a, b, 1e-12) << "pose " << i;
  }
}

TEST(FclSolidPairs, AScaledLinearPartIsRejectedForBoxAndCapsule) {
  ::fcl::Boxd box(1.0, 0.6, 0.8);
  ::fcl::Capsuled capsule(0.3, 0.9);
  ::fcl::Transform3d scaled = ::fcl::Transform3d::Identity();
  scaled.linear() *= 1.01;  // beyond the tolerance of a rotation (|q| = 1 +- 1e-3)
  ::fcl::Transform3d nearlyRotation = ::fcl::Transform3d::Identity();
  nearlyRotation.linear() *= 1.0001;  // within it
  const ::fcl::Transform3d origin = ::fcl::Transform3d::Identity();
  for (const ::fcl::CollisionGeometryd* g : {static_cast<const ::fcl::CollisionGeometryd*>(&box),
                                             static_cast<const ::fcl::CollisionGeometryd*>(&capsule)}) {
    ::fcl::CollisionResultd c;
    EXPECT_EQ(gq::fcl::collide<double>(g, scaled, &box, origin, ::fcl::CollisionRequestd(), c), 0u);
    EXPECT_EQ(c.numContacts(), 0u);
    ::fcl::DistanceResultd d;
    EXPECT_EQ(gq::fcl::distance<double>(&box, origin, g, scaled, ::fcl::DistanceRequestd(true), d),
              std::numeric_limits<double>::max());
    EXPECT_EQ(d.o1, nullptr);
    ::fcl::CollisionResultd ok;
    EXPECT_EQ(gq::fcl::collide<double>(g, nearlyRotation, &box, origin, ::fcl::CollisionRequestd(), ok), 1u);
  }
}

// Two Convex decided by their hulls' balls (deeply overlapping, or far apart) still validate the transforms as the
// GJK path does: a hull is not symmetric, so a reflection is rejected as a scaled linear part is. A miss on bad
// input is told from a miss by the return value: 0 instead of the result's count.
// A Convex over 30 random points (seeded), with its vertices.
std::shared_ptr<::fcl::Convexd> randomConvex(unsigned seed, std::vector<Vector3d>& vertices) {
  std::mt19937 rng(seed);
  std::vector<std::vector<int>> faces;
  gq::fcltest::randomHull(rng, 30, vertices, faces);
  return gq::fcltest::convexGeometry(vertices, faces);
}

// collide's return for a pair, on a result pre-seeded with one contact: 1 on a miss, 2 on a hit, 0 on bad input.
std::size_t collideOnSeededResult(const ::fcl::Convexd& hull, const ::fcl::Transform3d& at) {
  ::fcl::CollisionRequestd request;
  request.num_max_contacts = 4;  // room beside the pre-seeded contact
  ::fcl::CollisionResultd c;
  c.addContact(::fcl::Contactd());
  const std::size_t count = gq::fcl::collide<double>(&hull, ::fcl::Transform3d::Identity(), &hull, at, request, c);
  EXPECT_EQ(c.numContacts(), count == 0 ? 1u : count);  // bad input writes nothing
  return count;
}

TEST(FclSolidPairs, ConvexPairsDecidedByTheirBallsRejectReflectedAndScaledLinearParts) {
  std::vector<Vector3d> vertices;
  const auto hull = randomConvex(23, vertices);
  const ::fcl::Transform3d origin = ::fcl::Transform3d::Identity();
  ::fcl::Transform3d far = origin;
  far.translation() = Vector3d(20, 0, 0);
  for (const ::fcl::Transform3d& at : {origin, far}) {
    ::fcl::Transform3d reflected = at, scaled = at, rotated = at;
    reflected.linear() = Eigen::Vector3d(1, 1, -1).asDiagonal();
    scaled.linear() *= 1.01;
    rotated.linear() = Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const bool hit = at.translation().norm() == 0;
    EXPECT_EQ(collideOnSeededResult(*hull, reflected), 0u);
    EXPECT_EQ(collideOnSeededResult(*hull, scaled), 0u);
    EXPECT_EQ(collideOnSeededResult(*hull, rotated), hit ? 2u : 1u);
  }
}

// Two Convex their balls cannot decide (centres between the inner and the outer balls' reach) go to GJK, placed by
// FCL's matrices as given: a reflection or a scaled linear part is rejected there too, in collide and in distance.
TEST(FclSolidPairs, ConvexPairsLeftToGjkRejectReflectedAndScaledLinearParts) {
  std::vector<Vector3d> vertices;
  const auto hull = randomConvex(29, vertices);
  std::shared_ptr<const gq::ConvexMesh<double>> cooked;
  ASSERT_TRUE(gq::cookConvexMesh(std::vector<gq::Vec3<double>>(vertices.begin(), vertices.end()), cooked).ok());
  const double reach = cooked->innerRadius + cooked->outerRadius;  // halfway between both balls' contact distances
  const ::fcl::Transform3d origin = ::fcl::Transform3d::Identity();
  ::fcl::Transform3d reflected = origin, scaled = origin, rotated = origin;
  rotated.linear() = Eigen::AngleAxisd(0.05, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  reflected.linear() = Eigen::Vector3d(1, 1, -1).asDiagonal();
  scaled.linear() *= 1.01;
  for (::fcl::Transform3d* t : {&reflected, &scaled, &rotated}) {
    t->translation() = Vector3d(reach, 0, 0) + cooked->center - t->linear() * cooked->center;  // centres `reach` apart
    const double centres = (t->linear() * cooked->center + t->translation() - cooked->center).norm();
    ASSERT_GT(centres, 2 * cooked->innerRadius + 0.01);
    ASSERT_LT(centres, 2 * cooked->outerRadius - 0.01);
  }
  for (const ::fcl::Transform3d& bad : {reflected, scaled}) {
    EXPECT_EQ(collideOnSeededResult(*hull, bad), 0u);
    ::fcl::DistanceResultd d;
    d.min_distance = 5;
    EXPECT_EQ(gq::fcl::distance<double>(hull.get(), origin, hull.get(), bad, ::fcl::DistanceRequestd(true), d),
              std::numeric_limits<double>::max());
    EXPECT_EQ(d.min_distance, 5);
  }
  EXPECT_NE(collideOnSeededResult(*hull, rotated), 0u);
  ::fcl::DistanceResultd d;
  EXPECT_LT(gq::fcl::distance<double>(hull.get(), origin, hull.get(), rotated, ::fcl::DistanceRequestd(true), d),
            std::numeric_limits<double>::max());
}

// Two Convex with their centres in the band the hulls' balls cannot decide, in random orientations: collide agrees
// with the exact SAT answer on every pose. The band is where the adapter's centre-line certificate (a point of one
// inner ball inside the other hull) answers before GJK, so a wrong certificate shows here as a false hit.
TEST(FclSolidPairs, ConvexPairsInTheBallsBandMatchTheExactAnswer) {
  std::mt19937 rng(31);
  const gq::fcltest::TestShape a = gq::fcltest::makeShape(gq::fcltest::Kind::Convex, rng);
  const gq::fcltest::TestShape b = gq::fcltest::makeShape(gq::fcltest::Kind::Convex, rng);
  std::shared_ptr<const gq::ConvexMesh<double>> ha, hb;
  ASSERT_TRUE(gq::cookConvexMesh(std::vector<gq::Vec3<double>>(a.vertices.begin(), a.vertices.end()), ha).ok());
  ASSERT_TRUE(gq::cookConvexMesh(std::vector<gq::Vec3<double>>(b.vertices.begin(), b.vertices.end()), hb).ok());
  std::uniform_real_distribution<double> unit(0, 1);
  std::normal_distribution<double> normal(0, 1);
  int hits = 0, misses = 0;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Quaterniond qa(normal(rng), normal(rng), normal(rng), normal(rng));
    const Eigen::Quaterniond qb(normal(rng), normal(rng), normal(rng), normal(rng));
    ::fcl::Transform3d pa = ::fcl::Transform3d::Identity(), pb = ::fcl::Transform3d::Identity();
    pa.linear() = qa.normalized().toRotationMatrix();
    pb.linear() = qb.normalized().toRotationMatrix();
    // Centres apart by a distance between the inner balls' and the outer balls' reach, in a random direction.
    const double lo = ha->innerRadius + hb->innerRadius, hi = ha->outerRadius + hb->outerRadius;
    const Vector3d dir = Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    const Vector3d ca = pa.linear() * ha->center, cb = pb.linear() * hb->center;
    pa.translation() = -ca;
    pb.translation() = (lo + (hi - lo) * unit(rng)) * dir - cb;
    const gq::fcltest::ExactAnswer exact = gq::fcltest::exactAnswer(a, pa, b, pb);
    ASSERT_TRUE(exact.known);
    ::fcl::CollisionResultd result;
    const bool hit = gq::fcl::collide(a.geometry.get(), pa, b.geometry.get(), pb, ::fcl::CollisionRequestd(), result) > 0;
    EXPECT_EQ(hit, exact.colliding) << "pose " << i;
    (exact.colliding ? hits : misses) += 1;
  }
  EXPECT_GT(hits, 200);
  EXPECT_GT(misses, 200);
}

// FCL 0.7 writes them in both modes (its shape traversal always passes its solver's points to update()).
TEST(FclSolidPairs, NearestPointsAreWrittenWhetherRequestedOrNot) {
  ::fcl::Sphered sphere(0.5);
  ::fcl::Boxd box(1.0, 1.0, 1.0);
  ::fcl::Transform3d far = ::fcl::Transform3d::Identity();
  far.translation() = Vector3d(3, 0, 0);
  ::fcl::DistanceResultd without, with;
  without.nearest_points[0] = without.nearest_points[1] = Vector3d(7, 7, 7);
  EXPECT_NEAR(gq::fcl::distance<double>(&sphere, ::fcl::Transform3d::Identity(), &box, far, ::fcl::DistanceRequestd(false), without), 2.0, 1e-12);
  gq::fcl::distance<double>(&sphere, ::fcl::Transform3d::Identity(), &box, far, ::fcl::DistanceRequestd(true), with);
  for (const ::fcl::DistanceResultd* r : {&without, &with}) {
    EXPECT_NEAR((r->nearest_points[0] - Vector3d(0.5, 0, 0)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((r->nearest_points[1] - Vector3d(2.5, 0, 0)).norm(), 0.0, 1e-12);
  }
}

}  // namespace
