// fitShape on generated meshes: the certified bound is never below dense sampling, contained fits contain every
// vertex, the cheapest representation within the tolerance wins, fits are deterministic, bad input gets a status.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>

#include "fit_test_support.h"

namespace gq {
namespace {

using fittest::Vec3d;

FitOptions<double> only(FitRepresentation r, double tolerance, bool contain = false) {
  FitOptions<double> o;
  o.tolerance = tolerance;
  o.allowed = fitBit(r);
  o.contain = contain;
  o.measureCost = false;
  o.maxBoundPatches = 100000;
  return o;
}

MeshData<double> rotatedBox() {
  const Quat<double> q(Eigen::AngleAxisd(0.4, Vec3d(1, 2, 3).normalized()));
  return fittest::boxMesh({0.5, 0.3, 0.2}, Transform<double>(Vec3d(1, -2, 0.5), q));
}

MeshData<double> movedSphere() {
  MeshData<double> m = fittest::sphereMesh(3, 0.7);
  for (auto& v : m.vertices) v += Vec3d(0.3, 0.1, -0.2);
  return m;
}

TEST(FitShapeBound, NeverBelowDenseSamplingOnEveryRepresentation) {
  for (const MeshData<double>& mesh : {rotatedBox(), movedSphere(), fittest::lShapeMesh()}) {
    for (FitRepresentation r : fittest::kSolidRepresentations) {
      for (bool contain : {false, true}) {
        FitResult<double> fit;
        const Status s = fitShape(mesh, only(r, 1e-3, contain), fit);
        ASSERT_TRUE(s.ok()) << toString(r) << ": " << s.toString();
        ASSERT_FALSE(fit.parts.empty());
        ASSERT_EQ(fit.representation, r);
        const double sampled = fittest::sampledHausdorff(mesh, fit.parts, 20000);
        EXPECT_GE(double(fit.errorBound), sampled) << toString(r) << (contain ? " containing" : " close");
        if (contain) {
          EXPECT_TRUE(fittest::containsVertices(mesh, fit.parts, 1e-9)) << toString(r);
        }
      }
    }
  }
}

TEST(FitShapeBound, TightOnExactShapes) {
  // A box mesh is its own box and hull: the bound comes down to the rounding allowance (1e-8 of the mesh size, plus
  // the float parts' rounding), patches straddling a face's diagonal included; a fine sphere mesh is within its chord
  // error of its enclosing sphere.
  FitResult<double> fit;
  ASSERT_TRUE(fitShape(rotatedBox(), only(FitRepresentation::Box, 1e-12), fit).code == StatusCode::Warning);
  EXPECT_LE(fit.errorBound, 1e-7);
  ASSERT_TRUE(fitShape(rotatedBox(), only(FitRepresentation::ConvexHull, 1e-12), fit).code == StatusCode::Warning);
  EXPECT_LE(fit.errorBound, 1e-7);
  ASSERT_TRUE(fitShape(movedSphere(), only(FitRepresentation::Sphere, 0.02), fit).ok());
  EXPECT_LE(fit.errorBound, 0.02);  // level-3 octahedron: sagitta about 0.7 * (1 - cos(pi / 32 * 1.5))
}

// The stated optimality gap: a one-part fit's volume over the mesh hull's. A box mesh's containing box is the box
// itself (ratio 1); its containing sphere is the sphere through its corners (radius the half diagonal).
TEST(FitShapeOptimalityGap, VolumeRatioIsOneForABoxMeshsBoxAndTheCornerSphereOverTheBoxForItsSphere) {
  FitResult<double> fit;
  ASSERT_TRUE(fitShape(rotatedBox(), only(FitRepresentation::Box, 1e-3, true), fit).ok());
  ASSERT_EQ(fit.candidates.size(), 1u);
  EXPECT_NEAR(fit.candidates[0].volumeRatio, 1.0, 1e-9);
  ASSERT_TRUE(fitShape(rotatedBox(), only(FitRepresentation::Sphere, 1.0, true), fit).ok());
  const double r2 = 0.5 * 0.5 + 0.3 * 0.3 + 0.2 * 0.2;
  EXPECT_NEAR(fit.candidates[0].volumeRatio, 4.0 / 3.0 * M_PI * r2 * std::sqrt(r2) / (8 * 0.5 * 0.3 * 0.2), 1e-6);
  ASSERT_TRUE(fitShape(fittest::lShapeMesh(), only(FitRepresentation::ConvexDecomposition, 1e-3, true), fit).ok());
  EXPECT_EQ(fit.candidates.back().volumeRatio, 0.0);  // several parts: no gap stated
}

TEST(FitShapeChoice, CheapestWithinToleranceWins) {
  FitOptions<double> o;
  o.tolerance = 1e-4;
  o.measureCost = false;
  FitResult<double> fit;
  ASSERT_TRUE(fitShape(rotatedBox(), o, fit).ok());
  EXPECT_EQ(fit.representation, FitRepresentation::Box);
  ASSERT_GE(fit.candidates.size(), 3u);
  EXPECT_GT(fit.candidates[0].errorBound, o.tolerance);  // the sphere is too far
  o.tolerance = 0.02;
  ASSERT_TRUE(fitShape(movedSphere(), o, fit).ok());
  EXPECT_EQ(fit.representation, FitRepresentation::Sphere);
  ASSERT_EQ(fit.parts.size(), 1u);
  EXPECT_EQ(fit.parts[0].first.type(), GeometryType::Sphere);
}

TEST(FitShapeChoice, NonConvexMeshNeedsManyPartsOrTheMesh) {
  FitOptions<double> o;
  o.tolerance = 1e-3;
  o.measureCost = false;
  FitResult<double> fit;
  ASSERT_TRUE(fitShape(fittest::lShapeMesh(), o, fit).ok());
  EXPECT_TRUE(fit.representation == FitRepresentation::ConvexDecomposition ||
              fit.representation == FitRepresentation::Mesh);
  EXPECT_LE(fit.errorBound, o.tolerance);
}

TEST(FitShapeChoice, WarnsWhenNothingAllowedIsWithinTolerance) {
  FitResult<double> fit;
  const Status s = fitShape(fittest::lShapeMesh(), only(FitRepresentation::Sphere, 1e-3), fit);
  EXPECT_EQ(s.code, StatusCode::Warning);
  EXPECT_EQ(fit.representation, FitRepresentation::Sphere);
  EXPECT_GT(fit.errorBound, 1e-3);
}

TEST(FitShapeChoice, MeshItselfHasNoError) {
  FitResult<double> fit;
  ASSERT_TRUE(fitShape(fittest::lShapeMesh(), only(FitRepresentation::Mesh, 1e-6), fit).ok());
  EXPECT_EQ(fit.errorBound, 0.0);
  ASSERT_EQ(fit.parts.size(), 1u);
  EXPECT_EQ(fit.parts[0].first.type(), GeometryType::TriangleMesh);
}

TEST(FitShapeSimplifiedHull, FewerVerticesThanTheHullWithinTolerance) {
  const MeshData<double> mesh = fittest::sphereMesh(4);
  FitResult<double> hull, simple;
  ASSERT_TRUE(fitShape(mesh, only(FitRepresentation::ConvexHull, 0.05), hull).ok());
  for (bool contain : {false, true}) {
    ASSERT_TRUE(fitShape(mesh, only(FitRepresentation::SimplifiedHull, 0.05, contain), simple).ok());
    ASSERT_EQ(simple.representation, FitRepresentation::SimplifiedHull);
    EXPECT_LE(simple.errorBound, 0.05);
    ASSERT_EQ(simple.candidates.size(), 1u);
    EXPECT_LT(simple.candidates[0].vertices, hull.candidates[0].vertices);
    if (contain) {
      EXPECT_TRUE(fittest::containsVertices(mesh, simple.parts, 1e-9));
    }
  }
}

TEST(FitShapeDecomposition, PartsWithinMaxPartsContainingAndCertified) {
  FitOptions<double> o = only(FitRepresentation::ConvexDecomposition, 1e-3, true);
  o.maxParts = 4;
  FitResult<double> fit;
  EXPECT_TRUE(fitShape(fittest::lShapeMesh(), o, fit).ok());
  EXPECT_GE(fit.parts.size(), 2u);
  EXPECT_LE(fit.parts.size(), 4u);
  for (const auto& part : fit.parts) EXPECT_EQ(part.first.type(), GeometryType::ConvexMesh);
  EXPECT_TRUE(fittest::containsVertices(fittest::lShapeMesh(), fit.parts, 1e-9));
  EXPECT_GE(double(fit.errorBound), fittest::sampledHausdorff(fittest::lShapeMesh(), fit.parts, 20000));
  // Better than the one hull, which covers the whole notch of the L.
  FitResult<double> hull;
  ASSERT_TRUE(fitShape(fittest::lShapeMesh(), only(FitRepresentation::ConvexHull, 1e-3), hull).code == StatusCode::Warning);
  EXPECT_LT(fit.errorBound, hull.errorBound);
}

TEST(FitShapeDecomposition, AnLOfTwoBoxesSplitsAlongItsConcaveEdgeIntoTheTwoBoxes) {
  FitOptions<double> o = only(FitRepresentation::ConvexDecomposition, 1e-3, true);
  o.maxParts = 4;
  o.maxBoundPatches = FitOptions<double>().maxBoundPatches;  // the bound along the boxes' edges needs the default
  FitResult<double> fit;
  const Status s = fitShape(fittest::lShapeMesh(), o, fit);
  EXPECT_EQ(s.code, StatusCode::Ok) << s.toString();
  ASSERT_EQ(fit.parts.size(), 2u);
  EXPECT_LE(double(fit.errorBound), 1e-3);
  EXPECT_TRUE(fittest::containsVertices(fittest::lShapeMesh(), fit.parts, 1e-9));
  EXPECT_GE(double(fit.errorBound), fittest::sampledHausdorff(fittest::lShapeMesh(), fit.parts, 20000));
  // Each part is one of the boxes [0,2]x[0,0.5] and [0,0.5]x[0,1.5] or [0,0.5]x[0.5,1.5] and [0,2]x[0,0.5] (the
  // cut at x = 0.5 or at y = 0.5), reaching at most the overlap slab across the cut: 8 corners each.
  for (const auto& part : fit.parts) {
    const auto* hull = part.first.getIf<ConvexMeshGeometry<double>>();
    ASSERT_NE(hull, nullptr);
    EXPECT_EQ(hull->mesh->vertices.size(), 8u);
  }
}

// The hull of a torus spans its hole (0.74 from the surface for R = 1, r = 0.3); the splitting measures each
// piece's concavity over the whole of its hull faces, so eight parts already come well below the hull.
TEST(FitShapeDecomposition, TorusAtEightPartsIsWellBelowItsHull) {
  const MeshData<double> torus = fittest::torusMesh(1.0, 0.3, 32, 12);
  FitOptions<double> o = only(FitRepresentation::ConvexDecomposition, 0.01, true);
  o.maxParts = 8;
  FitResult<double> fit, hull;
  EXPECT_EQ(fitShape(torus, o, fit).code, StatusCode::Warning);
  ASSERT_EQ(fit.parts.size(), 8u);
  ASSERT_EQ(fitShape(torus, only(FitRepresentation::ConvexHull, 0.01, true), hull).code, StatusCode::Warning);
  EXPECT_LT(fit.errorBound, 0.4 * hull.errorBound);
  EXPECT_TRUE(fittest::containsVertices(torus, fit.parts, 1e-9));
  EXPECT_GE(double(fit.errorBound), fittest::sampledHausdorff(torus, fit.parts, 20000));
}

// Two closed unit-half-height boxes stacked face to face: their shared wall z = 0 is mesh surface inside the solid,
// 1 from its boundary at the wall's centre, whatever convex parts contain the mesh. The decomposition's certified
// bound is then at least 1 and never above the hull's (the hull stands in for a split that does not pay).
TEST(FitShapeDecomposition, AnInternalWallKeepsItsDepthSoTheDecompositionIsNeverFartherThanTheHull) {
  MeshData<double> mesh = fittest::boxMesh({1, 1, 0.5}, Transform<double>(Vec3d(0, 0, -0.5)));
  const MeshData<double> upper = fittest::boxMesh({1, 1, 0.5}, Transform<double>(Vec3d(0, 0, 0.5)));
  const std::uint32_t base = std::uint32_t(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), upper.vertices.begin(), upper.vertices.end());
  for (const auto& t : upper.triangles) mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  FitResult<double> hull, parts;
  EXPECT_EQ(fitShape(mesh, only(FitRepresentation::ConvexHull, 0.01, true), hull).code, StatusCode::Warning);
  FitOptions<double> o = only(FitRepresentation::ConvexDecomposition, 0.01, true);
  o.maxParts = 8;
  EXPECT_EQ(fitShape(mesh, o, parts).code, StatusCode::Warning);
  ASSERT_EQ(parts.representation, FitRepresentation::ConvexDecomposition);
  EXPECT_GE(hull.errorBound, 1.0);
  EXPECT_GE(parts.errorBound, 1.0);
  EXPECT_LE(parts.errorBound, hull.errorBound);
  EXPECT_TRUE(fittest::containsVertices(mesh, parts.parts, 1e-9));
}

TEST(FitShapeDeterminism, SameInputSameFit) {
  for (FitRepresentation r : fittest::kSolidRepresentations) {
    FitResult<double> a, b;
    ASSERT_TRUE(fitShape(fittest::lShapeMesh(), only(r, 1e-3), a).ok());
    ASSERT_TRUE(fitShape(fittest::lShapeMesh(), only(r, 1e-3), b).ok());
    EXPECT_TRUE(fittest::sameBits(fittest::fingerprint(a), fittest::fingerprint(b))) << toString(r);
  }
}

TEST(FitShapeFloat, BoundAndContainmentHoldInFloat) {
  const MeshData<float> mesh = fittest::castMesh<float>(movedSphere());
  for (FitRepresentation r : {FitRepresentation::Sphere, FitRepresentation::Box, FitRepresentation::ConvexHull}) {
    FitOptions<float> o;
    o.tolerance = 0.5f;
    o.allowed = fitBit(r);
    o.contain = true;
    o.measureCost = false;
    FitResult<float> fit;
    ASSERT_TRUE(fitShape(mesh, o, fit).ok()) << toString(r);
    for (const auto& v : mesh.vertices) {
      PointDistanceResult<float> pd;
      ASSERT_TRUE(pointDistance<float>(v, fit.parts[0].first, fit.parts[0].second, pd).ok());
      EXPECT_LE(pd.distance, 1e-6f) << toString(r);
    }
  }
}

TEST(FitShapeBadInput, ClearStatuses) {
  FitResult<double> fit;
  fit.errorBound = 42;
  const FitOptions<double> ok = only(FitRepresentation::Box, 0.1);
  EXPECT_EQ(fitShape(MeshData<double>(), ok, fit).code, StatusCode::DegenerateMesh);
  MeshData<double> nan = rotatedBox();
  nan.vertices[3].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(fitShape(nan, ok, fit).code, StatusCode::InvalidArgument);
  MeshData<double> range = rotatedBox();
  range.triangles[2][1] = 99;
  EXPECT_EQ(fitShape(range, ok, fit).code, StatusCode::InvalidArgument);
  for (double t : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    FitOptions<double> o = ok;
    o.tolerance = t;
    EXPECT_EQ(fitShape(rotatedBox(), o, fit).code, StatusCode::InvalidArgument) << t;
  }
  FitOptions<double> noParts = ok;
  noParts.maxParts = 0;
  EXPECT_EQ(fitShape(rotatedBox(), noParts, fit).code, StatusCode::InvalidArgument);
  FitOptions<double> none = ok;
  none.allowed = 0;
  EXPECT_EQ(fitShape(rotatedBox(), none, fit).code, StatusCode::InvalidArgument);
  MeshData<double> flat;
  flat.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  flat.triangles = {{0, 1, 2}, {1, 3, 2}};
  EXPECT_EQ(fitShape(flat, ok, fit).code, StatusCode::DegenerateMesh);
  MeshData<double> zeroArea;
  zeroArea.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  zeroArea.triangles = {{0, 1, 2}};
  EXPECT_EQ(fitShape(zeroArea, ok, fit).code, StatusCode::DegenerateMesh);
  EXPECT_EQ(fit.errorBound, 42);  // untouched on failure
}

TEST(FitShapeCertify, BoundOfAGivenFit) {
  const MeshData<double> mesh = movedSphere();
  double bound = 0;
  const std::vector<std::pair<Geometry<double>, Transform<double>>> parts = {
      {SphereGeometry<double>(0.8), Transform<double>(Vec3d(0.3, 0.1, -0.2))}};
  ASSERT_TRUE(certifyFit(mesh, parts, 0.0, 100000, bound).ok());
  EXPECT_GE(bound, 0.1);   // every mesh point is at least 0.1 inside
  EXPECT_LE(bound, 0.13);  // and at most 0.1 plus the chord error
  EXPECT_EQ(certifyFit(mesh, {}, 0.0, 1000, bound).code, StatusCode::InvalidArgument);
  // A target that is not finite or below 0 (0 asks for refinement to the patch budget): a status, the bound untouched.
  bound = 42;
  for (double t : {-1e-3, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    EXPECT_EQ(certifyFit(mesh, parts, t, 1000, bound).code, StatusCode::InvalidArgument) << t;
  EXPECT_EQ(bound, 42);
  EXPECT_EQ(certifyFit(mesh, {{PlaneGeometry<double>(), Transform<double>()}}, 0.0, 1000, bound).code,
            StatusCode::Unsupported);
}

}  // namespace
}  // namespace gq
