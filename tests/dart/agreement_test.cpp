// On 1000 seeded random scenes (two shapes each: spheres, boxes, capsules, cylinders), the gq detector's collide
// booleans against DART's fcl and bullet detectors and an exact answer. Pairs with a sphere have a closed form (the
// distance from the sphere's centre to the other shape, signed); the other pairs a brute force in long double: the
// distance is the minimum over the points of one shape of the closed-form distance to the other, a convex function
// minimised by nested golden-section searches, and an overlap counts when it survives eroding the other shape by the
// margin (then no translation shorter than the margin separates them). Every disagreement of fcl or bullet is
// printed with the exact value; gq must agree with the exact answer on every scene farther than 1e-9 from touching,
// and its distances with the exact ones to 1e-9.
#include <gtest/gtest.h>

#include <cmath>
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

using LD = long double;
using Vec3L = Eigen::Matrix<LD, 3, 1>;

// Distance (0 inside) from a world point to the solid, in long double.
LD pointDistanceL(const Solid& s, const Vec3L& world) {
  const Eigen::Matrix<LD, 3, 3> r = s.pose.linear().cast<LD>();
  const Vec3L p = r.transpose() * (world - s.pose.translation().cast<LD>());
  const Vec3L size = s.size.cast<LD>();
  switch (s.kind) {
    case Sphere: return std::max(LD(0), p.norm() - size.x());
    case Box: return (p.cwiseAbs() - LD(0.5) * size).cwiseMax(LD(0)).norm();
    case Capsule: {
      const LD z = std::clamp(p.z(), LD(-0.5) * size.y(), LD(0.5) * size.y());
      return std::max(LD(0), (p - Vec3L(0, 0, z)).norm() - size.x());
    }
    default: {
      const LD dr = std::max(LD(0), std::hypot(p.x(), p.y()) - size.x());
      const LD dz = std::max(LD(0), std::abs(p.z()) - LD(0.5) * size.y());
      return std::hypot(dr, dz);
    }
  }
}

// The minimum of a convex f over [lo, hi] by golden-section search to a bracket of 1e-12; stops at a zero.
template <class F> LD minimizeConvex(LD lo, LD hi, F&& f) {
  const LD g = (std::sqrt(LD(5)) - 1) / 2;
  LD a = lo, b = hi, c = b - g * (b - a), d = a + g * (b - a);
  LD fc = f(c), fd = f(d);
  while (b - a > LD(1e-12) && fc > 0 && fd > 0) {
    if (fc < fd) {
      b = d, d = c, fd = fc, c = b - g * (b - a), fc = f(c);
    } else {
      a = c, c = d, fc = fd, d = a + g * (b - a), fd = f(d);
    }
  }
  return std::min({fc, fd, f(lo), f(hi)});
}

// The same solid eroded by `margin` (every point at least `margin` inside the original).
Solid eroded(const Solid& s, double margin) {
  Solid e = s;
  if (s.kind == Box) e.size -= Eigen::Vector3d::Constant(2 * margin);
  if (s.kind == Capsule) e.size.x() -= margin;
  if (s.kind == Cylinder) e.size -= Eigen::Vector3d(margin, 2 * margin, 0);
  return e;
}

// The exact distance between two solids (0 when they overlap), neither a sphere: the minimum over a's points of the
// distance to b. A capsule is searched along its segment; a box over its volume (x, then y, then z); a cylinder over
// its height, then its disc. Every nested minimum of a convex function over a convex set is convex.
LD bruteForceDistance(const Solid& a, const Solid& b) {
  const Eigen::Matrix<LD, 3, 3> r = a.pose.linear().cast<LD>();
  const Vec3L t = a.pose.translation().cast<LD>();
  const Vec3L size = a.size.cast<LD>();
  auto at = [&](LD x, LD y, LD z) { return pointDistanceL(b, r * Vec3L(x, y, z) + t); };
  if (a.kind == Capsule) {
    const LD h = LD(0.5) * size.y();
    return std::max(LD(0), minimizeConvex(-h, h, [&](LD z) { return at(0, 0, z); }) - size.x());
  }
  if (a.kind == Box) {
    const Vec3L h = LD(0.5) * size;
    return minimizeConvex(-h.x(), h.x(), [&](LD x) {
      return minimizeConvex(-h.y(), h.y(), [&](LD y) {
        return minimizeConvex(-h.z(), h.z(), [&](LD z) { return at(x, y, z); });
      });
    });
  }
  const LD radius = size.x(), h = LD(0.5) * size.y();
  return minimizeConvex(-h, h, [&](LD z) {
    return minimizeConvex(-radius, radius, [&](LD x) {
      const LD w = std::sqrt(std::max(LD(0), radius * radius - x * x));
      return minimizeConvex(-w, w, [&](LD y) { return at(x, y, z); });
    });
  });
}

// The exact answer of a pair without a sphere: the distance when they are apart, 0 when they overlap by at least
// `margin`, NaN in between (within the margin of touching).
double exactWithoutSphere(const Solid& a, const Solid& b, double margin) {
  // Search over the lower-dimensional shape: a capsule's segment before a box's or cylinder's volume.
  const bool aFirst = a.kind == Capsule || b.kind != Capsule;
  const Solid& searched = aFirst ? a : b;
  const Solid& other = aFirst ? b : a;
  const LD d = bruteForceDistance(searched, other);
  if (d > LD(margin)) return double(d);
  if (bruteForceDistance(searched, eroded(other, margin)) <= LD(1e-13)) return 0.0;
  return std::nan("");
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
  std::size_t closedFormScenes = 0, fclWrong = 0, bulletWrong = 0, nearTouching = 0, colliding = 0;
  double maxDistanceError = 0.0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Scene& s = all[i];
    const double gqDist = gqDistance(s);
    double exact = 0.0;
    const bool closedForm = s.a.kind == Sphere || s.b.kind == Sphere;
    if (closedForm) {
      const Solid& sphere = s.a.kind == Sphere ? s.a : s.b;
      const Solid& other = s.a.kind == Sphere ? s.b : s.a;
      exact = pointDistance(other, sphere.pose.translation()) - sphere.size.x();
      ++closedFormScenes;
    } else {
      exact = exactWithoutSphere(s.a, s.b, 1e-9);
    }
    if (std::isnan(exact) || (closedForm && std::abs(exact) < 1e-9)) {
      ++nearTouching;
      continue;
    }
    if (exact > 0.0) maxDistanceError = std::max(maxDistanceError, std::abs(gqDist - exact));
    const bool truth = exact <= 0.0;
    colliding += truth ? 1 : 0;
    const bool gq = collides("gq", s);
    EXPECT_EQ(gq, truth) << "scene " << i << " " << kKindNames[s.a.kind] << "-" << kKindNames[s.b.kind]
                         << " exact distance " << exact << " (gq " << gqDist << ")";
    const bool fcl = collides("fcl", s);
    if (fcl != truth) {
      ++fclWrong;
      std::printf("fcl disagrees: scene %zu %s-%s fcl %d, exact distance %.9g, gq signed distance %.9g\n", i,
                  kKindNames[s.a.kind], kKindNames[s.b.kind], int(fcl), exact, gqDist);
    }
#ifdef GQ_HAVE_DART_BULLET
    const bool bullet = collides("bullet", s);
    if (bullet != truth) {
      ++bulletWrong;
      std::printf("bullet disagrees: scene %zu %s-%s bullet %d, exact distance %.9g, gq signed distance %.9g\n", i,
                  kKindNames[s.a.kind], kKindNames[s.b.kind], int(bullet), exact, gqDist);
    }
#endif
  }
  std::printf("scenes %zu (colliding %zu, within 1e-9 of touching %zu, closed form %zu, brute force %zu): fcl wrong "
              "%zu, bullet wrong %zu, gq distance max error against the exact distance %.3g\n",
              all.size(), colliding, nearTouching, closedFormScenes, all.size() - closedFormScenes, fclWrong,
              bulletWrong, maxDistanceError);
  EXPECT_LT(maxDistanceError, 1e-9);
  EXPECT_GT(colliding, all.size() / 4);
  EXPECT_LT(colliding, 3 * all.size() / 4);
}

}  // namespace
