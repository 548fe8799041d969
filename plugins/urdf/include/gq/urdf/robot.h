#pragma once
// gq::urdf — a robot's collision model loaded from URDF (+ SRDF), forward kinematics and the allowed-collision
// matrix. Loading never throws: every entry returns a gq::Status. Instantiated for float and double.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gq/geometry.h"
#include "gq/status.h"
#include "gq/transform.h"

namespace gq::urdf {

// How a mesh collision element is modelled. Box/sphere/cylinder elements keep their own exact shape in every mode
// (a cylinder is gq's custom CylinderCallbacks, gq/custom_shapes.h).
enum class Representation : std::uint8_t {
  Mesh,           // the triangle mesh itself (needs mesh-mesh queries)
  Hull,           // convex hull (qhull)
  Box,            // PCA-oriented bounding box
  BoxAabb,        // bounding box aligned with the link frame
  Capsule,        // capsule along the principal axis, enclosing every vertex
  Sphere,         // enclosing sphere
  BestPrimitive,  // the enclosing box / capsule / sphere of least volume
};
const char* toString(Representation r);
Status parseRepresentation(const std::string& name, Representation& out);

struct LoadOptions {
  Representation representation = Representation::Hull;
  std::vector<std::string> packagePaths;  // folders searched for package://<name>/..., before ROS_PACKAGE_PATH
  bool useRosPackagePath = true;          // also search the ROS_PACKAGE_PATH environment variable
  std::uint32_t errorSamplesPerShape = 2000;  // surface samples for the measured approximation error
  std::uint64_t errorSeed = 1;
};

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

// Measured geometric error of a shape's representation against its source (0 for exact shapes).
template <class T> struct ApproximationError {
  // max over mesh vertices and points sampled on the mesh triangles of the distance to the approximation solid
  // (the one-sided Hausdorff distance mesh -> approximation; 0 when the approximation encloses the mesh)
  T meshToApproximation = T(0);
  // max over points sampled on the approximation's surface of the distance to the source surface: how far the
  // representation reaches beyond the real shape (0 for boxes, spheres and the exact cylinders)
  T approximationToMesh = T(0);
};

template <class T> struct Shape {
  std::uint32_t link = 0;
  Transform<T> origin;  // link frame -> shape frame
  Geometry<T> geometry;
  ShapeSource source = ShapeSource::Box;
  Representation representation = Representation::Hull;  // what `geometry` is, for mesh sources
  // Mesh representation only: the mesh's convex hull. Hull-disjoint implies mesh-disjoint, so the checker tests
  // the hulls (GJK) before the triangles.
  std::shared_ptr<const ConvexMesh<T>> boundingHull;
  std::string file;                 // resolved mesh path
  std::uint32_t sourceTriangles = 0;
  std::uint32_t modelTriangles = 0;  // triangles (or hull polygons) of what is checked
  ApproximationError<T> error;
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
