// Loading: URI resolution, collision-only geometry, mesh scale, cylinders, and the errors of broken inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "gq/cooking.h"
#include "gq/custom_shapes.h"
#include "robot_paths.h"
#include "scratch_dir.h"

namespace gq::urdf::test {
namespace {

namespace fs = std::filesystem;

// A scratch folder with a unit-cube OBJ (corners at 0 and 1) for hand-written URDFs.
fs::path scratchDir() {
  const fs::path& dir = gqtest::processScratchDir();
  fs::create_directories(dir / "pkgroot" / "my_pkg" / "meshes");
  std::ofstream obj(dir / "pkgroot" / "my_pkg" / "meshes" / "cube.obj");
  obj << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
         "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
  return dir;
}

std::string oneLinkUrdf(const std::string& collisionGeometry) {
  return "<robot name=\"r\"><link name=\"a\"><visual><geometry><mesh filename=\"package://nowhere/visual.dae\"/>"
         "</geometry></visual><collision><geometry>" + collisionGeometry + "</geometry></collision></link></robot>";
}

template <class T> Status loadString(const std::string& urdf, const std::string& srdf, RobotModel<T>& m,
                                     Representation rep = Representation::Hull) {
  LoadOptions o = testOptions(rep);
  o.packagePaths = {(scratchDir() / "pkgroot").string()};
  return loadRobotFromStrings(urdf, srdf, scratchDir().string(), o, m);
}

template <class T> class UrdfLoading : public ::testing::Test {};
TYPED_TEST_SUITE(UrdfLoading, Scalars);

// On the real robots of the shared data folder (skipped when it does not hold them).
template <class T> class UrdfLoadingData : public RobotDataTest {};
TYPED_TEST_SUITE(UrdfLoadingData, Scalars);

TYPED_TEST(UrdfLoadingData, RealRobotsLoadCollisionGeometryOnlyWithoutOpeningVisualMeshes) {
  // The visual .dae files named by these URDFs are absent on purpose: loading must not touch them.
  for (const RobotFiles* r : {&kPanda, &kPandaPrimitives, &kUr5}) {
    RobotModel<TypeParam> m;
    const Status s = loadRobot(robotFile(r->urdf), robotFile(r->srdf), testOptions(Representation::Hull), m);
    ASSERT_TRUE(s.ok()) << r->name << ": " << s.toString();
    EXPECT_GT(m.shapes.size(), 6u) << r->name;
    EXPECT_EQ(m.variables.size(), r == &kUr5 ? 6u : 8u) << r->name;  // Panda: 7 arm joints + 1 finger (1 mimic)
  }
}

TYPED_TEST(UrdfLoading, MissingMeshFileFailsWithAnErrorNamingTheFile) {
  RobotModel<TypeParam> m;
  const Status s = loadString(oneLinkUrdf("<mesh filename=\"package://my_pkg/meshes/no_such_part.stl\"/>"), "", m);
  EXPECT_EQ(s.code, StatusCode::FileError);
  EXPECT_NE(s.toString().find("no_such_part.stl"), std::string::npos) << s.toString();
  RobotModel<TypeParam> r;
  const Status rel = loadString(oneLinkUrdf("<mesh filename=\"meshes/missing_relative.obj\"/>"), "", r);
  EXPECT_EQ(rel.code, StatusCode::FileError);
  EXPECT_NE(rel.toString().find("missing_relative.obj"), std::string::npos) << rel.toString();
}

TYPED_TEST(UrdfLoading, MissingUrdfOrSrdfFileFailsNamingIt) {
  RobotModel<TypeParam> m;
  Status s = loadRobot("/nonexistent/robot.urdf", "", testOptions(Representation::Hull), m);
  EXPECT_EQ(s.code, StatusCode::FileError);
  EXPECT_NE(s.toString().find("/nonexistent/robot.urdf"), std::string::npos);
  const fs::path urdf = scratchDir() / "one_link.urdf";
  std::ofstream(urdf) << oneLinkUrdf("<box size=\"1 1 1\"/>");
  s = loadRobot(urdf.string(), "/nonexistent/robot.srdf", testOptions(Representation::Hull), m);
  EXPECT_EQ(s.code, StatusCode::FileError);
  EXPECT_NE(s.toString().find("/nonexistent/robot.srdf"), std::string::npos);
}

TYPED_TEST(UrdfLoading, MalformedUrdfFailsWithAClearParseError) {
  const std::string broken[] = {
      "<robot name=\"r\"><link name=\"a\">",                                    // truncated XML
      "<robot name=\"r\"><link name=\"a\"/><joint name=\"j\" type=\"revolute\"><parent link=\"a\"/>"
      "<child link=\"ghost\"/><limit lower=\"0\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint></robot>",
      "<robot name=\"r\"><link name=\"a\"><collision><geometry><sphere radius=\"-1\"/></geometry></collision>"
      "</link></robot>",
      "not xml at all"};
  for (const auto& xml : broken) {
    RobotModel<TypeParam> m;
    const Status s = loadString(xml, "", m);
    EXPECT_EQ(s.code, StatusCode::ParseError) << xml << " -> " << s.toString();
    EXPECT_NE(s.toString().find("URDF"), std::string::npos) << s.toString();
    EXPECT_TRUE(m.links.empty()) << "no output on failure";
  }
}

TYPED_TEST(UrdfLoading, MalformedSrdfFailsWithAClearParseError) {
  const std::string urdf = oneLinkUrdf("<box size=\"1 1 1\"/>");
  const std::string broken[] = {"<robot name=\"r\"><disable_collisions link1=\"a\"", "<notrobot/>",
                                "<robot><disable_collisions link1=\"a\" reason=\"x\"/></robot>",
                                "<robot><group_state name=\"ready\"><joint name=\"j\" value=\"abc\"/></group_state></robot>"};
  for (const auto& srdf : broken) {
    RobotModel<TypeParam> m;
    const Status s = loadString(urdf, srdf, m);
    EXPECT_EQ(s.code, StatusCode::ParseError) << srdf << " -> " << s.toString();
    EXPECT_NE(s.toString().find("SRDF"), std::string::npos) << s.toString();
  }
}

TYPED_TEST(UrdfLoading, PackageUrisResolveThroughRosPackagePath) {
  LoadOptions o = testOptions(Representation::Hull);
  o.packagePaths.clear();
  o.useRosPackagePath = true;
  const std::string old = std::getenv("ROS_PACKAGE_PATH") ? std::getenv("ROS_PACKAGE_PATH") : "";
  setenv("ROS_PACKAGE_PATH", ("/nonexistent:" + (scratchDir() / "pkgroot").string()).c_str(), 1);
  std::string path;
  const Status s = resolveMeshPath("package://my_pkg/meshes/cube.obj", "/", o, path);
  setenv("ROS_PACKAGE_PATH", old.c_str(), 1);
  ASSERT_TRUE(s.ok()) << s.toString();
  EXPECT_EQ(fs::path(path), scratchDir() / "pkgroot" / "my_pkg" / "meshes" / "cube.obj");
}

TYPED_TEST(UrdfLoading, FileAndRelativeUrisResolve) {
  const std::string cube = (scratchDir() / "pkgroot" / "my_pkg" / "meshes" / "cube.obj").string();
  std::string path;
  ASSERT_TRUE(resolveMeshPath("file://" + cube, "/", testOptions(Representation::Hull), path).ok());
  EXPECT_EQ(path, cube);
  ASSERT_TRUE(resolveMeshPath("my_pkg/meshes/cube.obj", (scratchDir() / "pkgroot").string(),
                              testOptions(Representation::Hull), path).ok());
  EXPECT_EQ(fs::path(path), fs::path(cube));
}

TYPED_TEST(UrdfLoading, MeshScaleStretchesEachAxis) {
  using T = TypeParam;
  RobotModel<T> m;
  const Status s = loadString(oneLinkUrdf("<mesh filename=\"package://my_pkg/meshes/cube.obj\" scale=\"2 0.5 3\"/>"),
                              "", m, Representation::BoxAabb);
  ASSERT_TRUE(s.ok()) << s.toString();
  ASSERT_EQ(m.shapes.size(), 1u);
  const auto* box = m.shapes[0].geometry.template getIf<BoxGeometry<T>>();
  ASSERT_NE(box, nullptr);
  const T tol = T(50) * std::numeric_limits<T>::epsilon();
  EXPECT_NEAR(box->halfExtents.x(), T(1), tol);
  EXPECT_NEAR(box->halfExtents.y(), T(0.25), tol);
  EXPECT_NEAR(box->halfExtents.z(), T(1.5), tol);
  EXPECT_NEAR(m.shapes[0].origin.p.x(), T(1), tol);  // box centre = scaled cube centre (1, 0.25, 1.5)
  EXPECT_NEAR(m.shapes[0].origin.p.z(), T(1.5), tol);
}

// A mesh shape's memory counts every array of its cooked mesh: among them the vertex rows the ray and pair kernels
// read (TriangleMesh::leafVertices). The mesh: a unit cube whose faces are 8 x 8 grids (768 triangles), so its rows
// (36 or 72 bytes a triangle) outweigh its 8-vertex hull, which the shape's bytes also count.
TYPED_TEST(UrdfLoading, MeshShapeBytesCountTheCookedVertexRows) {
  using T = TypeParam;
  constexpr int kCells = 8;
  {
    std::ofstream obj(scratchDir() / "pkgroot" / "my_pkg" / "meshes" / "grid_cube.obj");
    int base = 1;
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        for (int i = 0; i <= kCells; ++i)
          for (int j = 0; j <= kCells; ++j) {
            double p[3];
            p[axis] = side;
            p[(axis + 1) % 3] = double(i) / kCells;
            p[(axis + 2) % 3] = double(j) / kCells;
            obj << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
          }
        for (int i = 0; i < kCells; ++i)
          for (int j = 0; j < kCells; ++j) {
            const int a = base + i * (kCells + 1) + j, b = a + 1, c = a + kCells + 1, d = c + 1;
            obj << "f " << a << ' ' << c << ' ' << d << "\nf " << a << ' ' << d << ' ' << b << '\n';
          }
        base += (kCells + 1) * (kCells + 1);
      }
  }
  RobotModel<T> m;
  const Status s = loadString(oneLinkUrdf("<mesh filename=\"package://my_pkg/meshes/grid_cube.obj\"/>"), "", m,
                              Representation::Mesh);
  ASSERT_TRUE(s.ok()) << s.toString();
  ASSERT_EQ(m.shapes.size(), 1u);
  const auto* mesh = m.shapes[0].geometry.template getIf<TriangleMeshGeometry<T>>();
  ASSERT_NE(mesh, nullptr);
  const TriangleMesh<T>& cooked = *mesh->mesh;
  ASSERT_EQ(cooked.triangles.size(), std::size_t(6 * 2 * kCells * kCells));
  const std::size_t indexBytes =
      (cooked.inputIndex.size() + cooked.cookedIndex.size() + cooked.hullVertices.size()) * sizeof(std::uint32_t);
  EXPECT_GE(m.shapes[0].bytes, cooked.vertices.size() * sizeof(Vec3<T>) +
                                   cooked.triangles.size() * sizeof(TriangleIndices) + indexBytes +
                                   cooked.leafVertices.size() * sizeof(T) + cooked.bvhBytes);
}

// A URDF cylinder (axis Z) is gq's exact custom Cylinder (axis X) turned onto Z: no polygonal approximation, so a
// ball grazing the rim between where a 64-gon prism's vertices would be touches it, and error 0 is reported.
TYPED_TEST(UrdfLoading, CylinderIsTheExactCustomCylinderAlongZ) {
  using T = TypeParam;
  RobotModel<T> m;
  ASSERT_TRUE(loadString(oneLinkUrdf("<cylinder radius=\"0.1\" length=\"0.4\"/>"), "", m).ok());
  ASSERT_EQ(m.shapes.size(), 1u);
  const Shape<T>& shape = m.shapes[0];
  EXPECT_EQ(shape.source, ShapeSource::Cylinder);
  const auto* custom = shape.geometry.template getIf<CustomGeometry<T>>();
  ASSERT_NE(custom, nullptr);
  const auto* cylinder = dynamic_cast<const CylinderCallbacks<T>*>(custom->callbacks.get());
  ASSERT_NE(cylinder, nullptr);
  const T tol = T(50) * std::numeric_limits<T>::epsilon();
  EXPECT_NEAR(cylinder->radius(), T(0.1), tol);
  EXPECT_NEAR(cylinder->halfHeight(), T(0.2), tol);
  EXPECT_NEAR(std::abs(shape.origin.rotate(Vec3<T>::UnitX()).z()), T(1), tol) << "custom X axis = URDF Z axis";
  EXPECT_EQ(shape.errorBound, T(0));
  // Ball of radius 0.01 centred at angle pi/64 (mid-edge of a 64-gon) at radial distance 0.11 - 3e-5: it overlaps
  // the true cylinder by 3e-5 but clears the prism by sagitta - 3e-5 = 0.1 (1 - cos(pi/64)) - 3e-5 = 9e-5.
  const double angle = M_PI / 64, radial = 0.11 - 3e-5;
  const Transform<T> ball(Vec3<T>(T(radial * std::cos(angle)), T(radial * std::sin(angle)), T(0.1)));
  bool hit = false;
  ASSERT_TRUE(overlap(shape.geometry, shape.origin, Geometry<T>(SphereGeometry<T>(T(0.01))), ball, hit).ok());
  EXPECT_TRUE(hit);
  const Transform<T> beyondCap(Vec3<T>(T(0), T(0), T(0.2 + 0.01 + 1e-4)));
  ASSERT_TRUE(overlap(shape.geometry, shape.origin, Geometry<T>(SphereGeometry<T>(T(0.01))), beyondCap, hit).ok());
  EXPECT_FALSE(hit);
}

}  // namespace
}  // namespace gq::urdf::test
