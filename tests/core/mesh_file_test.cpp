// loadMeshFile: small OBJ / STL (ascii, binary) / DAE files written here, node transforms, errors, coordinates read
// exactly (OBJ, STL), and the bunny of the shared data folder read exactly and raycast against its own numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "gq/io.h"
#include "gq/query.h"
#include "mesh_test_helpers.h"
#include "shared_data.h"

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
  EXPECT_NE(s.toString().find(path), std::string::npos) << s.toString();
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


// The correctly rounded value of a decimal number in T: what the file says, as the C library reads it.
template <class T> T fromText(const std::string& text) {
  if constexpr (std::is_same_v<T, float>) {
    return std::strtof(text.c_str(), nullptr);
  } else {
    return std::strtod(text.c_str(), nullptr);
  }
}

template <class T> bool sameBits(T a, T b) { return std::memcmp(&a, &b, sizeof(T)) == 0; }

// Coordinates with 17 significant digits, none of them a float (so a float round trip would change each).
const std::vector<std::string>& preciseCoordinates() {
  static const std::vector<std::string> c = {
      "0.10000000000000001",  "-1.2345678901234567", "3.1415926535897931",  "2.7182818284590451e-3",
      "-0.33333333333333331", "123456.78901234567",  "1.0000000000000002",  "-7.0710678118654757e-1",
      "+1.2345678901234567e-20"};
  for (const std::string& x : c) {
    const double d = std::strtod(x.c_str(), nullptr);
    EXPECT_NE(double(float(d)), d) << x;
  }
  return c;
}

TYPED_TEST(MeshFile, ObjCoordinatesAreReadExactly) {
  using T = TypeParam;
  const auto& c = preciseCoordinates();
  const std::string path = this->write("precise.obj", "v " + c[0] + " " + c[1] + " " + c[2] + "\nv " + c[3] + " " +
                                                          c[4] + " " + c[5] + "\nv " + c[6] + "\t" + c[7] + " " +
                                                          c[8] + " 1.0\nf 1 2 3\n");
  MeshData<T> m;
  const Status s = loadMeshFile(path, m);
  ASSERT_TRUE(s.ok()) << s.toString();
  ASSERT_EQ(m.vertices.size(), 3u);  // in order of first use by a triangle: the file's order here
  ASSERT_EQ(m.triangles.size(), 1u);
  for (int v = 0; v < 3; ++v)
    for (int k = 0; k < 3; ++k)
      EXPECT_TRUE(sameBits(m.vertices[m.triangles[0][v]][k], fromText<T>(c[3 * v + k])))
          << c[3 * v + k] << " read as " << std::hexfloat << m.vertices[m.triangles[0][v]][k];
}

TYPED_TEST(MeshFile, AsciiStlCoordinatesAreReadExactly) {
  using T = TypeParam;
  const auto& c = preciseCoordinates();
  const std::string path = this->write("precise.stl", "solid precise\r\n facet normal 0 0 1\r\n  outer loop\r\n"
                                                      "   vertex " + c[0] + " " + c[1] + " " + c[2] + "\r\n"
                                                      "   vertex " + c[3] + " " + c[4] + " " + c[5] + "\r\n"
                                                      "   vertex " + c[6] + " " + c[7] + " " + c[8] + "\r\n"
                                                      "  endloop\r\n endfacet\r\nendsolid precise\r\n");
  MeshData<T> m;
  const Status s = loadMeshFile(path, m);
  ASSERT_TRUE(s.ok()) << s.toString();
  ASSERT_EQ(m.vertices.size(), 3u);
  ASSERT_EQ(m.triangles.size(), 1u);
  for (int v = 0; v < 3; ++v)
    for (int k = 0; k < 3; ++k)
      EXPECT_TRUE(sameBits(m.vertices[m.triangles[0][v]][k], fromText<T>(c[3 * v + k])))
          << c[3 * v + k] << " read as " << std::hexfloat << m.vertices[m.triangles[0][v]][k];
}

TYPED_TEST(MeshFile, BinaryStlFloatsAreReadExactly) {
  using T = TypeParam;
  const std::array<float, 9> xyz = {0.1f, -1.2345678f, 3.1415927f, 2.7182817e-3f, -0.33333334f,
                                    123456.79f, 1.0000001f, -0.70710677f, 4.440892e-16f};
  const std::string path = this->write("floats.stl", binaryStl({xyz}, 1));
  MeshData<T> m;
  const Status s = loadMeshFile(path, m);
  ASSERT_TRUE(s.ok()) << s.toString();
  ASSERT_EQ(m.vertices.size(), 3u);
  for (int v = 0; v < 3; ++v)
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(sameBits(m.vertices[m.triangles[0][v]][k], T(xyz[3 * v + k])));
}

// Twice the signed area of triangle (a, b, c) in the XY plane.
template <class T> double area2(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  return double(b.x() - a.x()) * double(c.y() - a.y()) - double(b.y() - a.y()) * double(c.x() - a.x());
}

TYPED_TEST(MeshFile, ObjConcavePolygonIsTriangulatedInsideItAndNegativeIndicesAreRelative) {
  using T = TypeParam;
  // An L-shaped hexagon (area 3), counter-clockwise from a reflex corner's neighbour, given by relative indices. A fan
  // from its first corner would leave the polygon and overlap itself (the triangles' areas would not add up to 3).
  const std::string path = this->write("l.obj",
                                       "v 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\n"
                                       "f -6 -5 -4 -3 -2 -1\n");
  MeshData<T> m;
  const Status s = loadMeshFile(path, m);
  ASSERT_TRUE(s.ok()) << s.toString();
  ASSERT_EQ(m.triangles.size(), 4u);
  double sum = 0, sumAbs = 0;
  for (const auto& t : m.triangles) {
    const double a = area2(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]);
    EXPECT_GT(a, 0) << "every triangle keeps the polygon's counter-clockwise winding";
    sum += a;
    sumAbs += std::abs(a);
  }
  EXPECT_EQ(sum, 6.0);
  EXPECT_EQ(sumAbs, 6.0);
}

TYPED_TEST(MeshFile, BadObjAndAsciiStlContentIsParseErrorNamingTheLineAndChangesNothing) {
  using T = TypeParam;
  const std::vector<std::pair<std::string, std::string>> files = {
      {"index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"},
      {"relative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n"},
      {"word.obj", "v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n"},
      {"short.obj", "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n"},
      {"inf.obj", "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"two.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n"},
      {"word.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 x\nvertex 0 1 0\nendloop\n"
                   "endfacet\nendsolid s\n"},
      {"cut.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"},
      {"none.stl", "solid s\nendsolid s\n"}};
  for (const auto& [name, content] : files) {
    MeshData<T> m;
    m.vertices = {Vec3<T>(1, 2, 3)};
    const Status s = loadMeshFile(this->write(name, content), m);
    EXPECT_EQ(s.code, StatusCode::ParseError) << name << ": " << s.toString();
    EXPECT_NE(s.toString().find(name), std::string::npos) << s.toString();
    ASSERT_EQ(m.vertices.size(), 1u) << name;
    EXPECT_TRUE(m.triangles.empty()) << name;
  }
  MeshData<T> m;
  const Status s = loadMeshFile(this->write("word2.obj", "v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n"), m);
  EXPECT_NE(s.toString().find("line 2"), std::string::npos) << s.toString();
}

// The bunny of the shared data folder, read exactly: every triangle corner holds the strtod of the file's text, and a
// double raycast matches the hit computed (in long double) from the file's own numbers to 1e-12.
class MeshFileData : public ::testing::Test {
 protected:
  struct FileMesh {
    std::vector<std::array<double, 3>> vertices;
    std::vector<std::array<std::size_t, 3>> faces;
  };
  static FileMesh parse(const std::string& path) {
    FileMesh f;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
      std::istringstream fields(line);
      std::string tag, a, b, c;
      fields >> tag >> a >> b >> c;
      if (tag == "v") {
        f.vertices.push_back({std::strtod(a.c_str(), nullptr), std::strtod(b.c_str(), nullptr),
                              std::strtod(c.c_str(), nullptr)});
      } else if (tag == "f") {
        f.faces.push_back({std::stoul(a) - 1, std::stoul(b) - 1, std::stoul(c) - 1});
      }
    }
    return f;
  }
};

TEST_F(MeshFileData, BunnyLoadsWith69451TrianglesInFloatAndDouble) {
  GQ_REQUIRE_SHARED_FILE(meshtest::bunnyPath());
  MeshData<float> f;
  MeshData<double> d;
  ASSERT_TRUE(loadMeshFile(meshtest::bunnyPath(), f).ok());
  const Status s = loadMeshFile(meshtest::bunnyPath(), d);
  ASSERT_TRUE(s.ok()) << s.toString();
  EXPECT_EQ(f.triangles.size(), 69451u);
  EXPECT_EQ(d.triangles.size(), 69451u);
  EXPECT_EQ(f.vertices.size(), d.vertices.size());
  for (const auto& t : d.triangles)
    for (auto i : t) ASSERT_LT(i, d.vertices.size());
}

TEST_F(MeshFileData, DoubleBunnyHoldsTheFilesNumbersAndRaycastsMatchThemTo1e12) {
  const std::string path = meshtest::bunnyPath();
  GQ_REQUIRE_SHARED_FILE(path);
  const FileMesh file = parse(path);
  MeshData<double> m;
  const Status s = loadMeshFile(path, m);
  ASSERT_TRUE(s.ok()) << s.toString();
  ASSERT_EQ(m.triangles.size(), file.faces.size());
  ASSERT_EQ(file.faces.size(), 69451u);
  // Triangles keep the file's order and corners; each corner is the file's vertex bit for bit.
  std::size_t differing = 0;
  for (std::size_t t = 0; t < file.faces.size(); ++t)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k)
        differing += !sameBits(m.vertices[m.triangles[t][c]][k], file.vertices[file.faces[t][c]][k]);
  EXPECT_EQ(differing, 0u);

  const auto mesh = meshtest::cook(m.vertices, m.triangles);
  ASSERT_NE(mesh, nullptr);
  const TriangleMeshGeometry<double> geometry(mesh);
  using L = long double;
  std::size_t checked = 0;
  for (std::size_t t = 0; t < file.faces.size(); t += 691) {
    // Towards the centroid of face t, from 0.5 outside the bunny along a fixed slanted direction.
    std::array<std::array<L, 3>, 3> p;
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) p[c][k] = file.vertices[file.faces[t][c]][k];
    const Vec3<double> dir = Vec3<double>(0.3, -0.8, 0.52).normalized();
    Vec3<double> target;
    for (int k = 0; k < 3; ++k) target[k] = double((p[0][k] + p[1][k] + p[2][k]) / 3);
    const Vec3<double> origin = target - 0.5 * dir;
    RaycastHit<double> hit;
    std::uint32_t n = 0;
    const Status rs = raycast<double>(origin, dir, geometry, Transform<double>(), 2.0,
                                      kDefaultHitFlags | HitFlag::UV | HitFlag::MeshBothSides, 1, &hit, n);
    ASSERT_TRUE(rs.ok()) << rs.toString();
    if (n != 1) continue;  // cannot miss (the ray reaches face t), but a failure is reported by `checked` below
    ASSERT_LT(hit.faceIndex, file.faces.size());
    // The reference: the ray against the file's triangle hit.faceIndex, Moller-Trumbore in long double.
    std::array<std::array<L, 3>, 3> q;
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) q[c][k] = file.vertices[file.faces[hit.faceIndex][c]][k];
    const std::array<L, 3> o = {origin.x(), origin.y(), origin.z()}, d = {dir.x(), dir.y(), dir.z()};
    const auto sub = [](const std::array<L, 3>& a, const std::array<L, 3>& b) {
      return std::array<L, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    };
    const auto cross = [](const std::array<L, 3>& a, const std::array<L, 3>& b) {
      return std::array<L, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    const auto dot = [](const std::array<L, 3>& a, const std::array<L, 3>& b) {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    const auto e1 = sub(q[1], q[0]), e2 = sub(q[2], q[0]), pv = cross(d, e2);
    const L det = dot(e1, pv);
    ASSERT_NE(det, 0.0L);
    const auto tv = sub(o, q[0]);
    const L u = dot(tv, pv) / det;
    const auto qv = cross(tv, e1);
    const L v = dot(d, qv) / det, distance = dot(e2, qv) / det;
    EXPECT_GE(u, -1e-9L);
    EXPECT_GE(v, -1e-9L);
    EXPECT_LE(u + v, 1 + 1e-9L);
    EXPECT_NEAR(double(hit.distance), double(distance), 1e-12) << "face " << hit.faceIndex;
    EXPECT_NEAR(double(hit.u), double(u), 1e-9) << "face " << hit.faceIndex;
    EXPECT_NEAR(double(hit.v), double(v), 1e-9) << "face " << hit.faceIndex;
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(hit.position[k], double(o[k] + distance * d[k]), 1e-12) << "face " << hit.faceIndex;
    ++checked;
  }
  EXPECT_EQ(checked, (file.faces.size() + 690) / 691);
}

}  // namespace
}  // namespace gq
