// Contacts between a capsule, box, convex mesh or convex custom shape and one triangle (gq/contacts.h).
//
// 1. Closest features by GJK (separated) or EPA (overlapping): separation s and normal N from the triangle towards
//    the shape. Nothing is reported when s > contactDistance.
// 2. The face normal n (oriented towards the shape) explains the contact when the shape's separation from the
//    triangle's plane, s_f = n.(support(-n) - v0) - margin, is within meshContactMargin of s (always s_f <= s). Then
//    the manifold is built along n: core vertices of the shape whose projection falls inside the triangle (separation
//    n.(p - v0) - margin), triangle vertices under the shape (a ray from below the vertex along n enters the shape
//    at its lower surface), and the crossings of the shape's core edges with the triangle's edges seen along n (the
//    corners of the contact polygon where a face or an edge of the shape straddles the triangle's boundary).
//    Otherwise, or when no point lies under the face, the closest point alone, along N.
// 3. At most 4 points: the deepest, the one farthest from it, the one farthest from the line of those two, and the
//    one farthest from the three chosen (a spread-out, stable set).
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "common/validate.h"
#include "contacts/contact_features.h"
#include "gjk/gjk.h"
#include "gq/contacts.h"
#include "gq/query.h"
#include "sweep/sweep.h"

namespace gq {
namespace {

// Core vertices of the shape (world): box corners, capsule segment ends, hull vertices.
template <class T> void coreVertices(const detail::ConvexShape<T>& a, std::vector<Vec3<T>>& out) {
  using Kind = typename detail::ConvexShape<T>::Kind;
  out.clear();
  if (a.kind == Kind::Box) {
    for (int c = 0; c < 8; ++c)
      out.push_back(a.toWorld(Vec3<T>((c & 1) ? a.halfExtents.x() : -a.halfExtents.x(),
                                      (c & 2) ? a.halfExtents.y() : -a.halfExtents.y(),
                                      (c & 4) ? a.halfExtents.z() : -a.halfExtents.z())));
  } else if (a.kind == Kind::Segment) {
    out.push_back(a.toWorld(Vec3<T>(a.halfExtents.x(), T(0), T(0))));
    out.push_back(a.toWorld(Vec3<T>(-a.halfExtents.x(), T(0), T(0))));
  } else if (a.kind == Kind::Hull) {
    for (const Vec3<T>& v : a.hull->vertices) out.push_back(a.toWorld(a.hullScaled ? Vec3<T>(a.hullScale * v) : v));
  }
}

// Core edges of the shape (index pairs into coreVertices): the box's 12, the capsule's segment, every hull polygon
// edge once (each appears in two polygons, once in each direction).
template <class T> void coreEdges(const detail::ConvexShape<T>& a, std::vector<std::array<std::uint32_t, 2>>& out) {
  using Kind = typename detail::ConvexShape<T>::Kind;
  out.clear();
  if (a.kind == Kind::Box) {
    for (std::uint32_t c = 0; c < 8; ++c)
      for (std::uint32_t axis = 1; axis < 8; axis <<= 1)
        if (!(c & axis)) out.push_back({c, c | axis});
  } else if (a.kind == Kind::Segment) {
    out.push_back({0u, 1u});
  } else if (a.kind == Kind::Hull) {
    for (const HullPolygon<T>& poly : a.hull->polygons)
      for (std::uint32_t k = 0; k < poly.indexCount; ++k) {
        const std::uint32_t u = a.hull->polygonVertices[poly.indexBase + k];
        const std::uint32_t v = a.hull->polygonVertices[poly.indexBase + (k + 1) % poly.indexCount];
        if (u < v) out.push_back({u, v});
      }
  }
}

// Crossings, seen along n, of the core edge p-q with the triangle's edges: the point of p-q above each crossing.
// Solves p + s (q - p) = a + t (b - a) in the plane orthogonal to n (2D cross products taken along n).
template <class T>
void addEdgeCrossings(const Triangle<T>& tri, const Vec3<T>& n, const Vec3<T>& p, const Vec3<T>& q,
                      std::vector<Vec3<T>>& out) {
  const Vec3<T> e = q - p;
  for (int k = 0; k < 3; ++k) {
    const Vec3<T>& a = tri.verts[k];
    const Vec3<T> f = tri.verts[(k + 1) % 3] - a;
    const T den = n.dot(e.cross(f));
    // Parallel in projection (or an edge along n): no single crossing.
    if (!(std::abs(den) > T(tol::Rel<T>::kEpsilon) * e.norm() * f.norm())) continue;
    const Vec3<T> r = a - p;
    const T s = n.dot(r.cross(f)) / den, t = n.dot(r.cross(e)) / den;
    if (s >= T(0) && s <= T(1) && t >= T(0) && t <= T(1)) out.push_back(Vec3<T>(p + s * e));
  }
}

// The triangle's edges seen along n: unit inward normals in its plane (into the triangle for counter-clockwise about
// n), taken once a call (per tested point they were three square roots and divisions each).
template <class T> struct EdgeNormals {
  std::array<Vec3<T>, 3> inward;
  EdgeNormals(const Triangle<T>& tri, const Vec3<T>& n) {
    for (int k = 0; k < 3; ++k) inward[k] = n.cross(tri.verts[(k + 1) % 3] - tri.verts[k]).normalized();
  }
};

// Whether p projects (along the triangle's normal) inside the triangle grown by `slack`.
template <class T> bool projectsInside(const Triangle<T>& tri, const EdgeNormals<T>& edges, const Vec3<T>& p, T slack) {
  for (int k = 0; k < 3; ++k)
    if (edges.inward[k].dot(p - tri.verts[k]) < -slack) return false;
  return true;
}

template <class T> struct Candidate {
  Vec3<T> position;
  T separation;
};

// Keeps at most kMaxTriangleContacts spread-out points of `c` (sorted in place), the deepest first; returns how many.
template <class T>
std::size_t reduceContacts(std::vector<Candidate<T>>& c, T mergeDistance,
                           std::array<Candidate<T>, kMaxTriangleContacts>& kept) {
  if (c.empty()) return 0;
  std::sort(c.begin(), c.end(), [](const Candidate<T>& x, const Candidate<T>& y) { return x.separation < y.separation; });
  std::size_t count = 0;
  kept[count++] = c.front();
  // Each next point maximises its distance to the set kept so far (distance to the nearest kept point).
  while (count < kMaxTriangleContacts) {
    T best = mergeDistance;
    int pick = -1;
    for (std::size_t i = 0; i < c.size(); ++i) {
      T nearest = std::numeric_limits<T>::max();
      for (std::size_t k = 0; k < count; ++k) nearest = std::min(nearest, (c[i].position - kept[k].position).norm());
      if (nearest > best) { best = nearest; pick = int(i); }
    }
    if (pick < 0) break;
    kept[count++] = c[std::size_t(pick)];
  }
  return count;
}

// The candidate lists, kept per thread between calls: allocated per call (seven vectors and their growth), they
// were ~40 % of a call's instructions in the Bullet adapter's heightfield scene.
template <class T> struct ContactScratch {
  std::vector<Candidate<T>> candidates, face;
  std::vector<Vec3<T>> vertices, points;
  std::vector<std::array<std::uint32_t, 2>> edges;
};
template <class T> ContactScratch<T>& contactScratch() {
  thread_local ContactScratch<T> scratch;
  return scratch;
}

// A custom shape's surface has no vertices or edges to test: when its closest-feature normal is along the triangle's
// face and a flat feature of it (a cylinder's cap or side) rests there, that feature clipped to the triangle, along the
// face normal (a standing cylinder would otherwise get one point per call and rock); otherwise the closest point.
template <class T>
void customShapeContacts(const Geometry<T>& geom, const Transform<T>& pose, const Triangle<T>& triangle,
                         std::uint32_t triangleIndex, T separation, const Vec3<T>& normal, const Vec3<T>& closest,
                         T contactDistance, ContactBuffer<T>& contacts) {
  contacts = ContactBuffer<T>();
  const auto add = [&](const Vec3<T>& p, const Vec3<T>& n, T s) {
    if (s > contactDistance || contacts.count == kMaxTriangleContacts) return;
    contacts.contacts[contacts.count++] = ContactPoint<T>{p, n, s, triangleIndex};
  };
  Vec3<T> n = triangle.normal();
  if (n.dot(normal) < T(0)) n = -n;  // two-sided: the side facing the shape
  detail::Feature<T> reference, incident;
  if (n.dot(normal) >= T(detail::kFaceAlignmentCos) && detail::incidentFeature(geom, pose, Vec3<T>(-n), incident)) {
    reference.count = 3;
    for (int i = 0; i < 3; ++i) reference.points[i] = triangle.verts[i];
    reference.normal = n;
    reference.origin = triangle.verts[0];
    detail::clipToFace(reference, incident);
    for (int i = 0; i < incident.count; ++i) add(incident.points[i], n, n.dot(incident.points[i] - triangle.verts[0]));
    if (incident.count > 0) return;
  }
  add(closest, normal, separation);
}

template <class T>
Status validateContacts(const Geometry<T>& geom, const Transform<T>& pose, const Triangle<T>& tri, T contactDistance,
                        T meshContactMargin, T toleranceLength) {
  // Shape and triangle are a pair query's two geometries: sizes and offsets within kMaxMagnitude (a float triangle
  // 4e28 from the shape gave contact positions of -inf: fuzz_mesh_queries).
  if (const detail::Problem p = detail::pairGeometryProblem(geom)) return p.status();
  if (Status s = detail::checkPose(pose, detail::kPoseField); !s.ok()) return s;
  const GeometryType t = geom.type();
  const auto* custom = geom.template getIf<CustomGeometry<T>>();
  if (t != GeometryType::Capsule && t != GeometryType::Box && t != GeometryType::ConvexMesh &&
      !(custom && custom->callbacks->isConvex()))
    return Status::unsupported("generateTriangleContacts takes a capsule, box, convex mesh or convex custom shape")
        .withType(t);
  if (const char* problem = detail::rawTriangleProblem(tri, pose)) return Status::invalid(problem);
  if (!(std::isfinite(contactDistance) && contactDistance >= T(0))) return Status::invalid("contactDistance must be finite and >= 0");
  if (!(std::isfinite(meshContactMargin) && meshContactMargin >= T(0))) return Status::invalid("meshContactMargin must be finite and >= 0");
  if (!(std::isfinite(toleranceLength) && toleranceLength > T(0))) return Status::invalid("toleranceLength must be finite and > 0");
  const Vec3<T> n = (tri.verts[1] - tri.verts[0]).cross(tri.verts[2] - tri.verts[0]);
  if (!(n.norm() > T(0))) return Status::invalid("the triangle is degenerate (zero area)");
  return {};
}

}  // namespace

template <class T>
Status generateTriangleContacts(const Geometry<T>& geom, const Transform<T>& pose, const Triangle<T>& triangle,
                                std::uint32_t triangleIndex, ContactBuffer<T>& contacts,
                                const TriangleContactSettings<T>& settings) noexcept {
  return detail::guarded([&]() -> Status {
    const T contactDistance = settings.contactDistance;
    const T meshContactMargin = settings.meshContactMargin;
    const T toleranceLength = settings.toleranceLength;
    if (Status s = validateContacts(geom, pose, triangle, contactDistance, meshContactMargin, toleranceLength); !s.ok())
      return s;
    const detail::ConvexShape<T> a = detail::makeConvexShape(geom, pose);
    const detail::TriangleSupport<T> support(triangle);
    const detail::ConvexShape<T> b = support.shape();

    // 1. Closest features: separation and normal from the triangle towards the shape.
    T separation;
    Vec3<T> normal, closest;
    const detail::GjkResult<T> g = detail::gjkDistance(a, b);
    if (!g.coresOverlap) {
      separation = g.distance;
      normal = -g.normal;
      closest = g.point0;
    } else {
      const detail::EpaResult<T> e = detail::epaPenetration(a, b, &g.simplex);
      if (!isFinite(e.normal) || !std::isfinite(e.depth)) return Status(StatusCode::NotConverged, "EPA did not converge");
      separation = -e.depth;
      normal = -e.normal;
      closest = e.point0;
    }
    if (geom.type() == GeometryType::Custom) {
      customShapeContacts(geom, pose, triangle, triangleIndex, separation, normal, closest, contactDistance, contacts);
      return Status();
    }
    ContactScratch<T>& scratch = contactScratch<T>();
    std::vector<Candidate<T>>& candidates = scratch.candidates;
    candidates.clear();
    if (separation <= contactDistance) candidates.push_back({closest, separation});

    // 2. Face normal, oriented towards the shape.
    Vec3<T> n = triangle.normal();
    if (n.dot(a.center() - triangle.verts[0]) < T(0)) n = -n;
    const Vec3<T> lowest = a.support(-n) - a.margin * n;
    const T faceSeparation = n.dot(lowest - triangle.verts[0]);
    const T slack = T(tol::kContactMergeFactor) * toleranceLength;
    if (separation - faceSeparation <= meshContactMargin) {
      const EdgeNormals<T> edges(triangle, n);
      std::vector<Candidate<T>>& face = scratch.face;
      face.clear();
      if (faceSeparation <= contactDistance && projectsInside(triangle, edges, lowest, slack))
        face.push_back({lowest, faceSeparation});
      std::vector<Vec3<T>>& vertices = scratch.vertices;
      coreVertices(a, vertices);
      std::vector<Vec3<T>>& points = scratch.points;  // core points to test: vertices over the triangle, edge crossings
      points.clear();
      for (const Vec3<T>& p : vertices)
        if (projectsInside(triangle, edges, p, slack)) points.push_back(p);
      coreEdges(a, scratch.edges);
      for (const auto& edge : scratch.edges) addEdgeCrossings(triangle, n, vertices[edge[0]], vertices[edge[1]], points);
      for (const Vec3<T>& p : points) {
        const T s = n.dot(p - triangle.verts[0]) - a.margin;
        if (s <= contactDistance) face.push_back({Vec3<T>(p - a.margin * n), s});
      }
      // Triangle vertices under the shape: a ray from below the vertex along n enters the shape's lower surface.
      const T below = T(2) * a.size + std::abs(faceSeparation) + contactDistance;
      for (const Vec3<T>& v : triangle.verts) {
        RaycastHit<T> hit;
        std::uint32_t count = 0;
        if (!raycast(Vec3<T>(v - below * n), n, geom, pose, T(2) * below, HitFlags(HitFlag::Position), 1u, &hit, count).ok() ||
            count == 0)
          continue;
        const T s = hit.distance - below;
        if (s <= contactDistance) face.push_back({hit.position, s});
      }
      // Nothing under the face (the shape is beside the triangle): keep the closest point and its normal.
      if (!face.empty()) {
        normal = n;
        candidates.assign(face.begin(), face.end());  // copied, not swapped: each buffer keeps its capacity
      }
    }
    std::array<Candidate<T>, kMaxTriangleContacts> kept;
    const std::size_t keptCount = reduceContacts(candidates, slack, kept);
    contacts = ContactBuffer<T>();
    for (std::size_t k = 0; k < keptCount; ++k) {
      const Candidate<T>& c = kept[k];
      ContactPoint<T>& out = contacts.contacts[contacts.count++];
      out.position = c.position;
      out.normal = normal;
      out.separation = c.separation;
      out.triangleIndex = triangleIndex;
    }
    return Status();
  });
}

template Status generateTriangleContacts<float>(const Geometry<float>&, const Transform<float>&, const Triangle<float>&,
                                                std::uint32_t, ContactBuffer<float>&,
                                                const TriangleContactSettings<float>&);
template Status generateTriangleContacts<double>(const Geometry<double>&, const Transform<double>&,
                                                 const Triangle<double>&, std::uint32_t,
                                                 ContactBuffer<double>&, const TriangleContactSettings<double>&);

}  // namespace gq
