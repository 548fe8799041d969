// Options::meshFitting (gq/fcl/fit.h): with it set, a triangle BVHModel answers as its fit's parts do (the fit
// fitShape gives for its triangles), contacts name the model; without it, answers are the triangles'.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/math/bv/OBBRSS.h>

#include "gq/fcl/collision.h"
#include "gq/fcl/fit.h"
#include "gq/fit.h"

namespace {

using Model = ::fcl::BVHModel<::fcl::OBBRSS<double>>;

// A closed torus about Z (ring radius 1, tube radius 0.3): non-convex, with a hole of radius 0.7.
void torus(std::vector<::fcl::Vector3<double>>& v, std::vector<::fcl::Triangle>& t) {
  const int rings = 24, sides = 12;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const double u = 2 * M_PI * i / rings, w = 2 * M_PI * j / sides, r = 1 + 0.3 * std::cos(w);
      v.emplace_back(r * std::cos(u), r * std::sin(u), 0.3 * std::sin(w));
    }
  const auto at = [&](int i, int j) { return std::size_t((i % rings) * sides + j % sides); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      t.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      t.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
}

std::shared_ptr<Model> torusModel() {
  std::vector<::fcl::Vector3<double>> v;
  std::vector<::fcl::Triangle> t;
  torus(v, t);
  auto model = std::make_shared<Model>();
  model->beginModel();
  model->addSubModel(v, t);
  model->endModel();
  return model;
}

::fcl::Transform3<double> seededPose(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  ::fcl::Transform3<double> tf = ::fcl::Transform3<double>::Identity();
  tf.translation() = ::fcl::Vector3<double>(u(rng), u(rng), 0.5 * u(rng));
  return tf;
}

class MeshFittingTest : public ::testing::Test {
 protected:
  void SetUp() override {
    fitting.tolerance = 1.0;  // the torus's hull is 0.74 off (the hole)
    fitting.allowed = gq::fitBit(gq::FitRepresentation::ConvexHull);
    on.meshFitting = &fitting;
  }
  void TearDown() override { gq::fcl::clearGeometryCache(); }
  std::shared_ptr<Model> model = torusModel();
  gq::fcl::MeshFitting fitting;  // the hull within 1.0, what the tests with fitting on use
  gq::fcl::Options on;
  std::shared_ptr<::fcl::Sphere<double>> ball = std::make_shared<::fcl::Sphere<double>>(0.2);
  ::fcl::Transform3<double> modelPose = ::fcl::Transform3<double>(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()));
};

bool collides(const ::fcl::CollisionGeometry<double>* a, const ::fcl::Transform3<double>& ta,
              const ::fcl::CollisionGeometry<double>* b, const ::fcl::Transform3<double>& tb,
              const gq::fcl::Options& options) {
  ::fcl::CollisionResult<double> result;
  return gq::fcl::collide(a, ta, b, tb, ::fcl::CollisionRequest<double>(), result, options) > 0;
}

double distanceOf(const ::fcl::CollisionGeometry<double>* a, const ::fcl::Transform3<double>& ta,
                  const ::fcl::CollisionGeometry<double>* b, const ::fcl::Transform3<double>& tb,
                  const gq::fcl::Options& options) {
  ::fcl::DistanceResult<double> result;
  return gq::fcl::distance(a, ta, b, tb, ::fcl::DistanceRequest<double>(), result, options);
}

TEST_F(MeshFittingTest, FitIsFitShapesFitOfTheModelsTriangles) {
  fitting.tolerance = 1.0;  // the torus's box and hull are 0.74 off (the hole), its capsule 1.35
  fitting.allowed = gq::fitBit(gq::FitRepresentation::Capsule) | gq::fitBit(gq::FitRepresentation::Box) |
                    gq::fitBit(gq::FitRepresentation::ConvexHull);
  const gq::fcl::MeshFit<double>& fit = gq::fcl::meshFit<double>(model.get(), fitting);
  ASSERT_EQ(fit.status.code, gq::StatusCode::Ok) << fit.status.message();

  gq::MeshData<double> mesh;
  std::vector<::fcl::Triangle> t;
  std::vector<::fcl::Vector3<double>> v;
  torus(v, t);
  mesh.vertices.assign(v.begin(), v.end());
  for (const ::fcl::Triangle& tri : t)
    mesh.triangles.push_back({std::uint32_t(tri[0]), std::uint32_t(tri[1]), std::uint32_t(tri[2])});
  gq::FitOptions<double> options;
  options.tolerance = fitting.tolerance;
  options.allowed = fitting.allowed;
  options.contain = true;
  options.measureCost = false;
  gq::FitResult<double> direct;
  ASSERT_TRUE(gq::fitShape(mesh, options, direct).ok());
  EXPECT_EQ(fit.representation, direct.representation);
  EXPECT_EQ(fit.errorBound, direct.errorBound);
  EXPECT_EQ(fit.parts.size(), direct.parts.size());
  EXPECT_EQ(fit.representation, gq::FitRepresentation::Box);
  EXPECT_EQ(&fit, &gq::fcl::meshFit<double>(model.get(), fitting));  // cooked once
}

TEST_F(MeshFittingTest, WithFittingOnAnswersAreThoseOfTheFitsParts) {
  const gq::fcl::MeshFit<double>& fit = gq::fcl::meshFit<double>(model.get(), fitting);
  ASSERT_EQ(fit.status.code, gq::StatusCode::Ok);
  std::mt19937 rng(47);
  int hits = 0;
  for (int k = 0; k < 200; ++k) {
    const ::fcl::Transform3<double> pose = seededPose(rng);
    bool anyPart = false;
    double nearest = std::numeric_limits<double>::max();
    for (const gq::fcl::FittedPart<double>& p : fit.parts) {
      anyPart = anyPart || collides(p.geometry.get(), modelPose * p.pose, ball.get(), pose, gq::fcl::Options());
      nearest = std::min(nearest, distanceOf(p.geometry.get(), modelPose * p.pose, ball.get(), pose, gq::fcl::Options()));
    }
    hits += anyPart;
    EXPECT_EQ(collides(model.get(), modelPose, ball.get(), pose, on), anyPart) << k;
    EXPECT_EQ(collides(ball.get(), pose, model.get(), modelPose, on), anyPart) << k;
    if (!anyPart) EXPECT_EQ(distanceOf(model.get(), modelPose, ball.get(), pose, on), nearest) << k;
  }
  EXPECT_GT(hits, 10);
  EXPECT_LT(hits, 190);
}

TEST_F(MeshFittingTest, ContactsNameTheModelWithNoTriangle) {
  ::fcl::CollisionRequest<double> request(4, true);
  ::fcl::CollisionResult<double> result;
  // The ball in the torus's hole: clear of the triangles, inside their convex hull.
  const ::fcl::Transform3<double> centre = ::fcl::Transform3<double>::Identity();
  EXPECT_FALSE(collides(model.get(), centre, ball.get(), centre, gq::fcl::Options()));
  ASSERT_GT(gq::fcl::collide(model.get(), centre, ball.get(), centre, request, result, on), 0u);
  EXPECT_EQ(result.getContact(0).o1, model.get());
  EXPECT_EQ(result.getContact(0).b1, +::fcl::Contact<double>::NONE);
}

TEST_F(MeshFittingTest, WithFittingOffAnswersAreTheTriangles) {
  std::mt19937 rng(48);
  for (int k = 0; k < 100; ++k) {
    const ::fcl::Transform3<double> pose = seededPose(rng);
    ::fcl::CollisionResult<double> plain;
    const bool mesh = gq::fcl::collide(model.get(), modelPose, ball.get(), pose, ::fcl::CollisionRequest<double>(),
                                       plain) > 0;
    EXPECT_EQ(collides(model.get(), modelPose, ball.get(), pose, gq::fcl::Options()), mesh) << k;
    ::fcl::DistanceResult<double> d;
    const double meshDistance =
        gq::fcl::distance(model.get(), modelPose, ball.get(), pose, ::fcl::DistanceRequest<double>(), d);
    EXPECT_EQ(distanceOf(model.get(), modelPose, ball.get(), pose, gq::fcl::Options()), meshDistance) << k;
  }
}

TEST_F(MeshFittingTest, RejectedSettingsLeaveTheTrianglesAnswering) {
  fitting.tolerance = -1.0;
  EXPECT_EQ(gq::fcl::meshFit<double>(model.get(), fitting).status.code, gq::StatusCode::InvalidArgument);
  EXPECT_EQ(gq::fcl::meshFit<double>(ball.get(), fitting).status.code, gq::StatusCode::InvalidArgument);
  const ::fcl::Transform3<double> centre = ::fcl::Transform3<double>::Identity();
  EXPECT_FALSE(collides(model.get(), centre, ball.get(), centre, on));  // the hole, as the triangles answer
  EXPECT_NEAR(distanceOf(model.get(), centre, ball.get(), centre, on), 0.7 - 0.2, 0.02);
}

}  // namespace
