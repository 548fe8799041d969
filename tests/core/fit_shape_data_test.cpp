// fitShape on the shared meshes and robot links: for every representation the certified bound is never below the
// two-sided Hausdorff distance sampled with 20k points each way, and contained fits contain every vertex.
#include <gtest/gtest.h>

#include <string>

#include "fit_test_support.h"
#include "gq/io.h"
#include "shared_data.h"

namespace gq {
namespace {

class FitShapeData : public ::testing::TestWithParam<std::string> {};

double sizeOf(const MeshData<double>& m) {
  Bounds3<double> b;
  for (const auto& v : m.vertices) b.include(v);
  return (b.max - b.min).norm();
}

TEST_P(FitShapeData, BoundNeverBelowDenseSampling) {
  const std::string path = gqtest::sharedPath(GetParam());
  GQ_REQUIRE_SHARED_FILE(path);
  MeshData<double> mesh;
  ASSERT_TRUE(loadMeshFile(path, mesh).ok());
  const double size = sizeOf(mesh);
  for (FitRepresentation r : fittest::kSolidRepresentations) {
    FitOptions<double> o;
    o.tolerance = 0.01 * size;
    o.allowed = fitBit(r);
    o.contain = r != FitRepresentation::SimplifiedHull;  // the simplified hull is tried close, the rest containing
    o.measureCost = false;
    o.maxParts = 8;
    o.maxBoundPatches = 200000;
    FitResult<double> fit;
    const Status s = fitShape(mesh, o, fit);
    if (r == FitRepresentation::SimplifiedHull && fit.parts.empty()) continue;  // the hull itself is too far
    ASSERT_TRUE(s.ok()) << toString(r) << ": " << s.toString();
    ASSERT_EQ(fit.representation, r);
    const double sampled = fittest::sampledHausdorff(mesh, fit.parts, 20000);
    EXPECT_GE(double(fit.errorBound), sampled) << toString(r);
    if (o.contain) {
      EXPECT_TRUE(fittest::containsVertices(mesh, fit.parts, 1e-9 * size)) << toString(r);
    }
  }
}

// The bunny (69k triangles) split into up to 16 parts at 1 % of its size: the decomposition finishes within the
// bound's patch budget, its certified bound still holds against dense sampling, and it is well below the single
// hull's (0.042).
TEST(FitShapeDecompositionData, BunnySixteenPartsBelowItsHullAndNeverBelowDenseSampling) {
  const std::string path = gqtest::sharedPath("meshes/stanford-bunny.obj");
  GQ_REQUIRE_SHARED_FILE(path);
  MeshData<double> mesh;
  ASSERT_TRUE(loadMeshFile(path, mesh).ok());
  const double size = sizeOf(mesh);
  FitOptions<double> o;
  o.tolerance = 0.01 * size;
  o.allowed = fitBit(FitRepresentation::ConvexDecomposition);
  o.contain = true;
  o.measureCost = false;
  o.maxParts = 16;
  FitResult<double> fit;
  const Status s = fitShape(mesh, o, fit);
  ASSERT_TRUE(s.ok() || s.code == StatusCode::Warning) << s.toString();
  ASSERT_EQ(fit.representation, FitRepresentation::ConvexDecomposition);
  EXPECT_GT(fit.parts.size(), 1u);
  EXPECT_LE(fit.parts.size(), 16u);
  EXPECT_GE(double(fit.errorBound), fittest::sampledHausdorff(mesh, fit.parts, 20000));
  EXPECT_TRUE(fittest::containsVertices(mesh, fit.parts, 1e-9 * size));
  o.allowed = fitBit(FitRepresentation::ConvexHull);
  FitResult<double> hull;
  ASSERT_EQ(fitShape(mesh, o, hull).code, StatusCode::Warning);
  EXPECT_LT(fit.errorBound, 0.7 * hull.errorBound);
}

INSTANTIATE_TEST_SUITE_P(
    Meshes, FitShapeData,
    ::testing::Values("meshes/stanford-bunny.obj", "meshes/spot.obj", "meshes/teapot.obj", "meshes/fandisk.obj",
                      "robots/example-robot-data/robots/panda_description/meshes/collision/link0.stl",
                      "robots/example-robot-data/robots/panda_description/meshes/collision/link4.stl",
                      "robots/example-robot-data/robots/ur_description/meshes/ur5/collision/forearm.stl",
                      "robots/example-robot-data/robots/ur_description/meshes/ur5/collision/shoulder.stl"),
    [](const ::testing::TestParamInfo<std::string>& info) {
      std::string name = info.param.substr(info.param.find_last_of('/') + 1);
      if (info.param.find("panda") != std::string::npos) name = "panda_" + name;
      if (info.param.find("ur5") != std::string::npos) name = "ur5_" + name;
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

}  // namespace
}  // namespace gq
