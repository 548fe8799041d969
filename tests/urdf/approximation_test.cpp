// Per-link representations and their measured errors: every primitive fit encloses the mesh (mesh->approximation
// error 0), closed-form fits of a known box mesh, and the hull being the tightest enclosing representation.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "robot_paths.h"
#include "scratch_dir.h"

namespace gq::urdf::test {
namespace {

template <class T> class Approximation : public ::testing::Test {};
TYPED_TEST_SUITE(Approximation, Scalars);

// A 0.4 x 0.2 x 0.1 box mesh centred at (1, 2, 3), as OBJ.
std::string boxUrdf() {
  const auto& dir = gqtest::processScratchDir();
  std::ofstream obj(dir / "box.obj");
  for (int i = 0; i < 8; ++i)
    obj << "v " << 1 + ((i & 1) ? 0.2 : -0.2) << " " << 2 + ((i & 2) ? 0.1 : -0.1) << " " << 3 + ((i & 4) ? 0.05 : -0.05)
        << "\n";
  obj << "f 1 3 4\nf 1 4 2\nf 5 6 8\nf 5 8 7\nf 1 2 6\nf 1 6 5\nf 3 7 8\nf 3 8 4\nf 1 5 7\nf 1 7 3\nf 2 4 8\nf 2 8 6\n";
  return "<robot name=\"b\"><link name=\"a\"><collision><geometry><mesh filename=\"file://" + (dir / "box.obj").string() +
         "\"/></geometry></collision></link></robot>";
}

template <class T> Shape<T> fitOf(Representation rep) {
  RobotModel<T> m;
  const Status s = loadRobotFromStrings(boxUrdf(), "", "/", testOptions(rep), m);
  EXPECT_TRUE(s.ok()) << s.toString();
  return m.shapes.at(0);
}

TYPED_TEST(Approximation, BoxFitOfABoxMeshIsTheBoxItself) {
  using T = TypeParam;
  for (Representation rep : {Representation::Box, Representation::BoxAabb}) {
    const Shape<T> s = fitOf<T>(rep);
    const auto* box = s.geometry.template getIf<BoxGeometry<T>>();
    ASSERT_NE(box, nullptr);
    Vec3<T> he = box->halfExtents;
    std::sort(he.data(), he.data() + 3);
    EXPECT_NEAR(he.x(), T(0.05), T(1e-5));
    EXPECT_NEAR(he.y(), T(0.1), T(1e-5));
    EXPECT_NEAR(he.z(), T(0.2), T(1e-5));
    EXPECT_LT((s.origin.p - Vec3<T>(1, 2, 3)).norm(), T(1e-5));
    EXPECT_LT(s.error.approximationToMesh, T(1e-5));
    EXPECT_LT(s.error.meshToApproximation, T(1e-5));
  }
}

TYPED_TEST(Approximation, SphereAndCapsuleFitsOfABoxMeshHaveClosedFormSizes) {
  using T = TypeParam;
  const Shape<T> sphere = fitOf<T>(Representation::Sphere);
  const auto* sg = sphere.geometry.template getIf<SphereGeometry<T>>();
  ASSERT_NE(sg, nullptr);
  EXPECT_NEAR(sg->radius, T(std::sqrt(0.2 * 0.2 + 0.1 * 0.1 + 0.05 * 0.05)), T(1e-5));  // half diagonal
  // The sphere's farthest surface point from the box is along the shortest axis: radius - 0.05.
  EXPECT_LE(sphere.error.approximationToMesh, sg->radius - T(0.05) + T(1e-5));
  EXPECT_GT(sphere.error.approximationToMesh, T(0.5) * (sg->radius - T(0.05)));

  const Shape<T> capsule = fitOf<T>(Representation::Capsule);
  const auto* cg = capsule.geometry.template getIf<CapsuleGeometry<T>>();
  ASSERT_NE(cg, nullptr);
  const double r = std::hypot(0.1, 0.05);  // cross-section half diagonal
  EXPECT_NEAR(double(cg->radius), r, 1e-5);
  // Corner (0.2, 0.1, 0.05) is radial distance r from the axis: the segment reaches exactly x = 0.2.
  EXPECT_NEAR(double(cg->halfHeight), 0.2, 1e-5);
}

// On the real robots of the shared data folder (skipped when it does not hold them).
template <class T> class ApproximationData : public RobotDataTest {};
TYPED_TEST_SUITE(ApproximationData, Scalars);

TYPED_TEST(ApproximationData, EveryRepresentationEnclosesTheRealMeshes) {
  using T = TypeParam;
  for (Representation rep : {Representation::Hull, Representation::Box, Representation::BoxAabb,
                             Representation::Capsule, Representation::Sphere, Representation::BestPrimitive}) {
    const auto m = loadCached<T>(kUr5, rep);
    ASSERT_TRUE(m);
    for (const auto& s : m->shapes) {
      if (s.source != ShapeSource::Mesh) continue;
      EXPECT_LT(s.error.meshToApproximation, T(1e-4)) << toString(rep) << " " << s.file;
      EXPECT_GE(s.error.approximationToMesh, T(0));
    }
  }
}

TYPED_TEST(ApproximationData, HullIsTighterThanEveryPrimitive) {
  using T = TypeParam;
  const auto hull = loadCached<T>(kPanda, Representation::Hull);
  ASSERT_TRUE(hull);
  const auto best = loadCached<T>(kPanda, Representation::BestPrimitive);
  ASSERT_TRUE(best);
  for (std::size_t i = 0; i < hull->shapes.size(); ++i) {
    if (hull->shapes[i].source != ShapeSource::Mesh) continue;
    EXPECT_LT(hull->shapes[i].error.approximationToMesh, best->shapes[i].error.approximationToMesh)
        << hull->shapes[i].file;
  }
}

}  // namespace
}  // namespace gq::urdf::test
