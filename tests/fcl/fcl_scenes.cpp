#include "fcl_scenes.h"

#include <cmath>

namespace gq::fcltest {

const char* name(Kind k) {
  static const char* names[] = {"Sphere", "Box", "Capsule", "Cylinder", "Cone", "Ellipsoid",
                                "Convex", "TriangleP", "Halfspace", "Plane", "Mesh"};
  return names[int(k)];
}

std::vector<Kind> allKinds() {
  return {Kind::Sphere, Kind::Box, Kind::Capsule, Kind::Cylinder, Kind::Cone, Kind::Ellipsoid,
          Kind::Convex, Kind::TriangleP, Kind::Halfspace, Kind::Plane, Kind::Mesh};
}

bool isPlaneLike(Kind k) { return k == Kind::Halfspace || k == Kind::Plane; }

std::vector<std::pair<Kind, Kind>> allPairs() {
  std::vector<std::pair<Kind, Kind>> pairs;
  const auto kinds = allKinds();
  for (std::size_t i = 0; i < kinds.size(); ++i)
    for (std::size_t j = i; j < kinds.size(); ++j)
      if (!(isPlaneLike(kinds[i]) && isPlaneLike(kinds[j]))) pairs.emplace_back(kinds[i], kinds[j]);
  return pairs;
}

namespace {

// Three draws in a fixed order. Arguments of one call are evaluated in an unspecified order (GCC right to left,
// clang left to right), so drawing inside a constructor's arguments tests different cases per compiler.
template <class Distribution> ::fcl::Vector3d draw3(Distribution& d, std::mt19937& rng) {
  const double x = d(rng);
  const double y = d(rng);
  const double z = d(rng);
  return {x, y, z};
}

}  // namespace

::fcl::Transform3d randomPose(std::mt19937& rng, double extent) {
  std::normal_distribution<double> g(0, 1);
  std::uniform_real_distribution<double> u(-extent, extent);
  const double w = g(rng);
  const ::fcl::Vector3d xyz = draw3(g, rng);
  ::fcl::Transform3d tf = ::fcl::Transform3d::Identity();
  tf.linear() = Eigen::Quaterniond(w, xyz.x(), xyz.y(), xyz.z()).normalized().toRotationMatrix();
  tf.translation() = draw3(u, rng);
  return tf;
}

namespace {

// An irregular octahedron: one vertex on each half-axis, faces = the 8 octant triangles (CCW from outside).
void octahedron(std::mt19937& rng, std::vector<::fcl::Vector3d>& v, std::vector<std::vector<int>>& f) {
  std::uniform_real_distribution<double> u(0.35, 0.8);
  v = {{u(rng), 0, 0}, {-u(rng), 0, 0}, {0, u(rng), 0}, {0, -u(rng), 0}, {0, 0, u(rng)}, {0, 0, -u(rng)}};
  f = octahedronFaces(v);
}

// A closed latitude-longitude sphere of radius r (rings x segments), CCW from outside.
void uvSphere(double r, int rings, int segments, std::vector<::fcl::Vector3d>& v, std::vector<std::vector<int>>& f) {
  v = {{0, 0, r}};
  for (int i = 1; i < rings; ++i) {
    const double th = M_PI * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double ph = 2 * M_PI * j / segments;
      v.emplace_back(r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th));
    }
  }
  v.emplace_back(0, 0, -r);
  const int south = int(v.size()) - 1;
  const auto at = [&](int ring, int seg) { return 1 + (ring - 1) * segments + (seg % segments); };
  f.clear();
  for (int j = 0; j < segments; ++j) f.push_back({0, at(1, j), at(1, j + 1)});
  for (int i = 1; i + 1 < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      f.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      f.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  for (int j = 0; j < segments; ++j) f.push_back({south, at(rings - 1, j + 1), at(rings - 1, j)});
}

}  // namespace

void randomHull(std::mt19937& rng, int, std::vector<::fcl::Vector3d>& vertices, std::vector<std::vector<int>>& faces) {
  octahedron(rng, vertices, faces);
}

std::vector<std::vector<int>> octahedronFaces(const std::vector<::fcl::Vector3d>& v) {
  std::vector<std::vector<int>> f;
  for (int sx : {0, 1})
    for (int sy : {2, 3})
      for (int sz : {4, 5}) {
        std::vector<int> tri = {sx, sy, sz};
        const ::fcl::Vector3d n = (v[sy] - v[sx]).cross(v[sz] - v[sx]);
        if (n.dot(v[sx] + v[sy] + v[sz]) < 0) std::swap(tri[1], tri[2]);
        f.push_back(tri);
      }
  return f;
}

std::shared_ptr<::fcl::Convexd> convexGeometry(const std::vector<::fcl::Vector3d>& vertices,
                                               const std::vector<std::vector<int>>& faces) {
  auto faceList = std::make_shared<std::vector<int>>();
  for (const auto& f : faces) {
    faceList->push_back(int(f.size()));
    for (int i : f) faceList->push_back(i);
  }
  return std::make_shared<::fcl::Convexd>(std::make_shared<std::vector<::fcl::Vector3d>>(vertices), int(faces.size()),
                                          faceList);
}

TestShape makeShape(Kind k, std::mt19937& rng) {
  TestShape s;
  s.kind = k;
  std::uniform_real_distribution<double> u(0.3, 0.7);
  switch (k) {
    case Kind::Sphere:
      s.size = {u(rng), 0, 0};
      s.geometry = std::make_shared<::fcl::Sphered>(s.size.x());
      break;
    case Kind::Box: {
      s.size = {2 * u(rng), 2 * u(rng), 2 * u(rng)};
      s.geometry = std::make_shared<::fcl::Boxd>(s.size);
      const ::fcl::Vector3d h = s.size / 2;
      for (int i = 0; i < 8; ++i) s.vertices.emplace_back(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z());
      break;
    }
    case Kind::Capsule:
      s.size = {0.6 * u(rng), 2 * u(rng), 0};
      s.geometry = std::make_shared<::fcl::Capsuled>(s.size.x(), s.size.y());
      break;
    case Kind::Cylinder:
      s.size = {u(rng), 2 * u(rng), 0};
      s.geometry = std::make_shared<::fcl::Cylinderd>(s.size.x(), s.size.y());
      break;
    case Kind::Cone:
      s.size = {u(rng), 2 * u(rng), 0};
      s.geometry = std::make_shared<::fcl::Coned>(s.size.x(), s.size.y());
      break;
    case Kind::Ellipsoid:
      s.size = {u(rng), u(rng), u(rng)};
      s.geometry = std::make_shared<::fcl::Ellipsoidd>(s.size);
      break;
    case Kind::Convex:
      octahedron(rng, s.vertices, s.faces);
      s.geometry = convexGeometry(s.vertices, s.faces);
      break;
    case Kind::TriangleP: {
      std::uniform_real_distribution<double> c(-0.7, 0.7);
      for (int i = 0; i < 3; ++i) s.vertices.push_back(draw3(c, rng));
      s.faces = {{0, 1, 2}};
      s.geometry = std::make_shared<::fcl::TrianglePd>(s.vertices[0], s.vertices[1], s.vertices[2]);
      break;
    }
    case Kind::Halfspace:
    case Kind::Plane: {
      std::normal_distribution<double> g(0, 1);
      s.planeNormal = draw3(g, rng).normalized();
      s.planeOffset = 0.3 * g(rng);
      if (k == Kind::Halfspace) s.geometry = std::make_shared<::fcl::Halfspaced>(s.planeNormal, s.planeOffset);
      else s.geometry = std::make_shared<::fcl::Planed>(s.planeNormal, s.planeOffset);
      break;
    }
    case Kind::Mesh: {
      uvSphere(u(rng) + 0.2, 8, 12, s.vertices, s.faces);
      auto model = std::make_shared<::fcl::BVHModel<::fcl::OBBRSSd>>();
      model->beginModel();
      for (const auto& f : s.faces) model->addTriangle(s.vertices[f[0]], s.vertices[f[1]], s.vertices[f[2]]);
      model->endModel();
      s.geometry = model;
      break;
    }
  }
  s.geometry->computeLocalAABB();
  return s;
}

// Whether FCL 0.7 has a collide / distance function for the pair (it prints "not supported" and answers nothing
// otherwise: TriangleP against most shapes). FCL looks a shape-vs-BVHModel pair up with the BVHModel first.
namespace {
template <class Table> bool fclHas(const Table& table, const TestShape& a, const TestShape& b) {
  const auto ta = a.geometry->getNodeType(), tb = b.geometry->getNodeType();
  if (a.geometry->getObjectType() == ::fcl::OT_GEOM && b.geometry->getObjectType() == ::fcl::OT_BVH) return table[tb][ta] != nullptr;
  return table[ta][tb] != nullptr;
}
}  // namespace

// FCL 0.7's collide crashes the same way (libccd's MPR on a Plane: SIGSEGV in ccdMPRIntersect) for Convex-Plane and
// TriangleP against Halfspace/Plane: those are not asked either.
bool fclHasCollide(const TestShape& a, const TestShape& b) {
  const auto is = [&](Kind x, Kind y) { return (a.kind == x && b.kind == y) || (a.kind == y && b.kind == x); };
  if (is(Kind::Convex, Kind::Plane) || is(Kind::TriangleP, Kind::Plane) || is(Kind::TriangleP, Kind::Halfspace)) return false;
  return fclHas(::fcl::getCollisionFunctionLookTable<::fcl::detail::GJKSolver_libccdd>().collision_matrix, a, b);
}
// FCL 0.7's distance with a Halfspace or Plane has a table entry but crashes: libccd's GJK calls a null support
// function (observed: SIGSEGV in __ccdSupport), so those pairs are not asked.
bool fclHasDistance(const TestShape& a, const TestShape& b) {
  if (isPlaneLike(a.kind) || isPlaneLike(b.kind)) return false;
  return fclHas(::fcl::getDistanceFunctionLookTable<::fcl::detail::GJKSolver_libccdd>().distance_matrix, a, b);
}

}  // namespace gq::fcltest
