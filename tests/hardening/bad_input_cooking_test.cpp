// The bad-input contract of cooking and mesh files (gq/cooking.h): docs/hardening.md, table "cooking and files",
// one test per row. A rejected call leaves `out` as it was.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "gq/io.h"
#include "hardening_fixtures.h"
#include "scratch_dir.h"

namespace gq::hardening {
namespace {

template <class T> class BadInputCooking : public ::testing::Test {};
TYPED_TEST_SUITE(BadInputCooking, Scalars);

// Each test process writes its files into its own scratch folder (scratch_dir.h), removed at exit.
std::filesystem::path scratchFile(const std::string& name, const std::string& bytes) {
  const auto path = gqtest::processScratchDir() / name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// A binary STL header + triangle count, followed by `writtenTriangles` triangles of 50 bytes each.
std::string binaryStl(std::uint32_t declaredTriangles, std::uint32_t writtenTriangles) {
  std::string s(80, ' ');
  s.append(reinterpret_cast<const char*>(&declaredTriangles), 4);
  for (std::uint32_t t = 0; t < writtenTriangles; ++t) {
    const float f[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
    s.append(reinterpret_cast<const char*>(f), sizeof(f));
    s.append(2, '\0');
  }
  return s;
}

template <class T> MeshData<T> sentinelMeshData() {
  MeshData<T> m;
  m.vertices = {sentinelVec<T>()};
  m.triangles = {{9, 9, 9}};
  return m;
}
template <class T> bool isSentinel(const MeshData<T>& m) {
  return m.vertices.size() == 1 && sameBits(m.vertices[0], sentinelVec<T>()) && m.triangles.size() == 1 &&
         m.triangles[0][0] == 9;
}

TYPED_TEST(BadInputCooking, ConvexHullOfFewerThanFourCoplanarOrCoincidentPointsIsDegenerateMesh) {
  using T = TypeParam;
  std::shared_ptr<const ConvexMesh<T>> out;
  const std::vector<std::vector<Vec3<T>>> bad = {
      {},
      {Vec3<T>(T(0), T(0), T(0)), Vec3<T>(T(1), T(0), T(0)), Vec3<T>(T(0), T(1), T(0))},
      {Vec3<T>(T(0), T(0), T(0)), Vec3<T>(T(1), T(0), T(0)), Vec3<T>(T(0), T(1), T(0)), Vec3<T>(T(1), T(1), T(0)),
       Vec3<T>(T(2), T(3), T(0))},
      std::vector<Vec3<T>>(6, Vec3<T>(T(1), T(2), T(3))),
      {Vec3<T>(T(0), T(0), T(0)), Vec3<T>(T(1), T(1), T(1)), Vec3<T>(T(2), T(2), T(2)), Vec3<T>(T(3), T(3), T(3))}};
  for (const auto& points : bad) {
    const Status s = cookConvexMesh(points, out);
    EXPECT_EQ(s.code, StatusCode::DegenerateMesh) << points.size() << " points: " << s.toString();
    EXPECT_EQ(out, nullptr);
  }
}

TYPED_TEST(BadInputCooking, ConvexHullOfNonFinitePointsOrBadToleranceIsInvalidArgument) {
  using T = TypeParam;
  std::shared_ptr<const ConvexMesh<T>> out;
  for (const T bad : {kNaN<T>, kInf<T>}) {
    std::vector<Vec3<T>> points = cubePoints<T>();
    points[5].z() = bad;
    EXPECT_EQ(cookConvexMesh(points, out).code, StatusCode::InvalidArgument);
  }
  ConvexCookParams params;
  params.planeTolerance = -1;
  EXPECT_EQ(cookConvexMesh(cubePoints<T>(), out, params).code, StatusCode::InvalidArgument);
  EXPECT_EQ(out, nullptr);
}

TYPED_TEST(BadInputCooking, EmptyOrAllDegenerateTriangleMeshIsDegenerateMesh) {
  using T = TypeParam;
  std::shared_ptr<const TriangleMesh<T>> out;
  EXPECT_EQ(cookTriangleMesh<T>({}, {}, out).code, StatusCode::DegenerateMesh);
  EXPECT_EQ(cookTriangleMesh(cubePoints<T>(), {}, out).code, StatusCode::DegenerateMesh);
  // Repeated vertex, collinear vertices, coincident vertices.
  std::vector<Vec3<T>> v = {Vec3<T>(T(0), T(0), T(0)), Vec3<T>(T(1), T(0), T(0)), Vec3<T>(T(2), T(0), T(0)),
                            Vec3<T>(T(0), T(0), T(0))};
  EXPECT_EQ(cookTriangleMesh(v, {{0, 0, 1}, {0, 1, 2}, {0, 3, 0}}, out).code, StatusCode::DegenerateMesh);
  EXPECT_EQ(out, nullptr);
}

TYPED_TEST(BadInputCooking, TriangleIndexOutOfRangeOrNonFiniteVertexIsInvalidArgument) {
  using T = TypeParam;
  std::shared_ptr<const TriangleMesh<T>> out;
  std::vector<TriangleIndices> t = cubeTriangles();
  t[3][1] = 8;
  EXPECT_EQ(cookTriangleMesh(cubePoints<T>(), t, out).code, StatusCode::InvalidArgument);
  t[3][1] = 0xffffffffu;
  EXPECT_EQ(cookTriangleMesh(cubePoints<T>(), t, out).code, StatusCode::InvalidArgument);
  std::vector<Vec3<T>> v = cubePoints<T>();
  v[2].x() = kNaN<T>;
  EXPECT_EQ(cookTriangleMesh(v, cubeTriangles(), out).code, StatusCode::InvalidArgument);
  EXPECT_EQ(out, nullptr);
}

TYPED_TEST(BadInputCooking, HeightFieldWithTooFewOrAbsurdlyManySamplesIsInvalidArgument) {
  using T = TypeParam;
  std::shared_ptr<const HeightField<T>> out;
  HeightFieldDesc<T> desc;
  for (const auto& [rows, columns] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{
           {0, 0}, {1, 5}, {5, 1}, {0xffffffffu, 0xffffffffu}, {1u << 15, 1u << 15}, {0xffffffffu, 2}}) {
    desc.rows = rows;
    desc.columns = columns;
    const Status s = cookHeightField(desc, out);  // the absurd sizes must fail before allocating anything
    EXPECT_EQ(s.code, StatusCode::InvalidArgument) << rows << " x " << columns;
    EXPECT_STRNE(s.message(), "");
  }
  EXPECT_EQ(out, nullptr);
}

TYPED_TEST(BadInputCooking, HeightFieldWithWrongSampleCountNonFiniteHeightOrHoleOutOfRangeIsInvalidArgument) {
  using T = TypeParam;
  std::shared_ptr<const HeightField<T>> out;
  HeightFieldDesc<T> desc;
  desc.rows = desc.columns = 3;
  desc.heights.assign(8, T(0));
  EXPECT_EQ(cookHeightField(desc, out).code, StatusCode::InvalidArgument);
  desc.heights.assign(9, T(0));
  desc.heights[4] = kInf<T>;
  EXPECT_EQ(cookHeightField(desc, out).code, StatusCode::InvalidArgument);
  desc.heights[4] = T(0);
  desc.holes = {4};  // 2 x 2 cells: indices 0..3
  EXPECT_EQ(cookHeightField(desc, out).code, StatusCode::InvalidArgument);
  EXPECT_EQ(out, nullptr);
}

TYPED_TEST(BadInputCooking, MissingMeshFileOrFolderIsFileError) {
  using T = TypeParam;
  MeshData<T> m = sentinelMeshData<T>();
  EXPECT_EQ(loadMeshFile("/nonexistent/gq/mesh.obj", m).code, StatusCode::FileError);
  EXPECT_EQ(loadMeshFile("", m).code, StatusCode::FileError);
  const auto dir = scratchFile("placeholder", "").parent_path();
  const Status s = loadMeshFile(dir.string(), m);
  EXPECT_TRUE(s.code == StatusCode::FileError || s.code == StatusCode::ParseError) << s.toString();
  EXPECT_TRUE(isSentinel(m));
}

TYPED_TEST(BadInputCooking, MalformedOrEmptyMeshFileIsParseError) {
  using T = TypeParam;
  const std::vector<std::pair<std::string, std::string>> files = {
      {"empty.obj", ""},
      {"garbage.obj", "this is not a mesh \x01\x02\x03\n"},
      {"no_faces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"},
      {"bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"},
      {"empty.stl", ""},
      {"ascii_truncated.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0"},
      {"binary_truncated.stl", binaryStl(1000, 3)},
      {"binary_header_only.stl", binaryStl(0, 0)},
      {"unknown.xyz", "1 2 3\n"}};
  for (const auto& [name, bytes] : files) {
    MeshData<T> m = sentinelMeshData<T>();
    const Status s = loadMeshFile(scratchFile(name, bytes).string(), m);
    EXPECT_EQ(s.code, StatusCode::ParseError) << name << ": " << s.toString();
    EXPECT_STRNE(s.message(), "");
    EXPECT_TRUE(isSentinel(m)) << name;
  }
}

TYPED_TEST(BadInputCooking, NaNCoordinatesInAMeshFileAreRejectedAtLoadOrCook) {
  using T = TypeParam;
  MeshData<T> m = sentinelMeshData<T>();
  const Status s = loadMeshFile(scratchFile("nan.obj", "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").string(), m);
  if (s.ok()) {  // the loader passes numbers through; cooking must then refuse them
    std::shared_ptr<const TriangleMesh<T>> mesh;
    const bool finite = std::all_of(m.vertices.begin(), m.vertices.end(), [](const Vec3<T>& v) { return isFinite(v); });
    if (!finite) EXPECT_EQ(cookTriangleMesh(m.vertices, m.triangles, mesh).code, StatusCode::InvalidArgument);
  } else {
    EXPECT_EQ(s.code, StatusCode::ParseError) << s.toString();
    EXPECT_TRUE(isSentinel(m));
  }
}

}  // namespace
}  // namespace gq::hardening

namespace gq::hardening {
namespace {

// Regression (found by fuzz_point_queries): these points crashed qhull (its determinants overflow double).
TEST(BadInputCookingDouble, ConvexHullOfCoordinatesBeyond1e50IsInvalidArgument) {
  const std::vector<Vec3<double>> points = {
      {-8.2081686391925773e+291, -3, -1.6797940290797989e+62}, {7.6898357492576918e-78, -7.6875, 5.9042329941270784e+169},
      {5.3185841757355179e+87, -1.6797940290797989e+62, 7.6898357492576276e-78},
      {-8, 1.6453608312084192e+223, -5.1181110322177104e+271},
      {6.2448849556242614e+178, -2.5444737109221841e-111, 3.9947470077931918e-107},
      {-1e+30, -1.5032125394247303e-95, 0.25}, {-3.1875, 3.8125, -3.25}, {5.375, -4.625, -3.346003892147548e-265}};
  std::shared_ptr<const ConvexMesh<double>> out;
  EXPECT_EQ(cookConvexMesh(points, out).code, StatusCode::InvalidArgument);
  EXPECT_EQ(out, nullptr);
  // Up to the limit, hulls cook (a cube of half size 1e49).
  std::vector<Vec3<double>> big = cubePoints<double>();
  for (auto& p : big) p *= 1e49;
  EXPECT_TRUE(cookConvexMesh(big, out).ok());
}

}  // namespace
}  // namespace gq::hardening
