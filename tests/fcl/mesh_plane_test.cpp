// BVHModel against Halfspace and Plane through gq::fcl, answered by core's plane-mesh overlap and distance: closed
// forms on a two-triangle mesh, the same contacts as FCL's traversal, and the two-sided Plane's larger side.
#include <gtest/gtest.h>

#include <memory>
#include <set>

#include "gq/fcl/fcl.h"

namespace {

using ::fcl::Vector3d;

::fcl::Transform3d at(double x, double y, double z) {
  ::fcl::Transform3d tf = ::fcl::Transform3d::Identity();
  tf.translation() = Vector3d(x, y, z);
  return tf;
}

// Triangle 0 spans z in [0, 2] (a vertex at z = 0 and z = 2), triangle 1 lies flat at z = 5.
std::shared_ptr<::fcl::BVHModel<::fcl::OBBRSSd>> standingAndFlat() {
  auto model = std::make_shared<::fcl::BVHModel<::fcl::OBBRSSd>>();
  model->beginModel();
  model->addTriangle(Vector3d(0, 0, 0), Vector3d(1, 0, 2), Vector3d(0, 1, 1));
  model->addTriangle(Vector3d(5, 0, 5), Vector3d(6, 0, 5), Vector3d(5, 1, 5));
  model->endModel();
  return model;
}

TEST(FclMeshPlane, HalfspaceDistanceIsTheLowestVertexHeight) {
  auto mesh = standingAndFlat();
  ::fcl::Halfspaced below(Vector3d::UnitZ(), -0.5);  // z <= -0.5
  ::fcl::DistanceResultd r;
  const double d = gq::fcl::distance<double>(mesh.get(), at(0, 0, 0), &below, at(0, 0, 0), ::fcl::DistanceRequestd(true), r);
  EXPECT_NEAR(d, 0.5, 1e-12);
  EXPECT_NEAR((r.nearest_points[0] - Vector3d(0, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((r.nearest_points[1] - Vector3d(0, 0, -0.5)).norm(), 0.0, 1e-12);
  EXPECT_EQ(r.b1, 0);  // the triangle holding the vertex
  // Raised into the half-space by 0.25 + 0.5: minus the deepest vertex's depth.
  ::fcl::DistanceResultd deep;
  EXPECT_NEAR(gq::fcl::distance<double>(mesh.get(), at(0, 0, -0.75), &below, at(0, 0, 0), ::fcl::DistanceRequestd(true),
                                        deep),
              -0.25, 1e-12);
}

TEST(FclMeshPlane, HalfspaceContactsAreTheTrianglesReachingIt) {
  auto mesh = standingAndFlat();
  ::fcl::CollisionRequestd request(10, true);
  for (const double level : {-0.1, 0.0, 1.0, 5.5}) {  // z <= level (0: touching)
    ::fcl::Halfspaced h(Vector3d::UnitZ(), level);
    ::fcl::CollisionResultd mine, theirs;
    gq::fcl::collide<double>(mesh.get(), at(0, 0, 0), &h, at(0, 0, 0), request, mine);
    ::fcl::collide<double>(mesh.get(), at(0, 0, 0), &h, at(0, 0, 0), request, theirs);
    std::set<int> got;
    for (std::size_t c = 0; c < mine.numContacts(); ++c) got.insert(mine.getContact(c).b1);
    const std::set<int> expected = level < 0 ? std::set<int>{} : level < 5 ? std::set<int>{0} : std::set<int>{0, 1};
    EXPECT_EQ(got, expected) << level;
    if (level != 0.0) EXPECT_EQ(mine.isCollision(), theirs.isCollision()) << level;
    if (level == 1.0) {
      ASSERT_EQ(mine.numContacts(), 1u);
      EXPECT_NEAR(mine.getContact(0).penetration_depth, 1.0, 1e-12);  // the vertex at z = 0 is 1 below z = 1
    }
  }
}

TEST(FclMeshPlane, PlaneDistanceTakesTheLargerSideAndCrossingCollides) {
  auto mesh = standingAndFlat();
  // z = -1: the mesh lies above (lowest vertex 1 above): distance 1.
  ::fcl::Planed under(Vector3d::UnitZ(), -1);
  ::fcl::DistanceResultd r;
  EXPECT_NEAR(gq::fcl::distance<double>(mesh.get(), at(0, 0, 0), &under, at(0, 0, 0), ::fcl::DistanceRequestd(true), r),
              1.0, 1e-12);
  // z = 1 crosses triangle 0 (its vertices at z = 0, 1, 2) and passes below triangle 1: collide reports triangle 0.
  ::fcl::Planed through(Vector3d::UnitZ(), 1);
  ::fcl::CollisionRequestd request(10, false);
  ::fcl::CollisionResultd c;
  gq::fcl::collide<double>(mesh.get(), at(0, 0, 0), &through, at(0, 0, 0), request, c);
  ASSERT_EQ(c.numContacts(), 1u);
  EXPECT_EQ(c.getContact(0).b1, 0);
  // z = 3 lies between the triangles: no triangle crosses it although the mesh has vertices on both sides.
  ::fcl::Planed between(Vector3d::UnitZ(), 3);
  ::fcl::CollisionResultd none;
  gq::fcl::collide<double>(mesh.get(), at(0, 0, 0), &between, at(0, 0, 0), request, none);
  EXPECT_FALSE(none.isCollision());
}

}  // namespace
