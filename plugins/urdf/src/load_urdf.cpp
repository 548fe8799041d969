// URDF loading through urdfdom: links and joints in tree order, collision elements only (visual meshes are never
// opened), SRDF pairs and group states, then the allowed-collision matrix. urdfdom reports parse errors through
// console_bridge; they are captured into the returned Status instead of being printed.
#include <console_bridge/console.h>
#include <cstring>
#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <vector>

#include "gq/io.h"
#include "internal.h"

namespace gq::urdf {
namespace {

// Collects console_bridge errors while urdfdom parses (console_bridge's handler is global: hence the mutex).
class CapturedLog : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) messages += (messages.empty() ? "" : "; ") + text;
  }
  std::string messages;
};
std::mutex& parserMutex() {
  static std::mutex m;
  return m;
}

Status readFile(const std::string& path, const char* what, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::owned(StatusCode::FileError, std::string(what) + " file '" + path + "' cannot be opened");
  std::stringstream ss;
  ss << in.rdbuf();
  out = ss.str();
  return {};
}

// What keeps the joint graph (parent -> child edges) from being a tree, or "" for none. urdfdom puts each child
// link into its parent's child list by shared pointer, so a cyclic joint graph (e.g. a joint whose parent is its
// child) is never freed when urdfdom then rejects the model (found by fuzz_urdf under LeakSanitizer): such input is
// refused first.
// Kahn's algorithm: links left with a parent after peeling off every root are on or below a cycle.
// A link that is the child of two joints is refused too (a URDF is a tree): urdfdom keeps the last parent it reads
// but lists the link under both parents, so the breadth-first walk met it twice, once before its parent
// (found by fuzz_urdf: an out-of-range parent index read in computeAllowedCollisions).
std::string jointGraphProblem(const TiXmlDocument& doc) {
  const TiXmlElement* robot = doc.FirstChildElement("robot");
  if (!robot) return {};
  std::multimap<std::string, std::string> children;  // parent -> child
  std::map<std::string, int> parents;                 // link -> number of parent joints
  std::string twoParents;                             // the first link met as the child of a second joint
  for (const TiXmlElement* j = robot->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint")) {
    const auto* p = j->FirstChildElement("parent");
    const auto* c = j->FirstChildElement("child");
    const char* parent = p ? p->Attribute("link") : nullptr;
    const char* child = c ? c->Attribute("link") : nullptr;
    if (!parent || !child) continue;  // urdfdom rejects the joint
    children.emplace(parent, child);
    parents[parent] += 0;
    if (++parents[child] == 2 && twoParents.empty()) twoParents = child;
  }
  std::vector<std::string> roots;
  for (const auto& [link, count] : parents)
    if (count == 0) roots.push_back(link);
  while (!roots.empty()) {
    const std::string link = roots.back();
    roots.pop_back();
    const auto [first, last] = children.equal_range(link);
    for (auto it = first; it != last; ++it)
      if (--parents[it->second] == 0) roots.push_back(it->second);
  }
  for (const auto& [link, count] : parents)
    if (count > 0) return "joints form a cycle through link '" + link + "'";
  if (!twoParents.empty()) return "link '" + twoParents + "' is the child of more than one joint";
  return {};
}

// urdfdom 3 hands some messages built from attribute values to console_bridge as the printf format (a sphere radius
// that is not a number, for one), and the handler above makes console_bridge format them: a "%s" in such a value
// read a wild pointer (found by fuzz_urdf: SEGV in vsnprintf). No number, name or joint type needs '%', so an
// attribute holding one is refused before urdfdom reads it; mesh filenames keep theirs (URL escapes, e.g. "%20").
// The name of the first such attribute, or "" for none.
std::string attributeWithPercent(const TiXmlElement* e) {
  for (; e; e = e->NextSiblingElement()) {
    for (const TiXmlAttribute* a = e->FirstAttribute(); a; a = a->Next())
      if (std::strchr(a->Value(), '%') && std::strcmp(a->Name(), "filename") != 0)
        return std::string(e->Value()) + " " + a->Name();
    if (std::string inner = attributeWithPercent(e->FirstChildElement()); !inner.empty()) return inner;
  }
  return {};
}

// What urdfdom must not be given, or "" for none. The document is read with TinyXML 1, urdfdom's own parser, as
// urdfdom reads it (up to the first NUL): TinyXML 1 accepts damaged XML that tinyxml2 rejects, so a stricter
// parser here let a cycle through (found by fuzz_urdf). One parse serves both checks.
std::string preParseProblem(const std::string& xml) {
  TiXmlDocument doc;
  doc.Parse(xml.c_str());
  if (doc.Error()) return {};  // urdfdom fails on the same error before building any link or reading an attribute
  if (const std::string problem = jointGraphProblem(doc); !problem.empty())
    return "URDF " + problem + " (the kinematic graph must be a tree)";
  if (const std::string attribute = attributeWithPercent(doc.FirstChildElement()); !attribute.empty())
    return "URDF attribute '" + attribute +
           "' contains '%' (only mesh filenames may: urdfdom would use it as a printf format)";
  return {};
}

Status parseUrdfModel(const std::string& xml, ::urdf::ModelInterfaceSharedPtr& model) {
  if (const std::string problem = preParseProblem(xml); !problem.empty()) return Status::owned(StatusCode::ParseError, problem);
  std::lock_guard<std::mutex> lock(parserMutex());
  CapturedLog log;
  console_bridge::useOutputHandler(&log);
  std::string thrown;
  try {
    model = ::urdf::parseURDF(xml);
  } catch (const std::exception& e) {
    thrown = e.what();
  }
  console_bridge::restorePreviousOutputHandler();
  // urdfdom drops a <collision> it cannot parse (NaN or "abc" sizes, non-finite origins) and still returns a model:
  // the robot would silently lose a collision body, so any collision error fails the load.
  if (model && log.messages.find("collision") != std::string::npos) {
    model.reset();
    return Status::owned(StatusCode::ParseError, "malformed URDF: " + log.messages);
  }
  if (model) return {};
  std::string why = !thrown.empty() ? thrown : log.messages;
  return Status::owned(StatusCode::ParseError, "malformed URDF: " + (why.empty() ? std::string("urdfdom rejected the document") : why));
}

template <class T> Transform<T> toTransform(const ::urdf::Pose& p) {
  double x, y, z, w;
  p.rotation.getQuaternion(x, y, z, w);
  return Transform<T>(Vec3<T>(T(p.position.x), T(p.position.y), T(p.position.z)),
                      Quat<T>(Quat<double>(w, x, y, z).normalized().template cast<T>()));
}

bool endsWithDae(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".dae";
}

// Applies the URDF <mesh scale>: a mirrored scale reverses the winding to keep the outward orientation.
template <class T> void applyScale(const ::urdf::Vector3& s, MeshData<T>& mesh) {
  const Vec3<T> scale(T(s.x), T(s.y), T(s.z));
  for (auto& v : mesh.vertices) v = v.cwiseProduct(scale);
  if (scale.prod() < T(0))
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
}

template <class T>
Status meshElement(const ::urdf::Mesh& m, const std::string& baseDir, const LoadOptions& options,
                   internal::MeshParts<T>& parts) {
  std::string path;
  Status s = resolveMeshPath(m.filename, baseDir, options, path);
  if (!s.ok()) return s;
  MeshData<T> mesh;
  s = loadMeshFile(path, mesh, endsWithDae(path));  // ROS tools ignore the DAE root (up-axis) transform
  if (!s.ok()) return Status::owned(s.code, "mesh file '" + path + "': " + s.detailedMessage());
  applyScale(m.scale, mesh);
  s = internal::meshShapes(mesh, options.representation, options, parts);
  if (!s.ok()) return Status::owned(s.code, "mesh file '" + path + "': " + s.detailedMessage());
  for (auto& shape : parts.shapes) shape.file = path;
  return {};
}

// The shapes of one <collision>: one, or one per part of a mesh's convex decomposition.
template <class T>
Status collisionElement(const ::urdf::Collision& c, const std::string& linkName, const std::string& baseDir,
                        const LoadOptions& options, std::vector<Shape<T>>& shapes) {
  if (!c.geometry) return Status::owned(StatusCode::ParseError, "malformed URDF: a <collision> of link '" + linkName + "' has no geometry");
  internal::MeshParts<T> parts;
  parts.shapes.resize(1);
  parts.fits.resize(1);
  Shape<T>& shape = parts.shapes[0];
  Status s;
  const ::urdf::Geometry& g = *c.geometry;
  switch (g.type) {
    case ::urdf::Geometry::SPHERE: {
      const T r = T(static_cast<const ::urdf::Sphere&>(g).radius);
      shape.geometry = SphereGeometry<T>(r);
      shape.source = ShapeSource::Sphere;
      break;
    }
    case ::urdf::Geometry::BOX: {
      const auto& d = static_cast<const ::urdf::Box&>(g).dim;
      shape.geometry = BoxGeometry<T>(T(0.5 * d.x), T(0.5 * d.y), T(0.5 * d.z));
      shape.source = ShapeSource::Box;
      break;
    }
    case ::urdf::Geometry::CYLINDER: {
      const auto& cyl = static_cast<const ::urdf::Cylinder&>(g);
      s = internal::cylinderShape(T(cyl.radius), T(cyl.length), shape, parts.fits[0]);
      break;
    }
    case ::urdf::Geometry::MESH: s = meshElement(static_cast<const ::urdf::Mesh&>(g), baseDir, options, parts); break;
  }
  if (!s.ok()) return s;
  if (shape.source != ShapeSource::Mesh && shape.source != ShapeSource::Cylinder) {
    s = validateGeometry(shape.geometry);
    if (!s.ok()) return Status::owned(StatusCode::ParseError, "malformed URDF: link '" + linkName + "': " + s.detailedMessage());
    shape.bytes = sizeof(Geometry<T>);
  }
  for (std::size_t i = 0; i < parts.shapes.size(); ++i) {
    parts.shapes[i].origin = toTransform<T>(c.origin) * parts.fits[i];
    shapes.push_back(std::move(parts.shapes[i]));
  }
  return {};
}

template <class T> Status convertJoint(const ::urdf::Joint& uj, Joint<T>& j) {
  j.name = uj.name;
  j.origin = toTransform<T>(uj.parent_to_joint_origin_transform);
  switch (uj.type) {
    case ::urdf::Joint::REVOLUTE: j.type = JointType::Revolute; break;
    case ::urdf::Joint::CONTINUOUS: j.type = JointType::Continuous; break;
    case ::urdf::Joint::PRISMATIC: j.type = JointType::Prismatic; break;
    case ::urdf::Joint::FIXED: j.type = JointType::Fixed; break;
    default:
      return Status::owned(StatusCode::Unsupported, "joint '" + uj.name + "': only revolute, continuous, prismatic and fixed joints");
  }
  if (j.type == JointType::Fixed) return {};
  Vec3<double> axis(uj.axis.x, uj.axis.y, uj.axis.z);
  if (!(axis.norm() > 0)) return Status::owned(StatusCode::ParseError, "malformed URDF: joint '" + uj.name + "' has a zero axis");
  j.axis = axis.normalized().cast<T>();
  if (j.type == JointType::Continuous) {
    j.lower = T(-M_PI);
    j.upper = T(M_PI);
  } else {
    if (!uj.limits || !(uj.limits->lower <= uj.limits->upper))
      return Status::owned(StatusCode::ParseError, "malformed URDF: joint '" + uj.name + "' needs limits with lower <= upper");
    j.lower = T(uj.limits->lower);
    j.upper = T(uj.limits->upper);
  }
  return {};
}

// Mimic joints follow q = multiplier * q[driver] + offset; chains of mimics collapse onto the driving variable.
template <class T> Status resolveMimics(const ::urdf::ModelInterface& um, RobotModel<T>& model) {
  std::map<std::string, std::uint32_t> index;
  for (std::uint32_t i = 0; i < model.joints.size(); ++i) index[model.joints[i].name] = i;
  for (auto& j : model.joints) {
    const auto uj = um.getJoint(j.name);
    if (j.type == JointType::Fixed || !uj->mimic) continue;
    T mult = T(1), off = T(0);
    std::string driver = j.name;
    for (std::size_t hops = 0; um.getJoint(driver)->mimic; ++hops) {
      const auto& mimic = *um.getJoint(driver)->mimic;
      if (hops > model.joints.size() || !index.count(mimic.joint_name))
        return Status::owned(StatusCode::ParseError, "malformed URDF: joint '" + j.name + "' mimics an unknown joint or a mimic cycle");
      off = mult * T(mimic.offset) + off;
      mult = mult * T(mimic.multiplier);
      driver = mimic.joint_name;
    }
    j.mimicJoint = std::int32_t(index[driver]);
    j.multiplier = mult;
    j.offset = off;
  }
  for (auto& j : model.joints) {
    if (j.type == JointType::Fixed || j.mimicJoint >= 0) continue;
    j.variable = std::int32_t(model.variables.size());
    model.variables.push_back(j.name);
  }
  return {};
}

// Links breadth-first from the root, so every parent precedes its children; joints in the same order.
template <class T>
Status buildTree(const ::urdf::ModelInterface& um, const std::string& baseDir, const LoadOptions& options,
                 RobotModel<T>& model) {
  const auto root = um.getRoot();
  if (!root) return Status::parseError("malformed URDF: no root link");
  std::vector<::urdf::LinkConstSharedPtr> queue{root};
  std::map<std::string, std::uint32_t> placed;  // link name -> index
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const auto& ul = *queue[head];
    // The pre-check makes the graph a tree; should urdfdom still list a link twice, or before its parent, refuse it
    // rather than index link -1.
    const auto parent = head > 0 && ul.parent_joint ? placed.find(ul.parent_joint->parent_link_name) : placed.end();
    if (!placed.emplace(ul.name, std::uint32_t(head)).second || (head > 0 && parent == placed.end()))
      return Status::owned(StatusCode::ParseError, "malformed URDF: link '" + ul.name + "' is not reached exactly once from the root");
    Link<T> link;
    link.name = ul.name;
    for (const auto& c : ul.collision_array) {
      std::vector<Shape<T>> shapes;
      Status s = collisionElement(*c, ul.name, baseDir, options, shapes);
      if (!s.ok()) return s;
      for (auto& shape : shapes) {
        shape.link = std::uint32_t(head);
        link.shapes.push_back(std::uint32_t(model.shapes.size()));
        model.shapes.push_back(std::move(shape));
      }
    }
    if (head > 0) {
      const auto& uj = *ul.parent_joint;
      Joint<T> j;
      Status s = convertJoint(uj, j);
      if (!s.ok()) return s;
      j.parentLink = parent->second;
      j.childLink = std::uint32_t(head);
      link.parentJoint = std::int32_t(model.joints.size());
      model.joints.push_back(j);
    }
    model.links.push_back(std::move(link));
    for (const auto& child : ul.child_links) queue.push_back(child);
  }
  return resolveMimics(um, model);
}

template <class T>
Status loadImpl(const std::string& urdfXml, const std::string& srdfXml, const std::string& baseDir,
                const LoadOptions& options, RobotModel<T>& out) {
  ::urdf::ModelInterfaceSharedPtr um;
  Status s = parseUrdfModel(urdfXml, um);
  if (!s.ok()) return s;
  internal::SrdfData srdf;
  if (!srdfXml.empty()) {
    s = internal::parseSrdf(srdfXml, srdf);
    if (!s.ok()) return s;
  }
  RobotModel<T> model;
  model.name = um->getName();
  s = buildTree(*um, baseDir, options, model);
  if (!s.ok()) return s;
  std::string warnings;
  internal::computeAllowedCollisions(model, srdf, warnings);
  internal::chooseHomeConfiguration(model, srdf);
  out = std::move(model);
  return warnings.empty() ? Status() : Status::owned(StatusCode::Warning, warnings);
}

}  // namespace

template <class T> std::int32_t RobotModel<T>::findLink(const std::string& linkName) const {
  for (std::size_t i = 0; i < links.size(); ++i)
    if (links[i].name == linkName) return std::int32_t(i);
  return -1;
}

template <class T> std::size_t RobotModel<T>::memoryBytes() const {
  std::size_t bytes = sizeof(*this) + links.size() * sizeof(Link<T>) + joints.size() * sizeof(Joint<T>) +
                      allowed.size() + allowedReason.size() * sizeof(std::string);
  for (const auto& s : shapes) bytes += sizeof(Shape<T>) + s.bytes;
  return bytes;
}

template <class T>
Status loadRobotFromStrings(const std::string& urdfXml, const std::string& srdfXml, const std::string& baseDir,
                            const LoadOptions& options, RobotModel<T>& out) {
  try {
    return loadImpl(urdfXml, srdfXml, baseDir, options, out);
  } catch (const std::exception& e) {
    return Status::owned(StatusCode::InternalError, std::string("loading the robot: ") + e.what());
  }
}

template <class T>
Status loadRobot(const std::string& urdfPath, const std::string& srdfPath, const LoadOptions& options,
                 RobotModel<T>& out) {
  std::string urdf, srdf;
  Status s = readFile(urdfPath, "URDF", urdf);
  if (s.ok() && !srdfPath.empty()) s = readFile(srdfPath, "SRDF", srdf);
  if (!s.ok()) return s;
  const std::string baseDir = std::filesystem::path(urdfPath).parent_path().string();
  return loadRobotFromStrings(urdf, srdf, baseDir.empty() ? std::string(".") : baseDir, options, out);
}

template struct RobotModel<float>;
template struct RobotModel<double>;
template Status loadRobot<float>(const std::string&, const std::string&, const LoadOptions&, RobotModel<float>&);
template Status loadRobot<double>(const std::string&, const std::string&, const LoadOptions&, RobotModel<double>&);
template Status loadRobotFromStrings<float>(const std::string&, const std::string&, const std::string&,
                                            const LoadOptions&, RobotModel<float>&);
template Status loadRobotFromStrings<double>(const std::string&, const std::string&, const std::string&,
                                             const LoadOptions&, RobotModel<double>&);

}  // namespace gq::urdf
