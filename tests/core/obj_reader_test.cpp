// loadMeshFile on OBJ files (gq's own reader, cook/obj_reader.cpp): corner forms, negative indices, triangulation of
// concave polygons, vertex compaction, float rounding, errors (outputs untouched), and parity with assimp's import of
// every shared OBJ mesh.
#include <gtest/gtest.h>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>

#include "gq/cooking.h"

namespace gq {
namespace {

namespace fs = std::filesystem;

class ObjReader : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() /
          ("gq_obj_reader_test_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  std::string write(const std::string& content, const std::string& name = "m.obj") {
    const std::string path = (dir / name).string();
    std::ofstream(path, std::ios::binary) << content;
    return path;
  }
  MeshData<double> load(const std::string& content) {
    MeshData<double> m;
    const Status s = loadMeshFile(write(content), m);
    EXPECT_TRUE(s.ok()) << s.toString();
    return m;
  }
  fs::path dir;
};

using Point = std::array<double, 3>;

Point at(const MeshData<double>& m, std::uint32_t i) { return {m.vertices[i].x(), m.vertices[i].y(), m.vertices[i].z()}; }

std::set<std::array<Point, 3>> triangleSet(const MeshData<double>& m) {
  std::set<std::array<Point, 3>> s;
  for (const auto& t : m.triangles) s.insert({at(m, t[0]), at(m, t[1]), at(m, t[2])});
  return s;
}

// Signed area of triangle (a, b, c) in the z = 0 plane.
double signedArea(const Point& a, const Point& b, const Point& c) {
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

TEST_F(ObjReader, CornerFormsWithTextureAndNormalIndicesUseTheVertexIndex) {
  const auto m = load("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2//1 3/1\n");
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(triangleSet(m), (std::set<std::array<Point, 3>>{{Point{0, 0, 0}, Point{1, 0, 0}, Point{0, 1, 0}}}));
}

TEST_F(ObjReader, NegativeIndicesCountBackFromTheLastVertexRead) {
  const auto m = load("v 9 9 9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 5 5\n");
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(triangleSet(m), (std::set<std::array<Point, 3>>{{Point{0, 0, 0}, Point{1, 0, 0}, Point{0, 1, 0}}}));
}

TEST_F(ObjReader, ConcavePolygonIsTriangulatedInsideItself) {
  // A dart (area 4, reflex corner (1,1)) listed so that a fan from the first corner would leave the polygon.
  const auto m = load("v 4 0 0\nv 1 1 0\nv 0 4 0\nv 0 0 0\nf 1 2 3 4\n");
  ASSERT_EQ(m.triangles.size(), 2u);
  double total = 0;
  for (const auto& t : m.triangles) {
    const double a = signedArea(at(m, t[0]), at(m, t[1]), at(m, t[2]));
    EXPECT_GT(a, 0.0) << "every triangle keeps the polygon's counter-clockwise orientation";
    total += a;
  }
  EXPECT_DOUBLE_EQ(total, 4.0);  // shoelace area of the dart
}

TEST_F(ObjReader, ConvexPolygonIsFannedFromItsFirstCorner) {
  const auto m = load("v 0 0 0\nv 2 0 0\nv 3 1 0\nv 2 2 0\nv 0 2 0\nf 1 2 3 4 5\n");
  ASSERT_EQ(m.triangles.size(), 3u);
  double total = 0;
  for (const auto& t : m.triangles) {
    EXPECT_EQ(at(m, t[0]), (Point{0, 0, 0}));
    total += signedArea(at(m, t[0]), at(m, t[1]), at(m, t[2]));
  }
  EXPECT_DOUBLE_EQ(total, 5.0);
}

TEST_F(ObjReader, UnreferencedVerticesAreDroppedAndIdenticalCoordinatesJoined) {
  // Vertices 1 and 4 repeat the same point (once as -0); vertex 6 is never used.
  const auto m = load("v 0 0 0\nv 1 0 0\nv 0 1 0\nv -0 0 0\nv 0 0 1\nv 7 7 7\nf 1 2 3\nf 4 2 5\n");
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.triangles[0][0], m.triangles[1][0]);
  for (const auto& v : m.vertices) EXPECT_NE(v.x(), 7.0);
}

TEST_F(ObjReader, CoordinatesAreRoundedToFloatLikeStlAndDae) {
  const auto m = load("v 0.1 0 0\nv 1 0 0\nv 0 1e-3 0\nf 1 2 3\n");
  EXPECT_EQ(at(m, m.triangles[0][0])[0], double(0.1f));
  EXPECT_EQ(at(m, m.triangles[0][2])[1], double(1e-3f));
}

TEST_F(ObjReader, PointsLinesCommentsGroupsAndCrLfAreSkipped) {
  const auto m = load("# comment\r\nmtllib none.mtl\r\no part\r\ng a\r\nusemtl x\r\ns 1\r\nv +1 0 0\r\nv 0 1 0\r\n"
                      "v 0 0 1.5e0\r\np 1\r\nl 1 2\r\nf 1 2\r\nf 1 2 3\r\n");
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(triangleSet(m), (std::set<std::array<Point, 3>>{{Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1.5}}}));
}

TEST_F(ObjReader, MalformedStatementsAndIndicesAreParseErrorNamingTheLineAndLeaveTheOutputUntouched) {
  const std::vector<std::string> bad = {
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n",   // index past the last vertex
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",   // OBJ indices start at 1
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n",  // before the first vertex
      "v 0 0 0\nv 1 0 0\nv 0 1\nf 1 2 3\n",     // two coordinates
      "v 0 0 0\nv 1 0 x\nv 0 1 0\nf 1 2 3\n",   // not a number
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 a\n",   // not an index
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n",
      "v 0 0 0\nv 1 0 0\nv 0 1 0\n",            // no faces
      "",
  };
  for (const auto& text : bad) {
    MeshData<double> m;
    m.triangles = {{7, 7, 7}};
    const Status s = loadMeshFile(write(text), m);
    EXPECT_EQ(s.code, StatusCode::ParseError) << text;
    EXPECT_NE(s.message.find("m.obj"), std::string::npos) << s.message;
    EXPECT_TRUE(m.vertices.empty() && m.triangles.size() == 1 && m.triangles[0][0] == 7) << text;
  }
  MeshData<double> m;
  const Status s = loadMeshFile(write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"), m);
  EXPECT_NE(s.message.find("line 4"), std::string::npos) << s.message;
}

TEST_F(ObjReader, UppercaseExtensionUsesTheSameReader) {
  MeshData<float> m;
  ASSERT_TRUE(loadMeshFile(write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "M.OBJ"), m).ok());
  EXPECT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.vertices.size(), 3u);
}

// Same triangles, in the same order and with the same corner order, as assimp's OBJ import (triangulated, vertices
// joined) of every shared OBJ mesh (each one object). Coordinates agree to one float ulp: assimp's fast_atof is not
// correctly rounded (the bunny's decimals happen to come out identical), gq's from_chars is.
TEST_F(ObjReader, SharedMeshesGiveAssimpsTrianglesToOneFloatUlp) {
  for (const char* name : {"stanford-bunny.obj", "teapot.obj", "fandisk.obj", "spot.obj"}) {
    const std::string path = std::string(GQ_SHARED_DIR) + "/meshes/" + name;
    MeshData<double> ours;
    ASSERT_TRUE(loadMeshFile(path, ours).ok()) << name;
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
    ASSERT_TRUE(scene != nullptr && scene->mNumMeshes == 1) << name;
    const aiMesh& mesh = *scene->mMeshes[0];
    ASSERT_EQ(ours.triangles.size(), std::size_t(mesh.mNumFaces)) << name;
    for (std::size_t f = 0; f < ours.triangles.size(); ++f) {
      ASSERT_EQ(mesh.mFaces[f].mNumIndices, 3u);
      for (int c = 0; c < 3; ++c) {
        const aiVector3D& v = mesh.mVertices[mesh.mFaces[f].mIndices[c]];
        const Vec3<double>& w = ours.vertices[ours.triangles[f][c]];
        for (int k = 0; k < 3; ++k) {
          const double ulp = std::numeric_limits<float>::epsilon() * std::max(1.0, std::abs(double(v[k])));
          ASSERT_LE(std::abs(double(v[k]) - w[k]), ulp) << name << " face " << f << " corner " << c;
        }
      }
    }
  }
}

}  // namespace
}  // namespace gq
