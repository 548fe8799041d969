// Every DART shape gq models converts and answers: a ray straight down onto each hits its top where DART's geometry
// puts it; a shape whose version changes is converted again.
#include <gtest/gtest.h>

#include <dart/collision/RaycastResult.hpp>
#include <dart/dynamics/ConeShape.hpp>
#include <dart/dynamics/CylinderShape.hpp>
#include <dart/dynamics/EllipsoidShape.hpp>
#include <dart/dynamics/MultiSphereConvexHullShape.hpp>
#include <dart/dynamics/PlaneShape.hpp>
#include <dart/dynamics/PointCloudShape.hpp>
#include <dart/dynamics/PyramidShape.hpp>

#include "dart_scene.h"

namespace {

using namespace gqtest;

// The z of the first hit of a ray from (x, y, 10) down to (x, y, -10), or NaN when it misses.
double topAt(const dd::ShapePtr& shape, const Eigen::Isometry3d& tf, double x = 0.0, double y = 0.0) {
  auto d = detector("gq");
  auto f = frame(shape, tf);
  auto group = d->createCollisionGroup(f.get());
  dc::RaycastResult result;
  if (!d->raycast(group.get(), Eigen::Vector3d(x, y, 10), Eigen::Vector3d(x, y, -10), dc::RaycastOption(), &result)) {
    return std::nan("");
  }
  return result.mRayHits.front().mPoint.z();
}

const Eigen::Isometry3d kLifted = at(Eigen::Vector3d(0, 0, 1));

TEST(DartShapes, FactoryCreatesGqDetector) {
  auto d = detector("gq");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->getType(), "gq");
  EXPECT_EQ(d->cloneWithoutCollisionObjects()->getType(), "gq");
}

TEST(DartShapes, PrimitivesAnswerAtTheirTop) {
  EXPECT_NEAR(topAt(std::make_shared<dd::SphereShape>(0.5), kLifted), 1.5, 1e-9);
  EXPECT_NEAR(topAt(std::make_shared<dd::BoxShape>(Eigen::Vector3d(1, 2, 0.6)), kLifted), 1.3, 1e-9);
  // DART's capsule, cylinder and cone run along z; height is the cylindrical part's length.
  EXPECT_NEAR(topAt(std::make_shared<dd::CapsuleShape>(0.2, 1.0), kLifted), 1.7, 1e-9);
  EXPECT_NEAR(topAt(std::make_shared<dd::CylinderShape>(0.2, 1.0), kLifted), 1.5, 1e-9);
  EXPECT_NEAR(topAt(std::make_shared<dd::ConeShape>(0.4, 1.0), kLifted, 0.1, 0.0), 1.25, 1e-9);  // apex at +z
  EXPECT_NEAR(topAt(std::make_shared<dd::EllipsoidShape>(Eigen::Vector3d(1.0, 2.0, 0.8)), kLifted), 1.4, 1e-9);
  EXPECT_NEAR(topAt(std::make_shared<dd::PyramidShape>(1.0, 1.0, 0.6), kLifted), 1.3, 1e-9);
}

TEST(DartShapes, PlaneIsNormalDotXEqualsOffset) {
  // DART normalises the normal and keeps the offset: the plane z = 0.5 in its frame.
  EXPECT_NEAR(topAt(std::make_shared<dd::PlaneShape>(Eigen::Vector3d(0, 0, 2), 0.5), kLifted), 1.5, 1e-9);
}

TEST(DartShapes, MeshScaleIsHonoured) {
  auto mesh = groundMesh(1.0, 2, Eigen::Vector3d(1, 1, 1));
  EXPECT_NEAR(topAt(mesh, kLifted), 1.0, 1e-9);
  // A ground tilted by the scale's x only stays flat; scaled by 3 in x it reaches x = 2.5, unscaled it does not.
  EXPECT_TRUE(std::isnan(topAt(groundMesh(1.0, 2), kLifted, 2.5, 0.0)));
  EXPECT_NEAR(topAt(groundMesh(1.0, 2, Eigen::Vector3d(3, 1, 1)), kLifted, 2.5, 0.0), 1.0, 1e-9);
}

TEST(DartShapes, HeightmapIsCentredWithHeightsAlongZ) {
  // 5 x 5 samples 0.5 apart: x and y in [-1, 1]; heights 0.3 up.
  auto hm = flatHeightmap(5, 0.5, 0.3);
  EXPECT_NEAR(topAt(hm, kLifted, 0.9, -0.9), 1.3, 1e-6);  // float heights
  EXPECT_TRUE(std::isnan(topAt(hm, kLifted, 1.1, 0.0)));
  // A slope along x: height = column index (x), so z grows with x.
  auto slope = std::make_shared<dd::HeightmapShaped>();
  std::vector<double> heights;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) heights.push_back(c);
  slope->setHeightField(3, 3, heights);
  EXPECT_NEAR(topAt(slope, at(Eigen::Vector3d::Zero()), 0.5, 0.0), 1.5, 1e-9);
  // Depth rows run along -y: height = row index grows towards -y.
  auto rows = std::make_shared<dd::HeightmapShaped>();
  heights.clear();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) heights.push_back(r);
  rows->setHeightField(3, 3, heights);
  EXPECT_NEAR(topAt(rows, at(Eigen::Vector3d::Zero()), 0.0, -0.5), 1.5, 1e-9);
}

TEST(DartShapes, MultiSphereHullLiesWithinItsTolerance) {
  dd::MultiSphereConvexHullShape::Spheres spheres = {{0.3, Eigen::Vector3d(-0.5, 0, 0)},
                                                      {0.2, Eigen::Vector3d(0.5, 0, 0.1)}};
  auto shape = std::make_shared<dd::MultiSphereConvexHullShape>(spheres);
  const double top = topAt(shape, kLifted, -0.5, 0.0);
  EXPECT_LE(top, 1.3 + 1e-9);
  EXPECT_GE(top, 1.3 - 0.21 * 0.3);
}

TEST(DartShapes, ChangedShapeIsConvertedAgain) {
  auto box = std::make_shared<dd::BoxShape>(Eigen::Vector3d(1, 1, 1));
  auto d = detector("gq");
  auto f = frame(box, kLifted);
  auto group = d->createCollisionGroup(f.get());
  dc::RaycastResult result;
  ASSERT_TRUE(d->raycast(group.get(), Eigen::Vector3d(0, 0, 10), Eigen::Vector3d(0, 0, -10), dc::RaycastOption(),
                         &result));
  EXPECT_NEAR(result.mRayHits.front().mPoint.z(), 1.5, 1e-9);
  box->setSize(Eigen::Vector3d(1, 1, 3));
  ASSERT_TRUE(d->raycast(group.get(), Eigen::Vector3d(0, 0, 10), Eigen::Vector3d(0, 0, -10), dc::RaycastOption(),
                         &result));
  EXPECT_NEAR(result.mRayHits.front().mPoint.z(), 2.5, 1e-9);
}

TEST(DartShapes, UnmodelledShapeTakesPartInNoQuery) {
  auto cloud = std::make_shared<dd::PointCloudShape>();
  cloud->addPoint(Eigen::Vector3d::Zero());
  EXPECT_TRUE(std::isnan(topAt(cloud, kLifted)));
}

}  // namespace
