// loadMeshFile: the bunny, small OBJ / STL (ascii, binary) / DAE files written here, node transforms, and errors.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "gq/cooking.h"
#include "mesh_test_helpers.h"

namespace gq {
namespace {

namespace fs = std::filesystem;
using meshtest::Scalars;

template <class T> class MeshFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() /
          ("gq_mesh_file_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name() + (std::is_same_v<T, float> ? "_f" : "_d"));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  std::string write(const std::string& name, const std::string& content) {
    const std::string path = (dir / name).string();
    std::ofstream(path, std::ios::binary) << content;
    return path;
  }
  fs::path dir;
};
TYPED_TEST_SUITE(MeshFile, Scalars);

// Sorted copy of the vertices, for comparisons that must not depend on assimp's vertex order.
template <class T> std::vector<std::array<double, 3>> sortedVertices(const MeshData<T>& m) {
  std::vector<std::array<double, 3>> v;
  for (const auto& x : m.vertices) v.push_back({double(x.x()), double(x.y()), double(x.z())});
  std::sort(v.begin(), v.end());
  return v;
}

TYPED_TEST(MeshFile, LoadsTheBunnyWith69451Triangles) {
  MeshData<TypeParam> m;
  const Status s = loadMeshFile(meshtest::bunnyPath(), m);
  ASSERT_TRUE(s.ok()) << s.toString();
  EXPECT_EQ(m.triangles.size(), 69451u);
  for (const auto& t : m.triangles)
    for (auto i : t) ASSERT_LT(i, m.vertices.size());
}

TYPED_TEST(MeshFile, ObjPolygonsAreTriangulatedAndIdenticalVerticesJoined) {
  using T = TypeParam;
  const std::string path = this->write("quad.obj",
                                       "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
                                       "f 1 2 3 4\nf 1 2 5\n");
  MeshData<T> m;
  ASSERT_TRUE(loadMeshFile(path, m).ok());
  EXPECT_EQ(m.triangles.size(), 3u);
  EXPECT_EQ(m.vertices.size(), 5u);
  const auto v = sortedVertices(m);
  EXPECT_EQ(v.front(), (std::array<double, 3>{0, 0, 0}));
  EXPECT_EQ(v.back(), (std::array<double, 3>{1, 1, 0}));
}

TYPED_TEST(MeshFile, AsciiStlLoadsWithSharedVerticesJoined) {
  using T = TypeParam;
  const std::string path = this->write("two.stl",
                                       "solid two\n"
                                       "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 1 1 0\n"
                                       " endloop\nendfacet\n"
                                       "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 1 0\n  vertex 0 1 0\n"
                                       " endloop\nendfacet\nendsolid two\n");
  MeshData<T> m;
  ASSERT_TRUE(loadMeshFile(path, m).ok());
  EXPECT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.vertices.size(), 4u);
}

std::string binaryStl(const std::vector<std::array<float, 9>>& tris, std::uint32_t declaredCount) {
  std::string s(80, ' ');
  s.replace(0, 6, "binary");
  s.append(reinterpret_cast<const char*>(&declaredCount), 4);
  for (const auto& t : tris) {
    const float normal[3] = {0, 0, 1};
    s.append(reinterpret_cast<const char*>(normal), 12);
    s.append(reinterpret_cast<const char*>(t.data()), 36);
    s.append(2, '\0');
  }
  return s;
}

TYPED_TEST(MeshFile, BinaryStlLoads) {
  using T = TypeParam;
  const std::string path =
      this->write("bin.stl", binaryStl({{0, 0, 0, 2, 0, 0, 0, 3, 0}, {0, 0, 0, 0, 3, 0, 0, 0, 4}}, 2));
  MeshData<T> m;
  const Status s = loadMeshFile(path, m);
  ASSERT_TRUE(s.ok()) << s.toString();
  EXPECT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(sortedVertices(m).back(), (std::array<double, 3>{2, 0, 0}));
}

// A Z-up COLLADA file whose node translates its triangle by (1, 2, 3).
std::string colladaTriangle() {
  return R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries>
    <geometry id="tri" name="tri"><mesh>
      <source id="tri-pos">
        <float_array id="tri-pos-array" count="9">0 0 0 1 0 0 0 1 0</float_array>
        <technique_common><accessor source="#tri-pos-array" count="3" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common>
      </source>
      <vertices id="tri-vtx"><input semantic="POSITION" source="#tri-pos"/></vertices>
      <triangles count="1"><input semantic="VERTEX" source="#tri-vtx" offset="0"/><p>0 1 2</p></triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="Scene" name="Scene">
      <node id="n" name="n">
        <matrix>1 0 0 1 0 1 0 2 0 0 1 3 0 0 0 1</matrix>
        <instance_geometry url="#tri"/>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#Scene"/></scene>
</COLLADA>
)";
}

TYPED_TEST(MeshFile, DaeAppliesNodeTransformsAndIgnoreRootTransformDropsTheUpAxis) {
  using T = TypeParam;
  const std::string path = this->write("tri.dae", colladaTriangle());
  MeshData<T> local, full;
  ASSERT_TRUE(loadMeshFile(path, local, true).ok());
  ASSERT_TRUE(loadMeshFile(path, full, false).ok());
  ASSERT_EQ(local.triangles.size(), 1u);
  ASSERT_EQ(full.triangles.size(), 1u);
  // Root transform dropped: the node translation only.
  const auto v = sortedVertices(local);
  ASSERT_EQ(v.size(), 3u);
  const std::vector<std::array<double, 3>> expected = {{1, 2, 3}, {1, 3, 3}, {2, 2, 3}};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(v[i][k], expected[i][k], 1e-6);
  // With the root's Z-up -> Y-up rotation: (x, y, z) -> (x, z, -y).
  const auto w = sortedVertices(full);
  const std::vector<std::array<double, 3>> rotated = {{1, 3, -3}, {1, 3, -2}, {2, 3, -2}};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(w[i][k], rotated[i][k], 1e-6);
}

TYPED_TEST(MeshFile, MissingFileIsFileErrorNamingThePath) {
  MeshData<TypeParam> m;
  const std::string path = (this->dir / "no_such_mesh.obj").string();
  const Status s = loadMeshFile(path, m);
  EXPECT_EQ(s.code, StatusCode::FileError);
  EXPECT_NE(s.message.find(path), std::string::npos) << s.message;
  EXPECT_TRUE(m.vertices.empty());
}

TYPED_TEST(MeshFile, MalformedFileIsParseError) {
  using T = TypeParam;
  MeshData<T> m;
  // A binary STL that declares 10 triangles but holds 1, and a DAE cut in the middle of its XML.
  const std::string stl = this->write("short.stl", binaryStl({{0, 0, 0, 1, 0, 0, 0, 1, 0}}, 10));
  EXPECT_EQ(loadMeshFile(stl, m).code, StatusCode::ParseError);
  const std::string dae = this->write("cut.dae", colladaTriangle().substr(0, 500));
  EXPECT_EQ(loadMeshFile(dae, m).code, StatusCode::ParseError);
  const std::string obj = this->write("text.obj", "this is not a mesh\n");
  EXPECT_EQ(loadMeshFile(obj, m).code, StatusCode::ParseError);
  EXPECT_TRUE(m.vertices.empty());
}

}  // namespace
}  // namespace gq
