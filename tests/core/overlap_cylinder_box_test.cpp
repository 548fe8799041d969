// Cylinder/box overlap certificates (overlap/cylinder_box.cpp) and the cylinder's overlap callback built on them:
// a certificate, when given, is the boolean GJK's answer (touching counts as overlapping), gaps within GJK's
// tolerance are left undecided, and most random poses get one (the point of having them).
#include "gjk_test_shapes.h"

#include "gjk/gjk.h"
#include "gq/custom_shapes.h"
#include "overlap/overlap.h"

namespace {

using namespace gjktest;
using gq::detail::OverlapCertificate;

template <class T> class CylinderBoxOverlap : public ::testing::Test {};
TYPED_TEST_SUITE(CylinderBoxOverlap, Scalars);

template <class T> gq::Geometry<T> cylinder(T radius, T halfHeight) {
  gq::CustomGeometry<T> c;
  EXPECT_TRUE(gq::makeCylinder(radius, halfHeight, c).ok());
  return gq::Geometry<T>(c);
}

TYPED_TEST(CylinderBoxOverlap, CertificateIsGjksAnswerOnRandomPoses) {
  using T = TypeParam;
  Rng rng(1701);
  int apart = 0, overlapping = 0, unknown = 0;
  for (int i = 0; i < 4000; ++i) {
    const T radius = T(rng.uniform(0.1, 1.0));
    const T halfHeight = T(rng.uniform(0.05, 1.5));
    const gq::Vec3<T> h = rng.vec(0.05, 1.0).cast<T>();
    const gq::Transform<T> box = randomPose<T>(rng, 0.8);
    const gq::Transform<T> cyl = randomPose<T>(rng, 0.8);
    const gq::Geometry<T> gc = cylinder(radius, halfHeight), gb{gq::BoxGeometry<T>(h)};
    // The cylinder (axis = local X) in the box's frame.
    const OverlapCertificate got = gq::detail::cylinderBoxCertificate<T>(
        box.transformInv(cyl.p), box.rotateInv(cyl.rotate(gq::Vec3<T>::UnitX())), radius, halfHeight, h);
    const bool gjk = gq::detail::gjkOverlap(gq::detail::makeConvexShape(gc, cyl), gq::detail::makeConvexShape(gb, box));
    bool facade = false;
    ASSERT_TRUE(gq::overlap(gc, cyl, gb, box, facade).ok());
    switch (got) {
      case OverlapCertificate::Apart: ++apart; ASSERT_FALSE(gjk) << "pose " << i; break;
      case OverlapCertificate::Overlapping: ++overlapping; ASSERT_TRUE(gjk) << "pose " << i; break;
      case OverlapCertificate::Unknown: ++unknown; break;
    }
    ASSERT_EQ(facade, gjk) << "pose " << i << ": the callback must answer as GJK";
  }
  EXPECT_GT(apart, 1000);
  EXPECT_GT(overlapping, 1000);
  EXPECT_LT(unknown, 400) << "certificates decide most poses";
}

// Flush contacts (cap on a face, side on a face, side on an edge) at gap 0, inside GJK's tolerance and beyond it.
TYPED_TEST(CylinderBoxOverlap, TouchingIsOverlappingAndOnlyGapsBeyondTheToleranceAreApart) {
  using T = TypeParam;
  const gq::Vec3<T> h(T(1), T(0.75), T(0.5));
  const T radius = T(0.5), halfHeight = T(0.25);
  const T tolerance = gq::detail::gjkRelativeTolerance<T>() * T(4);  // scale: the centres are < 4 apart
  struct Contact {
    gq::Vec3<T> centre, axis;  // at gap 0
    gq::Vec3<T> out;           // unit direction in which a gap opens
    bool axisInSet;            // the separating direction is one the certificate tries
  };
  const T s = T(std::sqrt(0.5));
  const Contact contacts[] = {
      {gq::Vec3<T>(T(1.25), T(0), T(0)), gq::Vec3<T>::UnitX(), gq::Vec3<T>::UnitX(), true},  // cap on the +x face
      {gq::Vec3<T>(T(0), T(1.25), T(0)), gq::Vec3<T>::UnitZ(), gq::Vec3<T>::UnitY(), true},  // side on the +y face
      // Side on the box's z edge: apart along the diagonal, which is no face normal nor a x e_k: GJK's case.
      {gq::Vec3<T>(T(1), T(0.75), T(0)) + gq::Vec3<T>(s, s, T(0)) * radius, gq::Vec3<T>::UnitZ(),
       gq::Vec3<T>(s, s, T(0)), false},
  };
  for (const Contact& c : contacts) {
    const auto at = [&](T gap) {
      return gq::detail::cylinderBoxCertificate<T>(c.centre + gap * c.out, c.axis, radius, halfHeight, h);
    };
    EXPECT_NE(at(T(0)), OverlapCertificate::Apart) << c.centre.transpose();
    EXPECT_NE(at(tolerance / T(4)), OverlapCertificate::Apart) << c.centre.transpose();
    EXPECT_EQ(at(T(1e-3)), c.axisInSet ? OverlapCertificate::Apart : OverlapCertificate::Unknown)
        << c.centre.transpose();
    EXPECT_EQ(at(T(-1e-3)), OverlapCertificate::Overlapping) << c.centre.transpose();
  }
  // Flush on a face, a common point is on the boundary of both: touching is proved, not left to GJK.
  EXPECT_EQ(gq::detail::cylinderBoxCertificate<T>(contacts[0].centre, contacts[0].axis, radius, halfHeight, h),
            OverlapCertificate::Overlapping);
}

}  // namespace
