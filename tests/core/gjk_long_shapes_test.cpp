// GJK and EPA on support maps far longer than wide (gjk/wide.h): a unit box inside a custom cylinder 1e2 to 1e11
// long and 5.8 wide, and a box crossing a cube hull scaled to a sheet 1.7e12 wide and 1e-61 thick (the two open
// fuzz findings that double-precision simplices could not resolve). References in long double,
// written independently of the kernels:
//  - box inside a long cylinder, far from its caps: the minimum translation is perpendicular to the axis (any axial
//    component adds its half-height times that component to the cylinder's support), so the depth is
//    min over unit u perpendicular to the axis of  R - (c_box - c_cyl).u + sum_i h_i |(R_box^T u)_i|,
//    a one-dimensional minimum over the angle (sampled, then refined by golden section);
//  - box against a scaled cube hull (an oriented box): the separating-axis minimum over the 15 box-box axes.
#include "gjk_test_shapes.h"

#include "gjk/gjk.h"
#include "gq/custom_shapes.h"

namespace {

using namespace gjktest;
using gq::Transform;
using gq::Vec3;
using ML = Eigen::Matrix<L, 3, 3>;

ML rotationL(const Eigen::Quaterniond& q) { return q.normalized().toRotationMatrix().cast<L>(); }

// Depth of a box (centre c, rotation rb, half extents h) inside a cylinder (centre cc, rotation rc, axis = local X,
// radius r), pushed out perpendicular to the axis.
L depthOutOfLongCylinder(const VL& c, const ML& rb, const VL& h, const VL& cc, const ML& rc, L r) {
  const VL e1 = rc.col(1), e2 = rc.col(2), d = c - cc;
  const auto f = [&](L theta) {
    const VL u = std::cos(theta) * e1 + std::sin(theta) * e2;
    return r - d.dot(u) + (rb.transpose() * u).cwiseAbs().dot(h);
  };
  constexpr int kSamples = 1 << 16;
  const L step = 2 * L(M_PI) / kSamples;
  int best = 0;
  for (int k = 1; k < kSamples; ++k)
    if (f(k * step) < f(best * step)) best = k;
  L lo = (best - 1) * step, hi = (best + 1) * step;  // a kink of |.| can sit at the minimum: golden section still works
  for (int it = 0; it < 200; ++it) {
    const L m1 = lo + (hi - lo) * L(0.381966011250105151795), m2 = hi - (hi - lo) * L(0.381966011250105151795);
    (f(m1) <= f(m2) ? hi : lo) = f(m1) <= f(m2) ? m2 : m1;
  }
  return f((lo + hi) / 2);
}

// GJK/EPA's tolerance for a pair of the given size (gq/tolerances.h), twice over, and at least 1e-6.
double sizeBand(double size) { return std::max(1e-6, 2 * gq::tol::Rel<double>::kGjkTolerance * size); }

// The box's centre 3 from the cylinder's axis, halfway along it: inside the cylinder (radius 5.8) by ~1.5.
struct LongCylinderCase {
  Eigen::Quaterniond qc, qb;
  Eigen::Vector3d cc, cb;
};

LongCylinderCase longCylinderCase(Rng& rng) {
  LongCylinderCase k;
  k.qc = rng.rotation();
  k.qb = rng.rotation();
  k.cc = rng.vec(-4, 4);
  const double phi = rng.uniform(0, 2 * M_PI);
  k.cb = k.cc + k.qc * Eigen::Vector3d(0, 3 * std::cos(phi), 3 * std::sin(phi));
  return k;
}

// One case in T: the unit box and a cylinder of radius 5.8 and the given half-height, at the case's poses as stored
// in T, and the exact depth of those poses.
template <class T> struct LongCylinderPair {
  gq::Geometry<T> box, cylinder;
  Transform<T> pb, pc;
  L exact;
};

template <class T> LongCylinderPair<T> longCylinderPair(const LongCylinderCase& k, T halfHeight) {
  const T radius = T(5.8);
  const Vec3<T> half = Vec3<T>::Constant(T(0.5));
  const Transform<T> pb(k.cb.cast<T>(), k.qb.cast<T>()), pc(k.cc.cast<T>(), k.qc.cast<T>());
  const L exact = depthOutOfLongCylinder(toL(pb.p), rotationL(pb.q.template cast<double>()), toL(half), toL(pc.p),
                                         rotationL(pc.q.template cast<double>()), L(radius));
  const auto callbacks = std::make_shared<gq::CylinderCallbacks<T>>(radius, halfHeight);
  return {gq::BoxGeometry<T>(half), gq::CustomGeometry<T>(callbacks), pb, pc, exact};
}

TEST(GjkLongShapes, BoxInsideACylinderUpTo1e11LongHasItsExactDepthInDouble) {
  using T = double;
  Rng rng(20261124);
  for (int trial = 0; trial < 8; ++trial) {
    const LongCylinderCase k = longCylinderCase(rng);
    for (const T halfHeight : {1e2, 1e5, 1e8, 4.2e11}) {
      const auto [box, cylinder, pb, pc, exact] = longCylinderPair(k, halfHeight);
      ASSERT_GT(exact, L(0.5));
      SCOPED_TRACE(testing::Message() << "trial " << trial << " half-height " << halfHeight << " exact "
                                      << double(exact));
      // The boolean GJK alone (the public overlap asks the cylinder's closed-form certificate first).
      EXPECT_TRUE(
          gq::detail::gjkOverlap(gq::detail::makeConvexShape(box, pb), gq::detail::makeConvexShape(cylinder, pc)));
      gq::PenetrationResult<T> pen;
      ASSERT_TRUE(gq::computePenetration(pen, box, pb, cylinder, pc).ok());
      EXPECT_TRUE(pen.penetrating);
      // Within GJK/EPA's tolerance, which scales with the pair's size (1e-12 of it in double), and deeper by at most
      // 5 % more: EPA approaches the cylinder's round side as O(1/N^2) in its vertices and may stop on its
      // curved-shape rule with the best upper bound (measured: exact to 1e-6 at half-height 1e2, up to 2.6 % deep at
      // 1e8). Before this fix: "apart", depths of 1.6e5, distances of -3.8e11.
      const double shallow = sizeBand(halfHeight);
      const double deep = halfHeight <= 1e2 ? 1e-6 : shallow + 0.05 * double(exact);
      const auto expectDepth = [&](double depth) {
        EXPECT_GE(depth, double(exact) - shallow);
        EXPECT_LE(depth, double(exact) + deep);
      };
      expectDepth(double(pen.depth));
      const Vec3<T> axis = pc.q * Vec3<T>::UnitX();
      EXPECT_NEAR(pen.direction.dot(axis), 0.0, 1e-6);
      gq::DistanceResult<T> d;
      ASSERT_TRUE(gq::distance(d, box, pb, cylinder, pc).ok());
      expectDepth(-double(d.distance));
    }
  }
}

// The same in float up to half-height 1e6 (float's wider type is double): within float GJK/EPA's tolerance of the
// pair's size (1e-6 of it), and penetration and distance agree (the float finding answered -994,729 by distance and
// 205 by penetration for an exact 3.4).
TEST(GjkLongShapes, BoxInsideACylinderUpTo1e6LongHasItsDepthInFloat) {
  using T = float;
  Rng rng(20261125);
  for (int trial = 0; trial < 8; ++trial) {
    const LongCylinderCase k = longCylinderCase(rng);
    for (const T halfHeight : {1e2f, 1e4f, 1e6f}) {
      const auto [box, cylinder, pb, pc, exact] = longCylinderPair(k, halfHeight);
      SCOPED_TRACE(testing::Message() << "trial " << trial << " half-height " << halfHeight << " exact "
                                      << double(exact));
      const double tol = std::max(1e-3, 2 * double(gq::tol::Rel<T>::kGjkTolerance) * double(halfHeight));
      gq::PenetrationResult<T> pen;
      ASSERT_TRUE(gq::computePenetration(pen, box, pb, cylinder, pc).ok());
      EXPECT_TRUE(pen.penetrating);
      EXPECT_NEAR(double(pen.depth), double(exact), tol);
      gq::DistanceResult<T> d;
      ASSERT_TRUE(gq::distance(d, box, pb, cylinder, pc).ok());
      EXPECT_NEAR(double(d.distance), -double(exact), tol);
    }
  }
}

// Penetration depth of two overlapping oriented boxes: the minimum over the 15 separating axes (3 + 3 face normals,
// 9 edge cross products) of rA + rB - |n.(cB - cA)| for unit n (the minimum translation of two polytopes lies on one
// of them).
L orientedBoxDepth(const VL& ca, const ML& ra, const VL& ha, const VL& cb, const ML& rb, const VL& hb) {
  std::vector<VL> axes;
  for (int i = 0; i < 3; ++i) {
    axes.push_back(ra.col(i));
    axes.push_back(rb.col(i));
    for (int j = 0; j < 3; ++j) {
      const VL c = ra.col(i).cross(rb.col(j));
      if (c.norm() > L(1e-12)) axes.push_back(c.normalized());
    }
  }
  L best = std::numeric_limits<L>::infinity();
  for (const VL& n : axes) {
    const L overlap = (ra.transpose() * n).cwiseAbs().dot(ha) + (rb.transpose() * n).cwiseAbs().dot(hb) -
                      std::abs(n.dot(cb - ca));
    best = std::min(best, overlap);
  }
  return best;
}

// A box crossing the plane of a cube hull scaled to a sheet 1.7e12 wide and 2e-61 thick (the scale's rotation is the
// identity, so the scaled cube is an oriented box and the exact depth is the separating-axis minimum).
TEST(GjkLongShapes, BoxCrossingAHullScaledToAHugeSheetHasItsExactDepthInDouble) {
  using T = double;
  Rng rng(1124);
  const Vec3<T> half(3.3, 2.3, 5.1), sheet(3.6, 1e-61, 1.7e12);
  const auto cube = makeHull<T>({{-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}, {1, 1, -1},
                                 {-1, -1, 1}, {1, -1, 1}, {-1, 1, 1}, {1, 1, 1}});
  ASSERT_TRUE(cube);
  const gq::Geometry<T> hull = gq::ConvexMeshGeometry<T>(cube, gq::MeshScale<T>(sheet));
  const gq::Geometry<T> box = gq::BoxGeometry<T>(half);
  for (int trial = 0; trial < 8; ++trial) {
    const Transform<T> ps(rng.vec(-4, 4), rng.rotation());
    // The box's centre 1 to 2 from the sheet's plane, within its width: it crosses the sheet.
    const Transform<T> pb(ps.p + ps.q * Vec3<T>(rng.uniform(-3, 3), rng.uniform(1, 2), rng.uniform(-1e3, 1e3)),
                          rng.rotation());
    const L exact = orientedBoxDepth(toL(pb.p), rotationL(pb.q), toL(half), toL(ps.p), rotationL(ps.q), toL(sheet));
    SCOPED_TRACE(testing::Message() << "trial " << trial << " exact " << double(exact));
    ASSERT_GT(exact, L(0));
    // Within GJK/EPA's tolerance for a pair 1.7e12 wide (3.4): it catches the answer this fix mends (GJK called the
    // shapes 5.6e6 apart); the sheet's coordinates alone carry ~4e-4 of rounding.
    const double tol = sizeBand(sheet.z());
    gq::PenetrationResult<T> pen;
    ASSERT_TRUE(gq::computePenetration(pen, box, pb, hull, ps).ok());
    EXPECT_TRUE(pen.penetrating);
    EXPECT_NEAR(double(pen.depth), double(exact), tol);
    gq::DistanceResult<T> d;
    ASSERT_TRUE(gq::distance(d, box, pb, hull, ps).ok());
    EXPECT_NEAR(double(d.distance), -double(exact), tol);
  }
}

}  // namespace
