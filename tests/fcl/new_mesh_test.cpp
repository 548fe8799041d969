// A BVHModel's first queries are answered on FCL's own BV tree (gq::fcl cooks the model only once its queries have
// cost about as much as the cook): the answers must be the cooked mesh's. Two models with the same triangles: one
// new (tree), one cooked at once (a query against a half-space needs the cooked mesh), compared on seeded poses for
// every solid kind, in float and double.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "fcl_scenes.h"
#include "gq/fcl/fcl.h"

namespace {

using gq::fcltest::Kind;

template <class S> using Model = ::fcl::BVHModel<::fcl::OBBRSS<S>>;

// A closed, slightly irregular sphere mesh of 2 * 8 * 12 triangles.
template <class S> std::shared_ptr<Model<S>> bumpySphere() {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.9, 1.1);
  const int rings = 8, segments = 12;
  std::vector<::fcl::Vector3<S>> v;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double th = M_PI * i / rings, ph = 2 * M_PI * j / segments, r = 0.7 * u(rng);
      v.emplace_back(S(r * std::sin(th) * std::cos(ph)), S(r * std::sin(th) * std::sin(ph)), S(r * std::cos(th)));
    }
  std::vector<::fcl::Triangle> t;
  const auto at = [&](int i, int j) { return std::size_t(i * segments + j % segments); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      t.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      t.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  auto m = std::make_shared<Model<S>>();
  m->beginModel();
  m->addSubModel(v, t);
  m->endModel();
  return m;
}

// The model cooked: a collide against a half-space is answered only on the cooked mesh.
template <class S> void cookNow(const Model<S>& m) {
  ::fcl::Halfspace<S> h(::fcl::Vector3<S>::UnitZ(), S(0));
  ::fcl::CollisionRequest<S> request;
  ::fcl::CollisionResult<S> result;
  gq::fcl::collide<S>(&m, ::fcl::Transform3<S>::Identity(), &h, ::fcl::Transform3<S>::Identity(), request, result);
}

template <class S> std::shared_ptr<::fcl::CollisionGeometry<S>> shapeOf(Kind kind, std::mt19937& rng);
template <> std::shared_ptr<::fcl::CollisionGeometry<double>> shapeOf<double>(Kind kind, std::mt19937& rng) {
  return gq::fcltest::makeShape(kind, rng).geometry;
}
template <> std::shared_ptr<::fcl::CollisionGeometry<float>> shapeOf<float>(Kind kind, std::mt19937&) {
  switch (kind) {
    case Kind::Sphere: return std::make_shared<::fcl::Spheref>(0.3f);
    case Kind::Box: return std::make_shared<::fcl::Boxf>(0.5f, 0.3f, 0.4f);
    case Kind::Capsule: return std::make_shared<::fcl::Capsulef>(0.2f, 0.5f);
    case Kind::Cylinder: return std::make_shared<::fcl::Cylinderf>(0.25f, 0.5f);
    case Kind::Cone: return std::make_shared<::fcl::Conef>(0.25f, 0.5f);
    default: return std::make_shared<::fcl::Ellipsoidf>(0.3f, 0.2f, 0.25f);
  }
}

template <class S> ::fcl::Transform3<S> poseNear(std::mt19937& rng) {
  const ::fcl::Transform3d d = gq::fcltest::randomPose(rng, 0.9);
  ::fcl::Transform3<S> tf = ::fcl::Transform3<S>::Identity();
  tf.linear() = d.linear().cast<S>();
  tf.translation() = d.translation().cast<S>();
  return tf;
}

struct Seen {
  std::intptr_t b1;
  double depth;
};

// `tolerance` for depths and distances; `pointTolerance` for nearest points: on curved shapes GJK stops within
// DistanceRequest's default distance_tolerance (1e-6), which leaves the witness points that far apart between two
// runs over differently ordered triangles.
template <class S>
void expectTreeAnswersAreTheCookedOnes(const std::vector<Kind>& kinds, double tolerance, double pointTolerance) {
  std::mt19937 rng(2026);
  auto tree = bumpySphere<S>(), cooked = bumpySphere<S>();
  cookNow<S>(*cooked);
  const ::fcl::Transform3<S> meshPose = poseNear<S>(rng);
  int collisions = 0;
  for (const Kind kind : kinds) {
    const auto shape = shapeOf<S>(kind, rng);
    for (int i = 0; i < 40; ++i) {
      // A new model for each query, so that every query is a first one (never cooked by the earlier ones).
      gq::fcl::forgetGeometry<S>(tree.get());
      const ::fcl::Transform3<S> pose = poseNear<S>(rng);
      ::fcl::CollisionRequest<S> request(100, true);
      ::fcl::CollisionResult<S> onTree, onCooked;
      gq::fcl::collide<S>(tree.get(), meshPose, shape.get(), pose, request, onTree);
      gq::fcl::collide<S>(cooked.get(), meshPose, shape.get(), pose, request, onCooked);
      ASSERT_EQ(onTree.numContacts(), onCooked.numContacts()) << gq::fcltest::name(kind) << " pose " << i;
      collisions += onTree.isCollision();
      std::vector<Seen> a, b;
      for (std::size_t c = 0; c < onTree.numContacts(); ++c) {
        a.push_back({onTree.getContact(c).b1, double(onTree.getContact(c).penetration_depth)});
        b.push_back({onCooked.getContact(c).b1, double(onCooked.getContact(c).penetration_depth)});
      }
      const auto byId = [](const Seen& x, const Seen& y) { return x.b1 < y.b1; };
      std::sort(a.begin(), a.end(), byId), std::sort(b.begin(), b.end(), byId);
      for (std::size_t c = 0; c < a.size(); ++c) {
        EXPECT_EQ(a[c].b1, b[c].b1) << gq::fcltest::name(kind) << " pose " << i;
        EXPECT_NEAR(a[c].depth, b[c].depth, tolerance) << gq::fcltest::name(kind) << " pose " << i;
      }
      gq::fcl::forgetGeometry<S>(tree.get());
      for (const bool signedDistance : {false, true}) {
        ::fcl::DistanceRequest<S> dr(true);
        dr.enable_signed_distance = signedDistance;
        ::fcl::DistanceResult<S> da, db;
        const S x = gq::fcl::distance<S>(tree.get(), meshPose, shape.get(), pose, dr, da);
        const S y = gq::fcl::distance<S>(cooked.get(), meshPose, shape.get(), pose, dr, db);
        EXPECT_NEAR(double(x), double(y), tolerance) << gq::fcltest::name(kind) << " pose " << i;
        if (x > S(0)) {
          EXPECT_NEAR(double((da.nearest_points[0] - db.nearest_points[0]).norm()), 0.0, pointTolerance)
              << gq::fcltest::name(kind) << " pose " << i;
        }
      }
    }
  }
  EXPECT_GT(collisions, 20);  // the poses reach the mesh often enough to compare contacts
}

TEST(FclNewMesh, TreeAnswersAreTheCookedMeshAnswersInDouble) {
  expectTreeAnswersAreTheCookedOnes<double>({Kind::Sphere, Kind::Box, Kind::Capsule, Kind::Cylinder, Kind::Cone,
                                             Kind::Ellipsoid, Kind::Convex, Kind::TriangleP},
                                            1e-9, 1e-5);
}

TEST(FclNewMesh, TreeAnswersAreTheCookedMeshAnswersInFloat) {
  expectTreeAnswersAreTheCookedOnes<float>(
      {Kind::Sphere, Kind::Box, Kind::Capsule, Kind::Cylinder, Kind::Cone, Kind::Ellipsoid}, 1e-4, 1e-3);
}

// A model queried many times is cooked once and answers as before; after forgetGeometry it starts on the tree again.
TEST(FclNewMesh, RepeatedQueriesKeepTheirAnswersAcrossTheCook) {
  auto tree = bumpySphere<double>();
  ::fcl::Sphered sphere(0.3);
  std::mt19937 rng(9);
  std::vector<::fcl::Transform3d> poses;
  for (int i = 0; i < 64; ++i) poses.push_back(gq::fcltest::randomPose(rng, 0.9));
  std::vector<double> first;
  for (int round = 0; round < 40; ++round) {  // far past the cook's estimate for 192 triangles
    for (std::size_t i = 0; i < poses.size(); ++i) {
      ::fcl::DistanceRequestd request(true);
      ::fcl::DistanceResultd result;
      const double d = gq::fcl::distance<double>(tree.get(), ::fcl::Transform3d::Identity(), &sphere, poses[i],
                                                 request, result);
      if (round == 0) first.push_back(d);
      else EXPECT_NEAR(d, first[i], 1e-9) << "round " << round << " pose " << i;
    }
    if (round == 20) gq::fcl::forgetGeometry<double>(tree.get());
  }
}

// A new model with a NaN vertex is bad input whatever path would answer it: nothing written (as a cooked model).
TEST(FclNewMesh, NewModelWithANaNVertexWritesNothing) {
  auto model = std::make_shared<Model<double>>();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  model->beginModel();
  model->addTriangle(::fcl::Vector3d(0, 0, 0), ::fcl::Vector3d(1, 0, 0), ::fcl::Vector3d(0, 1, 0));
  model->addTriangle(::fcl::Vector3d(0, 0, 0), ::fcl::Vector3d(nan, 0, 1), ::fcl::Vector3d(0, 1, 1));
  model->endModel();
  ::fcl::Sphered sphere(0.5);
  const ::fcl::Transform3d identity = ::fcl::Transform3d::Identity();
  ::fcl::CollisionResultd collision;
  EXPECT_EQ(gq::fcl::collide<double>(model.get(), identity, &sphere, identity, ::fcl::CollisionRequestd(), collision),
            0u);
  EXPECT_EQ(collision.numContacts(), 0u);
  ::fcl::DistanceResultd distance;
  EXPECT_EQ(gq::fcl::distance<double>(model.get(), identity, &sphere, identity, ::fcl::DistanceRequestd(true), distance),
            std::numeric_limits<double>::max());
  EXPECT_EQ(distance.min_distance, std::numeric_limits<double>::max());
}

}  // namespace
