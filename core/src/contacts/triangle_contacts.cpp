// Contacts between a capsule, box, convex mesh or convex custom shape and one triangle (gq/contacts.h).
//
// 0. Culls without exact work: the shape's lowest point along the face normal n (towards the shape) farther than
//    contactDistance above the triangle's plane, or every core vertex farther than contactDistance + margin beyond
//    one of the triangle's edge lines (seen along n), bounds the distance from below: nothing is reported.
// 1. Closest features by GJK (separated) or EPA (overlapping): separation s and normal N from the triangle towards
//    the shape. Nothing is reported when s > contactDistance (GJK stops once it has certified that).
// 2. The face normal n explains the contact when the shape's separation from the triangle's plane,
//    s_f = n.(support(-n) - v0) - margin, is within meshContactMargin of s (always s_f <= s). Then the manifold is
//    built along n: core vertices of the shape whose projection falls inside the triangle (separation
//    n.(p - v0) - margin), triangle vertices under the shape (a ray from below the vertex along n enters the shape
//    at its lower surface), and the crossings of the shape's core edges with the triangle's edges seen along n (the
//    corners of the contact polygon where a face or an edge of the shape straddles the triangle's boundary).
//    Otherwise, or when no point lies under the face, the closest point alone, along N. These face points are
//    found before step 1: when one of them proves the test (a surface point over the triangle at height h >= 0
//    bounds s by h; one below the plane whose segment to the shape's centre crosses the plane inside the triangle
//    shows that the shape meets the triangle, s <= 0), step 1 is skipped, its answer being replaced anyway. Step 1
//    is also skipped, for every shape kind, when the shape's lowest point along n lies over the triangle at s_f >= 0:
//    that point is then the closest one (s = s_f, along n). When step 1 certifies s > contactDistance, no point is
//    reported, face points within the merge slack of an edge included. A core
//    point's separation is linear along a core edge, so edges whose two ends are beyond contactDistance are
//    skipped; a triangle vertex casts its ray only when the shape's shadow along n reaches both edge lines through
//    it and the vertex lies within the shape's bounding radius of the line through its origin along n.
// 3. At most 4 points: the deepest, the one farthest from it, the one farthest from the line of those two, and the
//    one farthest from the three chosen (a spread-out, stable set).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
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

// Calls f(u, v) for each core edge of the shape (index pairs into coreVertices): the box's 12, the capsule's
// segment, every hull polygon edge once (each appears in two polygons, once in each direction).
template <class T, class F> void forEachCoreEdge(const detail::ConvexShape<T>& a, F&& f) {
  using Kind = typename detail::ConvexShape<T>::Kind;
  if (a.kind == Kind::Box) {
    for (std::uint32_t c = 0; c < 8; ++c)
      for (std::uint32_t axis = 1; axis < 8; axis <<= 1)
        if (!(c & axis)) f(c, c | axis);
  } else if (a.kind == Kind::Segment) {
    f(0u, 1u);
  } else if (a.kind == Kind::Hull) {
    const std::vector<std::uint32_t>& index = a.hull->polygonVertices;
    for (const HullPolygon<T>& poly : a.hull->polygons)
      for (std::uint32_t k = 0; k < poly.indexCount; ++k) {
        const std::uint32_t u = index[poly.indexBase + k];
        const std::uint32_t v = index[poly.indexBase + (k + 1 == poly.indexCount ? 0 : k + 1)];
        if (u < v) f(u, v);
      }
  }
}

// The triangle's edges seen along n: unit inward normals in its plane (into the triangle whichever side n is on:
// the triangle is two-sided), the edge vectors and their inverse squared lengths, taken once a call.
template <class T> struct EdgeNormals {
  std::array<Vec3<T>, 3> inward, edge;
  std::array<T, 3> invLength2;
  EdgeNormals(const Triangle<T>& tri, const Vec3<T>& n) {
    const Vec3<T> winding = (tri.verts[1] - tri.verts[0]).cross(tri.verts[2] - tri.verts[0]);
    const T side = winding.dot(n) < T(0) ? T(-1) : T(1);  // counter-clockwise about n: n x edge points inwards
    for (int k = 0; k < 3; ++k) {
      edge[k] = tri.verts[(k + 1) % 3] - tri.verts[k];
      inward[k] = (side * n.cross(edge[k])).normalized();
      invLength2[k] = T(1) / edge[k].squaredNorm();
    }
  }
  // Signed distance of p's projection inside edge k's line (> 0 on the triangle's side).
  T inside(const Triangle<T>& tri, int k, const Vec3<T>& p) const { return inward[k].dot(p - tri.verts[k]); }
};

// Whether p projects (along the triangle's normal) inside the triangle grown by `slack`.
template <class T> bool projectsInside(const Triangle<T>& tri, const EdgeNormals<T>& edges, const Vec3<T>& p, T slack) {
  for (int k = 0; k < 3; ++k)
    if (edges.inside(tri, k, p) < -slack) return false;
  return true;
}

// Each core vertex's signed distances inside the triangle's three edge lines, seen along n.
template <class T> using EdgeDistances = std::array<T, 3>;

// Crossings, seen along n, of the core edge p-q with the triangle's edges: the point of p-q above each crossing.
// p and q lie on opposite sides of edge k's line (signed distances dp, dq); the crossing p + s (q - p) with
// s = dp / (dp - dq) counts when it falls within the edge (its parameter along the edge in [0, 1]).
template <class T>
void addEdgeCrossings(const Triangle<T>& tri, const EdgeNormals<T>& edges, const Vec3<T>& p, const Vec3<T>& q,
                      const EdgeDistances<T>& dp, const EdgeDistances<T>& dq, std::vector<Vec3<T>>& out) {
  for (int k = 0; k < 3; ++k) {
    if ((dp[k] > T(0) && dq[k] > T(0)) || (dp[k] < T(0) && dq[k] < T(0)) || dp[k] == dq[k]) continue;
    const Vec3<T> x = p + (dp[k] / (dp[k] - dq[k])) * (q - p);
    const T t = edges.edge[k].dot(x - tri.verts[k]) * edges.invLength2[k];
    if (t >= T(0) && t <= T(1)) out.push_back(x);
  }
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
  // Each next point maximises its distance to the set kept so far (distance to the nearest kept point; squared
  // distances compare the same).
  while (count < kMaxTriangleContacts) {
    T best = mergeDistance * mergeDistance;
    int pick = -1;
    for (std::size_t i = 0; i < c.size(); ++i) {
      T nearest = std::numeric_limits<T>::max();
      for (std::size_t k = 0; k < count; ++k)
        nearest = std::min(nearest, (c[i].position - kept[k].position).squaredNorm());
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
  std::vector<T> heights;  // each core vertex's separation from the triangle's plane, along n
  std::vector<EdgeDistances<T>> inside;  // each core vertex's distances inside the triangle's edge lines
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

// The shape's core vertices seen from the triangle (world positions, heights of their surface points above the
// plane along n, signed distances inside the three edge lines).
template <class T> struct CoreView {
  std::vector<Vec3<T>>& vertices;
  std::vector<T>& heights;
  std::vector<EdgeDistances<T>>& inside;
  // The range of the vertices' distances inside each edge line (the core's shadow spans it).
  EdgeDistances<T> least, most;
  // Whether the shape's shadow along n (its core's, grown by `margin`) reaches edge k's line.
  bool reachesLine(int k, T margin) const { return least[k] <= margin && most[k] >= -margin; }
};

template <class T>
CoreView<T> viewCore(const detail::ConvexShape<T>& a, const Triangle<T>& triangle, const Vec3<T>& n,
                     const EdgeNormals<T>& edges, ContactScratch<T>& scratch) {
  const T inf = std::numeric_limits<T>::infinity();
  CoreView<T> core{scratch.vertices, scratch.heights, scratch.inside, {inf, inf, inf}, {-inf, -inf, -inf}};
  coreVertices(a, core.vertices);
  core.heights.resize(core.vertices.size());
  core.inside.resize(core.vertices.size());
  const T base = n.dot(triangle.verts[0]) + a.margin;
  for (std::size_t i = 0; i < core.vertices.size(); ++i) {
    core.heights[i] = n.dot(core.vertices[i]) - base;
    for (int k = 0; k < 3; ++k) {
      const T d = edges.inside(triangle, k, core.vertices[i]);
      core.inside[i][k] = d;
      core.least[k] = std::min(core.least[k], d);
      core.most[k] = std::max(core.most[k], d);
    }
  }
  return core;
}

// Whether the whole shape lies beyond one of the triangle's edge lines by more than `reach` (its core vertices span
// it: box, segment, hull), so no point of it is within contactDistance of the triangle.
template <class T> bool beyondAnEdge(const CoreView<T>& core, T reach) {
  if (core.vertices.empty()) return false;
  return core.most[0] < -reach || core.most[1] < -reach || core.most[2] < -reach;
}

// The points of the shape under the triangle's face along n (step 2), into scratch.face: the lowest point, core
// vertices over the triangle, crossings of core edges with the triangle's edges, triangle vertices under the shape.
template <class T>
void facePoints(const Geometry<T>& geom, const Transform<T>& pose, const detail::ConvexShape<T>& a,
                const Triangle<T>& triangle, const Vec3<T>& n, const EdgeNormals<T>& edges, const CoreView<T>& core,
                const Vec3<T>& lowest, T faceSeparation, T contactDistance, T slack, ContactScratch<T>& scratch) {
  std::vector<Candidate<T>>& face = scratch.face;
  face.clear();
  if (faceSeparation <= contactDistance && projectsInside(triangle, edges, lowest, slack))
    face.push_back({lowest, faceSeparation});
  std::vector<Vec3<T>>& points = scratch.points;  // core points to test: vertices over the triangle, edge crossings
  points.clear();
  for (std::size_t i = 0; i < core.vertices.size(); ++i) {
    const EdgeDistances<T>& d = core.inside[i];
    if (core.heights[i] <= contactDistance && d[0] >= -slack && d[1] >= -slack && d[2] >= -slack)
      points.push_back(core.vertices[i]);
  }
  forEachCoreEdge(a, [&](std::uint32_t u, std::uint32_t v) {
    if (std::min(core.heights[u], core.heights[v]) <= contactDistance)
      addEdgeCrossings(triangle, edges, core.vertices[u], core.vertices[v], core.inside[u], core.inside[v], points);
  });
  for (const Vec3<T>& p : points) {
    const T s = n.dot(p - triangle.verts[0]) - a.margin;
    if (s <= contactDistance) face.push_back({Vec3<T>(p - a.margin * n), s});
  }
  // Triangle vertices under the shape: a ray from below the vertex along n enters the shape's lower surface. The
  // ray misses when the shape's shadow along n misses one of the two edge lines through the vertex, or when the
  // vertex is farther from the line through the shape's origin along n than its bounding radius.
  const T below = T(2) * a.size + std::abs(faceSeparation) + contactDistance;
  const T reach = a.size + a.margin;
  for (int k = 0; k < 3; ++k) {
    if (!core.reachesLine(k, a.margin) || !core.reachesLine((k + 2) % 3, a.margin)) continue;
    const Vec3<T>& v = triangle.verts[k];
    const Vec3<T> offset = v - a.position;
    if ((offset - n.dot(offset) * n).squaredNorm() > reach * reach) continue;
    RaycastHit<T> hit;
    std::uint32_t count = 0;
    if (!raycast(Vec3<T>(v - below * n), n, geom, pose, T(2) * below, HitFlags(HitFlag::Position), 1u, &hit, count).ok() ||
        count == 0)
      continue;
    const T s = hit.distance - below;
    if (s <= contactDistance) face.push_back({hit.position, s});
  }
}

// Whether the face points prove step 2's test (separation - faceSeparation <= meshContactMargin) without GJK: a
// point F of the shape's surface over the triangle (inside its edges) at height s >= 0 bounds the separation by s;
// one below the plane whose segment to the shape's centre crosses the plane inside the triangle shows that the
// shape meets the triangle (separation <= 0).
template <class T>
bool faceProven(const std::vector<Candidate<T>>& face, const Triangle<T>& tri, const EdgeNormals<T>& edges,
                const Vec3<T>& n, const Vec3<T>& center, T faceSeparation, T meshContactMargin) {
  const T hc = n.dot(center - tri.verts[0]);  // >= 0: n is oriented towards the centre
  for (const Candidate<T>& f : face) {
    if (!projectsInside(tri, edges, f.position, T(0))) continue;
    if (f.separation >= T(0)) {
      if (f.separation - faceSeparation <= meshContactMargin) return true;
      continue;
    }
    if (-faceSeparation > meshContactMargin) return false;
    const Vec3<T> crossing = f.position + (f.separation / (f.separation - hc)) * (center - f.position);
    if (projectsInside(tri, edges, crossing, T(0))) return true;
  }
  return false;
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

    // 0. Face normal, oriented towards the shape; the plane cull.
    Vec3<T> n = triangle.normal();
    const Vec3<T> center = a.center();
    if (n.dot(center - triangle.verts[0]) < T(0)) n = -n;
    const Vec3<T> lowest = a.support(-n) - a.margin * n;
    const T faceSeparation = n.dot(lowest - triangle.verts[0]);
    if (faceSeparation > contactDistance) {
      contacts = ContactBuffer<T>();
      return Status();
    }
    const EdgeNormals<T> edges(triangle, n);
    ContactScratch<T>& scratch = contactScratch<T>();
    const bool custom = geom.type() == GeometryType::Custom;
    const T slack = T(tol::kContactMergeFactor) * toleranceLength;
    std::vector<Candidate<T>>& face = scratch.face;
    face.clear();
    if (!custom) {
      const CoreView<T> core = viewCore(a, triangle, n, edges, scratch);
      if (beyondAnEdge(core, contactDistance + a.margin)) {
        contacts = ContactBuffer<T>();
        return Status();
      }
      facePoints(geom, pose, a, triangle, n, edges, core, lowest, faceSeparation, contactDistance, slack, scratch);
    }
    // The closest point of the shape to the plane lies over the triangle: it is the closest point to the triangle.
    const bool exact = faceSeparation >= T(0) && projectsInside(triangle, edges, lowest, T(0));
    const bool proven = !face.empty() && (exact || faceProven(face, triangle, edges, n, center, faceSeparation,
                                                               meshContactMargin));

    // 1. Closest features: separation and normal from the triangle towards the shape (not needed when the face is
    // proven to explain the contact: its points replace the closest one).
    T separation = faceSeparation;
    Vec3<T> normal = n, closest = lowest;
    if (!exact && !proven) {
      const detail::TriangleSupport<T> support(triangle);
      const detail::ConvexShape<T> b = support.shape();
      const detail::GjkResult<T> g = detail::gjkDistance(a, b, static_cast<GjkCache<T>*>(nullptr), T(0),
                                                         static_cast<const Vec3<T>*>(nullptr), contactDistance);
      if (g.beyond) {
        contacts = ContactBuffer<T>();
        return Status();
      }
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
    }
    if (custom) {
      customShapeContacts(geom, pose, triangle, triangleIndex, separation, normal, closest, contactDistance, contacts);
      return Status();
    }
    std::vector<Candidate<T>>& candidates = scratch.candidates;
    candidates.clear();
    if (separation <= contactDistance) candidates.push_back({closest, separation});

    // 2. The face normal explains the contact: the points under the face replace the closest one.
    if (!face.empty() && (proven || separation - faceSeparation <= meshContactMargin)) {
      normal = n;
      candidates.assign(face.begin(), face.end());  // copied, not swapped: each buffer keeps its capacity
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
