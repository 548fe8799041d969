// On 1000 seeded random scenes (two shapes each: spheres, boxes, capsules, cylinders), the gq detector's collide
// booleans against DART's fcl and bullet detectors and an exact answer. Pairs with a sphere have an exact answer here
// (the closed-form distance from the sphere's centre to the other shape); other pairs take gq's signed distance,
// and gq's collide must agree with its own distance. Every disagreement of fcl or bullet is printed with the exact
// value; gq must agree with the exact answer on every scene farther than 1e-9 from touching, and its distances
// with the exact ones to 1e-9.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include <dart/collision/DistanceResult.hpp>
#include <dart/dynamics/CylinderShape.hpp>

#include "dart_scene.h"

namespace {

using namespace gqtest;

enum Kind { Sphere, Box, Capsule, Cylinder, KindCount };
const char* kKindNames[] = {"sphere", "box", "capsule", "cylinder"};

struct Solid {
  Kind kind;
  Eigen::Vector3d size;  // sphere: radius; box: full sizes; capsule, cylinder: radius, height
  Eigen::Isometry3d pose;
  dd::ShapePtr shape() const {
    switch (kind) {
      case Sphere: return std::make_shared<dd::SphereShape>(size.x());
      case Box: return std::make_shared<dd::BoxShape>(size);
      case Capsule: return std::make_shared<dd::CapsuleShape>(size.x(), size.y());
      default: return std::make_shared<dd::CylinderShape>(size.x(), size.y());
    }
  }
  double boundingRadius() const {
    switch (kind) {
      case Sphere: return size.x();
      case Box: return 0.5 * size.norm();
      case Capsule: return size.x() + 0.5 * size.y();
      default: return std::hypot(size.x(), 0.5 * size.y());
    }
  }
};

// Distance from a point to the solid (0 inside).
double pointDistance(const Solid& s, const Eigen::Vector3d& world) {
  const Eigen::Vector3d p = s.pose.inverse() * world;
  switch (s.kind) {
    case Sphere: return std::max(0.0, p.norm() - s.size.x());
    case Box: {
      const Eigen::Vector3d h = 0.5 * s.size;
      return (p.cwiseAbs() - h).cwiseMax(0.0).norm();
    }
    case Capsule: {
      const double z = std::clamp(p.z(), -0.5 * s.size.y(), 0.5 * s.size.y());
      return std::max(0.0, (p - Eigen::Vector3d(0, 0, z)).norm() - s.size.x());
    }
    default: {
      const double dr = std::max(0.0, std::hypot(p.x(), p.y()) - s.size.x());
      const double dz = std::max(0.0, std::abs(p.z()) - 0.5 * s.size.y());
      return std::hypot(dr, dz);
    }
  }
}

Solid randomSolid(std::mt19937& rng, Kind kind) {
  std::uniform_real_distribution<double> size(0.1, 0.6);
  Solid s;
  s.kind = kind;
  if (kind == Sphere) {
    s.size = Eigen::Vector3d(size(rng), 0, 0);
  } else if (kind == Box) {
    s.size = Eigen::Vector3d(2 * size(rng), 2 * size(rng), 2 * size(rng));
  } else {
    s.size = Eigen::Vector3d(size(rng), 2 * size(rng), 0);
  }
  std::normal_distribution<double> n(0.0, 1.0);
  const Eigen::Quaterniond q = Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
  s.pose = at(Eigen::Vector3d::Zero(), q);
  return s;
}

struct Scene {
  Solid a, b;
};

std::vector<Scene> scenes(std::size_t count) {
  std::mt19937 rng(20261129u);
  std::uniform_int_distribution<int> kind(0, KindCount - 1);
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> reach(0.3, 1.05);
  std::vector<Scene> out;
  for (std::size_t i = 0; i < count; ++i) {
    Scene s{randomSolid(rng, Kind(kind(rng))), randomSolid(rng, Kind(kind(rng)))};
    const Eigen::Vector3d dir = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
    s.b.pose.translation() = dir * reach(rng) * (s.a.boundingRadius() + s.b.boundingRadius());
    out.push_back(s);
  }
  return out;
}

bool collides(const std::string& name, const Scene& s) {
  auto d = detector(name);
  auto fa = frame(s.a.shape(), s.a.pose, "a");
  auto fb = frame(s.b.shape(), s.b.pose, "b");
  auto group = d->createCollisionGroup(fa.get(), fb.get());
  return d->collide(group.get());
}

double gqDistance(const Scene& s) {
  auto d = detector("gq");
  auto fa = frame(s.a.shape(), s.a.pose, "a");
  auto fb = frame(s.b.shape(), s.b.pose, "b");
  auto group = d->createCollisionGroup(fa.get(), fb.get());
  return d->distance(group.get(), dc::DistanceOption(false, -1e9));
}

TEST(DartAgreement, ThousandRandomScenesAgainstFclBulletAndExact) {
  const std::vector<Scene> all = scenes(1000);
  std::size_t exactScenes = 0, fclWrong = 0, bulletWrong = 0, nearTouching = 0, colliding = 0;
  double maxDistanceError = 0.0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Scene& s = all[i];
    const double gqDist = gqDistance(s);
    double exact = gqDist;
    bool hasExact = false;
    if (s.a.kind == Sphere || s.b.kind == Sphere) {
      const Solid& sphere = s.a.kind == Sphere ? s.a : s.b;
      const Solid& other = s.a.kind == Sphere ? s.b : s.a;
      exact = pointDistance(other, sphere.pose.translation()) - sphere.size.x();
      hasExact = true;
      ++exactScenes;
      if (exact > 0.0) maxDistanceError = std::max(maxDistanceError, std::abs(gqDist - exact));
    }
    if (std::abs(exact) < 1e-9) {
      ++nearTouching;
      continue;
    }
    const bool truth = exact <= 0.0;
    colliding += truth ? 1 : 0;
    const bool gq = collides("gq", s);
    EXPECT_EQ(gq, truth) << "scene " << i << " " << kKindNames[s.a.kind] << "-" << kKindNames[s.b.kind]
                         << (hasExact ? " exact " : " gq distance ") << exact;
    const bool fcl = collides("fcl", s);
    if (fcl != truth) {
      ++fclWrong;
      std::printf("fcl disagrees: scene %zu %s-%s fcl %d, %s distance %.9g\n", i, kKindNames[s.a.kind],
                  kKindNames[s.b.kind], int(fcl), hasExact ? "exact" : "gq", exact);
    }
#ifdef GQ_HAVE_DART_BULLET
    const bool bullet = collides("bullet", s);
    if (bullet != truth) {
      ++bulletWrong;
      std::printf("bullet disagrees: scene %zu %s-%s bullet %d, %s distance %.9g\n", i, kKindNames[s.a.kind],
                  kKindNames[s.b.kind], int(bullet), hasExact ? "exact" : "gq", exact);
    }
#endif
  }
  std::printf("scenes %zu (colliding %zu, within 1e-9 of touching %zu, with a closed-form answer %zu): fcl wrong %zu, "
              "bullet wrong %zu, gq distance max error against the closed form %.3g\n",
              all.size(), colliding, nearTouching, exactScenes, fclWrong, bulletWrong, maxDistanceError);
  EXPECT_LT(maxDistanceError, 1e-9);
  EXPECT_GT(colliding, all.size() / 4);
  EXPECT_LT(colliding, 3 * all.size() / 4);
}

}  // namespace
