// Per-link representations fitted by gq::fitShape: closed-form fits of a known box mesh, certified error bounds
// against closed-form distances, the fit:<tolerance> mode (a primitive, several parts of a decomposition on one
// link, or the mesh itself), enclosure of every mesh vertex, and parsing the modes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "gq/query.h"
#include "robot_paths.h"
#include "scratch_dir.h"

namespace gq::urdf::test {
namespace {

template <class T> class Approximation : public ::testing::Test {};
TYPED_TEST_SUITE(Approximation, Scalars);

std::string writeObj(const std::string& name, const std::vector<Vec3<double>>& vertices,
                     const std::vector<std::array<int, 3>>& faces) {
  const auto path = gqtest::processScratchDir() / name;
  std::ofstream obj(path);
  obj.precision(17);
  for (const auto& v : vertices) obj << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const auto& f : faces) obj << "f " << f[0] + 1 << " " << f[1] + 1 << " " << f[2] + 1 << "\n";
  return path.string();
}

std::string oneMeshLinkUrdf(const std::string& objPath) {
  return "<robot name=\"b\"><link name=\"a\"><collision><geometry><mesh filename=\"file://" + objPath +
         "\"/></geometry></collision></link></robot>";
}

// A 0.4 x 0.2 x 0.1 box mesh centred at (1, 2, 3).
std::vector<Vec3<double>> boxVertices() {
  std::vector<Vec3<double>> v;
  for (int i = 0; i < 8; ++i)
    v.emplace_back(1 + ((i & 1) ? 0.2 : -0.2), 2 + ((i & 2) ? 0.1 : -0.1), 3 + ((i & 4) ? 0.05 : -0.05));
  return v;
}
std::string boxObj() {
  return writeObj("box.obj", boxVertices(),
                  {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                   {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}});
}

// An L-shaped prism, not convex: the L (0,0) (0.2,0) (0.2,0.05) (0.05,0.05) (0.05,0.15) (0,0.15), extruded over
// z in [-0.025, 0.025]; the union of two boxes, [0,0.2]x[0,0.05] and [0,0.05]x[0.05,0.15].
std::vector<Vec3<double>> lShapeVertices() {
  const double xy[7][2] = {{0, 0}, {0.2, 0}, {0.2, 0.05}, {0.05, 0.05}, {0.05, 0.15}, {0, 0.15}, {0, 0.05}};
  std::vector<Vec3<double>> v;
  for (double z : {-0.025, 0.025})
    for (const auto& p : xy) v.emplace_back(p[0], p[1], z);
  return v;
}
std::string lShapeObj() {
  std::vector<std::array<int, 3>> f;
  const int cap[5][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 6}, {6, 3, 4}, {6, 4, 5}};
  for (const auto& t : cap) {
    f.push_back({t[0] + 7, t[1] + 7, t[2] + 7});
    f.push_back({t[0], t[2], t[1]});
  }
  for (int i = 0; i < 7; ++i) {
    const int a = i, b = (i + 1) % 7;
    f.push_back({a, b, b + 7});
    f.push_back({a, b + 7, a + 7});
  }
  return writeObj("l_shape.obj", lShapeVertices(), f);
}

template <class T> RobotModel<T> load(const std::string& objPath, const LoadOptions& options) {
  RobotModel<T> m;
  const Status s = loadRobotFromStrings(oneMeshLinkUrdf(objPath), "", "/", options, m);
  EXPECT_TRUE(s.ok()) << s.toString();
  return m;
}

template <class T> RobotModel<T> load(const std::string& objPath, Representation rep) {
  LoadOptions o = testOptions(rep);
  o.errorBoundTarget = LoadOptions().errorBoundTarget;
  return load<T>(objPath, o);
}

template <class T> RobotModel<T> loadFit(const std::string& objPath, double tolerance) {
  LoadOptions o = testOptions(Representation::Fit);
  o.fitTolerance = tolerance;
  return load<T>(objPath, o);
}

// Every vertex lies in some shape of the model (distance 0 to the solid, within rounding of T).
template <class T> void expectEnclosed(const RobotModel<T>& m, const std::vector<Vec3<double>>& vertices) {
  const T slack = T(64) * std::numeric_limits<T>::epsilon();
  for (const auto& v : vertices) {
    T nearest = std::numeric_limits<T>::infinity();
    for (const auto& s : m.shapes) {
      PointDistanceResult<T> r;
      ASSERT_TRUE(pointDistance(Vec3<T>(v.cast<T>()), s.geometry, s.origin, r).ok());
      nearest = std::min(nearest, r.distance);
    }
    EXPECT_LE(nearest, slack) << v.transpose();
  }
}

TYPED_TEST(Approximation, BoxFitOfABoxMeshIsTheBoxItselfWithABoundNearZero) {
  using T = TypeParam;
  for (Representation rep : {Representation::Box, Representation::BoxAabb}) {
    const RobotModel<T> m = load<T>(boxObj(), rep);
    ASSERT_EQ(m.shapes.size(), 1u);
    const Shape<T>& s = m.shapes[0];
    const auto* box = s.geometry.template getIf<BoxGeometry<T>>();
    ASSERT_NE(box, nullptr) << toString(rep);
    Vec3<T> he = box->halfExtents;
    std::sort(he.data(), he.data() + 3);
    EXPECT_NEAR(he.x(), T(0.05), T(1e-5));
    EXPECT_NEAR(he.y(), T(0.1), T(1e-5));
    EXPECT_NEAR(he.z(), T(0.2), T(1e-5));
    EXPECT_LT((s.origin.p - Vec3<T>(1, 2, 3)).norm(), T(1e-5));
    EXPECT_EQ(s.fitted, FitRepresentation::Box);
    EXPECT_GE(s.errorBound, T(0));
    EXPECT_LT(s.errorBound, T(1e-5)) << toString(rep);
  }
}

TYPED_TEST(Approximation, SphereAndCapsuleFitsOfABoxMeshHaveClosedFormSizesAndCertifiedBounds) {
  using T = TypeParam;
  const RobotModel<T> sm = load<T>(boxObj(), Representation::Sphere);
  ASSERT_EQ(sm.shapes.size(), 1u);
  const Shape<T>& sphere = sm.shapes[0];
  const auto* sg = sphere.geometry.template getIf<SphereGeometry<T>>();
  ASSERT_NE(sg, nullptr);
  const double radius = std::sqrt(0.2 * 0.2 + 0.1 * 0.1 + 0.05 * 0.05);  // half diagonal
  EXPECT_NEAR(double(sg->radius), radius, 1e-5);
  // The sphere's farthest surface point from the box is along the shortest axis: radius - 0.05. The bound is at
  // least that, and refined to within 2 % of it (LoadOptions::errorBoundTarget is smaller).
  const double farthest = radius - 0.05;
  EXPECT_GE(double(sphere.errorBound), farthest - 1e-5);
  EXPECT_LE(double(sphere.errorBound), 1.03 * farthest);

  const RobotModel<T> cm = load<T>(boxObj(), Representation::Capsule);
  ASSERT_EQ(cm.shapes.size(), 1u);
  const auto* cg = cm.shapes[0].geometry.template getIf<CapsuleGeometry<T>>();
  ASSERT_NE(cg, nullptr);
  const double r = std::hypot(0.1, 0.05);  // cross-section half diagonal
  EXPECT_NEAR(double(cg->radius), r, 1e-5);
  // Corner (0.2, 0.1, 0.05) is radial distance r from the axis: the segment reaches exactly x = 0.2.
  EXPECT_NEAR(double(cg->halfHeight), 0.2, 1e-5);
  // The capsule's cap tip is r beyond the box's end face (x = 0.2 + r against x = 0.2).
  EXPECT_GE(double(cm.shapes[0].errorBound), r - 1e-5);
}

TYPED_TEST(Approximation, BestPrimitiveHasTheSmallestBoundOfThePrimitiveModes) {
  using T = TypeParam;
  const T best = load<T>(lShapeObj(), Representation::BestPrimitive).shapes.at(0).errorBound;
  for (Representation rep : {Representation::Sphere, Representation::Capsule, Representation::Box}) {
    const T bound = load<T>(lShapeObj(), rep).shapes.at(0).errorBound;
    EXPECT_LE(best, bound) << toString(rep);
  }
}

TYPED_TEST(Approximation, EveryFittedModeEnclosesEveryMeshVertex) {
  using T = TypeParam;
  for (Representation rep : {Representation::Hull, Representation::Box, Representation::BoxAabb,
                             Representation::Capsule, Representation::Sphere, Representation::BestPrimitive}) {
    SCOPED_TRACE(toString(rep));
    expectEnclosed(load<T>(lShapeObj(), rep), lShapeVertices());
  }
  for (double tolerance : {0.05, 0.01, 0.003}) {
    SCOPED_TRACE(tolerance);
    expectEnclosed(loadFit<T>(lShapeObj(), tolerance), lShapeVertices());
  }
}

TYPED_TEST(Approximation, FitModeTakesACheapPrimitiveWhenItIsWithinTheTolerance) {
  using T = TypeParam;
  const RobotModel<T> m = loadFit<T>(boxObj(), 0.001);
  ASSERT_EQ(m.shapes.size(), 1u);
  EXPECT_EQ(m.shapes[0].representation, Representation::Fit);
  EXPECT_EQ(m.shapes[0].fitted, FitRepresentation::Box);  // the sphere and the capsule are farther than 1 mm
  EXPECT_LE(double(m.shapes[0].errorBound), 0.001);
}

TYPED_TEST(Approximation, FitModeSplitsANonConvexMeshIntoSeveralShapesOfOneLinkWithinTheTolerance) {
  using T = TypeParam;
  // The hull covers the notch of the L: its slanted face is centimetres from the mesh, so 1 mm needs a
  // decomposition, and the L's two boxes are one.
  const double tolerance = 0.001;
  const RobotModel<T> m = loadFit<T>(lShapeObj(), tolerance);
  ASSERT_EQ(m.shapes.size(), 2u);
  ASSERT_EQ(m.links.size(), 1u);
  EXPECT_EQ(m.links[0].shapes.size(), m.shapes.size());
  for (const auto& s : m.shapes) {
    EXPECT_EQ(s.link, 0u);
    EXPECT_EQ(s.fitted, FitRepresentation::ConvexDecomposition);
    EXPECT_EQ(s.fitParts, std::uint32_t(m.shapes.size()));
    EXPECT_NE(s.geometry.template getIf<ConvexMeshGeometry<T>>(), nullptr);
    EXPECT_LE(double(s.errorBound), tolerance);
    EXPECT_EQ(s.errorBound, m.shapes[0].errorBound);  // the union's bound
  }
}

TYPED_TEST(Approximation, FitModeKeepsTheMeshWhenNoFitIsProvenWithinTheTolerance) {
  using T = TypeParam;
  const RobotModel<T> m = loadFit<T>(lShapeObj(), 1e-9);
  ASSERT_EQ(m.shapes.size(), 1u);
  EXPECT_EQ(m.shapes[0].fitted, FitRepresentation::Mesh);
  EXPECT_NE(m.shapes[0].geometry.template getIf<TriangleMeshGeometry<T>>(), nullptr);
  EXPECT_TRUE(m.shapes[0].boundingHull);
  EXPECT_EQ(m.shapes[0].errorBound, T(0));
}

TYPED_TEST(Approximation, AFlatMeshHasNoEnclosingSolidFitButFitModeKeepsTheMesh) {
  using T = TypeParam;
  const std::string square = writeObj("square.obj", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
  RobotModel<T> m;
  const Status s = loadRobotFromStrings(oneMeshLinkUrdf(square), "", "/", testOptions(Representation::Hull), m);
  EXPECT_EQ(s.code, StatusCode::DegenerateMesh) << s.toString();
  EXPECT_NE(s.detailedMessage().find("square.obj"), std::string::npos) << s.toString();
  const RobotModel<T> fit = loadFit<T>(square, 0.01);
  ASSERT_EQ(fit.shapes.size(), 1u);
  EXPECT_EQ(fit.shapes[0].fitted, FitRepresentation::Mesh);
}

TEST(ParseMode, FitTakesAToleranceInMetres) {
  LoadOptions o;
  ASSERT_TRUE(parseMode("fit:0.002", o).ok());
  EXPECT_EQ(o.representation, Representation::Fit);
  EXPECT_EQ(o.fitTolerance, 0.002);
  ASSERT_TRUE(parseMode("best-primitive", o).ok());
  EXPECT_EQ(o.representation, Representation::BestPrimitive);
  EXPECT_EQ(o.fitTolerance, 0.002);
}

TEST(ParseMode, BadModesAreInvalidArgumentsAndChangeNothing) {
  for (const char* bad : {"fit", "fit:", "fit:0", "fit:-0.1", "fit:abc", "fit:0.1x", "fit:nan", "fit:inf", "hul"}) {
    LoadOptions o;
    o.representation = Representation::Capsule;
    o.fitTolerance = 0.5;
    const Status s = parseMode(bad, o);
    EXPECT_EQ(s.code, StatusCode::InvalidArgument) << bad;
    EXPECT_EQ(o.representation, Representation::Capsule) << bad;
    EXPECT_EQ(o.fitTolerance, 0.5) << bad;
  }
}

// On the real robots of the shared data folder (skipped when it does not hold them).
template <class T> class ApproximationData : public RobotDataTest {};
TYPED_TEST_SUITE(ApproximationData, Scalars);

TYPED_TEST(ApproximationData, EveryMeshShapeOfTheRealRobotsHasAFiniteCertifiedBound) {
  using T = TypeParam;
  for (Representation rep : {Representation::Hull, Representation::Box, Representation::BoxAabb,
                             Representation::Capsule, Representation::Sphere, Representation::BestPrimitive}) {
    const auto m = loadCached<T>(kUr5, rep);
    ASSERT_TRUE(m);
    for (const auto& s : m->shapes) {
      if (s.source != ShapeSource::Mesh) continue;
      EXPECT_TRUE(std::isfinite(double(s.errorBound))) << toString(rep) << " " << s.file;
      EXPECT_GT(s.errorBound, T(0)) << toString(rep) << " " << s.file;
    }
  }
}

TYPED_TEST(ApproximationData, HullIsTighterThanEveryPrimitive) {
  using T = TypeParam;
  const auto hull = loadCached<T>(kPanda, Representation::Hull);
  ASSERT_TRUE(hull);
  const auto best = loadCached<T>(kPanda, Representation::BestPrimitive);
  ASSERT_TRUE(best);
  ASSERT_EQ(hull->shapes.size(), best->shapes.size());
  for (std::size_t i = 0; i < hull->shapes.size(); ++i) {
    if (hull->shapes[i].source != ShapeSource::Mesh) continue;
    EXPECT_LT(hull->shapes[i].errorBound, best->shapes[i].errorBound) << hull->shapes[i].file;
  }
}

TYPED_TEST(ApproximationData, FitModeKeepsEveryPandaLinkWithinTheTolerance) {
  using T = TypeParam;
  const double tolerance = 0.002;
  LoadOptions o = testOptions(Representation::Fit);
  o.fitTolerance = tolerance;
  RobotModel<T> m;
  const Status s = loadRobot(robotFile(kPanda.urdf), robotFile(kPanda.srdf), o, m);
  ASSERT_TRUE(s.ok()) << s.toString();
  std::size_t fitted = 0;
  for (const auto& shape : m.shapes) {
    if (shape.source != ShapeSource::Mesh) continue;
    EXPECT_LE(double(shape.errorBound), tolerance) << shape.file;
    fitted += shape.fitted != FitRepresentation::Mesh;
  }
  EXPECT_GT(fitted, 0u);
}

}  // namespace
}  // namespace gq::urdf::test
