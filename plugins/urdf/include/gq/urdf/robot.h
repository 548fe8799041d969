#pragma once
// gq::urdf — a robot's collision model loaded from URDF (+ SRDF), forward kinematics and the allowed-collision
// matrix. Loading never throws: every entry returns a gq::Status. Instantiated for float and double.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gq/fit.h"
#include "gq/geometry.h"
#include "gq/status.h"
#include "gq/transform.h"

namespace gq::urdf {

// How a mesh collision element is modelled. Box/sphere/cylinder elements keep their own exact shape in every mode
// (a cylinder is gq's custom CylinderCallbacks, gq/custom_shapes.h). Every mode but `Mesh` and `BoxAabb` is fitted by
// gq::fitShape (gq/fit.h), and every fit encloses the mesh.
enum class Representation : std::uint8_t {
  Mesh,           // the triangle mesh itself (needs mesh-mesh queries)
  Hull,           // convex hull
  Box,            // approximate minimum-volume oriented box
  BoxAabb,        // bounding box aligned with the link frame
  Capsule,        // enclosing capsule of least volume over the candidate axes
  Sphere,         // smallest enclosing sphere
  BestPrimitive,  // the enclosing sphere, capsule, box or cylinder of the smallest certified error bound
  Fit,            // the cheapest enclosing fit within LoadOptions::fitTolerance: a primitive, a (simplified) hull,
                  // a convex decomposition (several shapes) or the mesh itself
};
const char* toString(Representation r);
// "mesh", "hull", "box", "box-aabb", "capsule", "sphere", "best-primitive" or "fit" (Fit keeps the tolerance it has).
Status parseRepresentation(const std::string& name, Representation& out);

struct LoadOptions {
  Representation representation = Representation::Hull;
  std::vector<std::string> packagePaths;  // folders searched for package://<name>/..., before ROS_PACKAGE_PATH
  bool useRosPackagePath = true;          // also search the ROS_PACKAGE_PATH environment variable
  double fitTolerance = 0.002;            // metres: Representation::Fit's largest certified error
  std::uint32_t fitMaxParts = 16;         // Representation::Fit: most parts of a convex decomposition
  // Metres: the certified error bound of the other fitted modes is refined until it is within the largest of this,
  // 1e-4 of the mesh's size and 2 % of the distance actually attained (a tighter target costs loading time, never
  // accuracy).
  double errorBoundTarget = 1e-4;
};

// Parses a mode of the CLI into `options`: the names of parseRepresentation, or "fit:<tolerance>" (metres, finite
// and > 0) for Representation::Fit. InvalidArgument for anything else; `options` is unchanged then.
Status parseMode(const std::string& mode, LoadOptions& options);

enum class JointType : std::uint8_t { Revolute, Continuous, Prismatic, Fixed };
const char* toString(JointType t);

template <class T> struct Joint {
  std::string name;
  JointType type = JointType::Fixed;
  std::uint32_t parentLink = 0, childLink = 0;
  Transform<T> origin;                  // parent link frame -> joint frame at q = 0
  Vec3<T> axis = Vec3<T>::UnitX();      // unit, in the joint frame
  T lower = T(0), upper = T(0);         // position limits (continuous: -pi, pi for sampling only)
  std::int32_t variable = -1;           // index in the configuration vector (-1: fixed or mimic)
  std::int32_t mimicJoint = -1;         // q = multiplier * q[mimicJoint] + offset
  T multiplier = T(1), offset = T(0);
};

template <class T> struct Link {
  std::string name;
  std::int32_t parentJoint = -1;  // -1 for the root
  std::vector<std::uint32_t> shapes;
};

enum class ShapeSource : std::uint8_t { Box, Sphere, Cylinder, Mesh };
const char* toString(ShapeSource s);

template <class T> struct Shape {
  std::uint32_t link = 0;
  Transform<T> origin;  // link frame -> shape frame
  Geometry<T> geometry;
  ShapeSource source = ShapeSource::Box;
  Representation representation = Representation::Hull;  // the mode that modelled it, for mesh sources
  FitRepresentation fitted = FitRepresentation::Mesh;     // what `geometry` is, for mesh sources
  std::uint32_t fitParts = 1;  // shapes the collision element became: a decomposition's parts are consecutive shapes
  // The mesh itself only: its convex hull (null for a flat mesh). Hull-disjoint implies mesh-disjoint, so the
  // checker tests the hulls (GJK) before the triangles.
  std::shared_ptr<const ConvexMesh<T>> boundingHull;
  std::string file;                 // resolved mesh path
  std::uint32_t sourceTriangles = 0;
  std::uint32_t modelTriangles = 0;  // triangles (or hull polygons) of what is checked
  // Certified upper bound (metres) of the two-sided Hausdorff distance between the source mesh's surface and the
  // surface of what is checked (the union of the element's parts), gq::certifyFit; 0 for exact shapes and the mesh.
  T errorBound = T(0);
  std::size_t bytes = 0;             // memory of the cooked representation
};

template <class T> struct RobotModel {
  std::string name;
  std::vector<Link<T>> links;    // links[0] is the root; parents precede children
  std::vector<Joint<T>> joints;  // in tree order: a joint's parent link is placed before it
  std::vector<Shape<T>> shapes;
  std::vector<std::string> variables;  // configuration vector layout: active (non-fixed, non-mimic) joints
  // Allowed-collision matrix over links (row-major links x links): nonzero = never checked.
  std::vector<std::uint8_t> allowed;
  std::vector<std::string> allowedReason;  // same layout: "adjacent", "same link", "srdf:<reason>" or ""
  std::vector<T> home;                     // SRDF "ready"/"home"/"default" group state, else zero within limits
  std::string homeSource;

  std::size_t linkCount() const { return links.size(); }
  bool isAllowed(std::uint32_t a, std::uint32_t b) const { return allowed[std::size_t(a) * links.size() + b] != 0; }
  std::int32_t findLink(const std::string& name) const;
  std::size_t memoryBytes() const;
};

// Loads a URDF file (and, if srdfPath is not empty, its SRDF). Mesh paths: package://<pkg>/rest through
// options.packagePaths then ROS_PACKAGE_PATH, file:// absolute, and relative paths against the URDF folder.
// Errors: FileError naming the missing URDF/SRDF/mesh file, ParseError for malformed XML or URDF content.
template <class T>
Status loadRobot(const std::string& urdfPath, const std::string& srdfPath, const LoadOptions& options,
                 RobotModel<T>& out);
// Same from strings; relative mesh paths resolve against `baseDir`.
template <class T>
Status loadRobotFromStrings(const std::string& urdfXml, const std::string& srdfXml, const std::string& baseDir,
                            const LoadOptions& options, RobotModel<T>& out);

// Resolves a URDF mesh URI to a file path that exists, or FileError naming the URI and the places searched.
Status resolveMeshPath(const std::string& uri, const std::string& baseDir, const LoadOptions& options,
                       std::string& path);

// Link poses in the model's root frame. q has one entry per model.variables, within the joint limits
// (continuous joints unbounded). InvalidArgument on a wrong size, a non-finite value or a value outside limits.
template <class T>
Status forwardKinematics(const RobotModel<T>& model, const std::vector<T>& q, std::vector<Transform<T>>& linkPoses);

// Uniform within the joint limits (continuous joints in [-pi, pi]); deterministic for a given generator state.
template <class T> std::vector<T> randomConfiguration(const RobotModel<T>& model, std::uint64_t& rngState);

}  // namespace gq::urdf
