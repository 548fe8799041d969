// Convex shape against a triangle mesh or heightfield: the triangles under the shape's bounds (gq's midphase),
// then contacts per triangle (gq's generateTriangleContacts, which clips a cylinder's cap or side to the triangle).
// Triangles are two-sided, as Bullet's convex-triangle contacts are.
#include <algorithm>
#include <array>
#include <cmath>

#include "contacts.h"
#include "gq/contacts.h"
#include "gq/mesh_query.h"
#include "gq/query.h"

namespace gq::bullet {
namespace {

// Triangles come in pages of this many from the midphase.
constexpr std::uint32_t kTrianglePage = 64;
// generateTriangleContacts keeps the face normal when it is within this fraction of the shape size of the
// closest-feature separation (flat resting contacts stay flat).
constexpr Real kMeshContactMarginFactor = Real(0.05);

// A contact normal within this cosine of a triangle's face normal (~8 degrees) is a face contact.
constexpr Real kFaceAlignmentCos = Real(0.99);

// Internal edges: a shape resting on one triangle also reaches the edges of its neighbours, whose closest-feature
// normals tilt away from the surface and push the shape sideways (Bullet's "internal edge" artefact). Contacts are
// held until every triangle is done; when some triangle gives a face contact (normal along its face normal), edge
// or vertex contacts whose normal is not along a face contact's normal are dropped. Without a face contact (the
// shape over a real edge or corner of the surface) every contact stays.
class InternalEdgeFilter {
 public:
  static constexpr int kCapacity = 128;
  explicit InternalEdgeFilter(ContactSink& sink) : sink_(sink) {}
  void add(const V3& normalOnB, const V3& pointOnB, Real depth, TriangleIds ids, bool onFace) {
    if (count_ == kCapacity) {  // too many to hold: pass through unfiltered
      sink_.add(normalOnB, pointOnB, depth, ids, true);
      return;
    }
    held_[count_++] = {normalOnB, pointOnB, depth, ids, onFace};
  }
  // Hands the kept contacts to the sink in the form Bullet's manifold (4 points) keeps the deepest of:
  //  - deepest first: when full, the manifold never replaces its deepest cached point (sortCachedPoints);
  //  - of contacts closer than handOver.mergeRadius on the convex shape only the deepest: the manifold replaces its
  //    nearest cached point within that radius by each incoming one (getCacheEntry), so a later, shallower contact
  //    would overwrite a deeper one of the same call;
  //  - with handOver.touchingOnly, when some contact touches (depth <= 0), none still apart: a full manifold keeps
  //    its deepest point and otherwise the widest spread whatever the depth, so points up to the breaking threshold
  //    above the surface would take the places of the ones carrying the shape. Points cached while nothing touched
  //    stay cached.
  void flush(const HandOver& handOver) {
    std::array<int, kCapacity> order;
    int kept = 0;
    for (int i = 0; i < count_; ++i)
      if (keep(held_[i])) order[kept++] = i;
    std::sort(order.begin(), order.begin() + kept, [this](int i, int j) {
      return held_[i].depth < held_[j].depth || (held_[i].depth == held_[j].depth && i < j);
    });
    const bool touching = handOver.touchingOnly && kept > 0 && held_[order[0]].depth <= 0;
    const Real radius2 = handOver.mergeRadius * handOver.mergeRadius;
    int handed = 0;  // order[0, handed): the contacts handed over
    for (int k = 0; k < kept; ++k) {
      const Held& c = held_[order[k]];
      if (touching && c.depth > 0) break;  // the rest are apart too
      if (mergesIntoDeeper(c, order.data(), handed, radius2)) continue;
      sink_.add(c.normal, c.point, c.depth, c.ids, true);
      order[handed++] = order[k];
    }
    count_ = 0;
  }

 private:
  struct Held {
    V3 normal, point;
    Real depth;
    TriangleIds ids;
    bool onFace;
  };
  // The contact's point on the convex shape (Bullet's manifold compares points there).
  static V3 pointOnConvex(const Held& c) { return c.point + c.normal * c.depth; }
  // Whether one of the first `count` contacts of `order` lies within sqrt(radius2) of c on the convex shape.
  bool mergesIntoDeeper(const Held& c, const int* order, int count, Real radius2) const {
    const V3 p = pointOnConvex(c);
    for (int k = 0; k < count; ++k)
      if ((pointOnConvex(held_[order[k]]) - p).squaredNorm() < radius2) return true;
    return false;
  }
  bool keep(const Held& c) const {
    if (c.onFace) return true;
    bool anyFace = false;
    for (int i = 0; i < count_; ++i) {
      if (!held_[i].onFace) continue;
      anyFace = true;
      if (held_[i].normal.dot(c.normal) >= kFaceAlignmentCos) return true;
    }
    return !anyFace;
  }
  ContactSink& sink_;
  std::array<Held, kCapacity> held_;
  int count_ = 0;
};

struct SurfaceQuery {
  const PlacedShape& convex;
  const PlacedShape& surface;
  Real threshold;
  InternalEdgeFilter& sink;
};

// Whether a contact normal is the triangle's face normal (either side): a face contact, not an edge or vertex one.
bool alongFace(const V3& normal, const Triangle<Real>& tri) {
  return std::abs(normal.dot(tri.normal())) >= kFaceAlignmentCos;
}

bool getSurfaceTriangle(const PlacedShape& s, std::uint32_t index, Triangle<Real>& tri) {
  const Geometry<Real>& g = s.view->geom;
  if (const auto* mesh = g.getIf<TriangleMeshGeometry<Real>>()) return getTriangle(*mesh, s.pose, index, tri).ok();
  return getTriangle(g.get<HeightFieldGeometry<Real>>(), s.pose, index, tri).ok();
}

// Reports one contact of the convex shape (point on its core surface, normal from the triangle to it).
void report(const SurfaceQuery& q, const V3& pointOnConvex, const V3& normal, Real separation, std::uint32_t index,
            bool onFace) {
  const Real depth = separation - q.convex.view->margin - q.surface.view->margin;
  if (!(depth <= q.threshold)) return;
  const V3 pointOnA = pointOnConvex - normal * q.convex.view->margin;
  q.sink.add(normal, pointOnA - normal * depth, depth, q.surface.view->triangleIds(index), onFace);
}

void triangleContacts(const SurfaceQuery& q, std::uint32_t index, const Geometry<Real>& contactGeom) {
  Triangle<Real> tri;
  if (!getSurfaceTriangle(q.surface, index, tri)) return;
  const Real reach = q.threshold + q.convex.view->margin + q.surface.view->margin;
  const Real size = q.convex.view->size;
  ContactBuffer<Real> buffer;
  TriangleContactSettings<Real> settings;
  settings.contactDistance = std::max(reach, Real(0));
  settings.meshContactMargin = kMeshContactMarginFactor * size;
  settings.toleranceLength = size;
  if (!generateTriangleContacts(contactGeom, q.convex.pose, tri, index, buffer, settings).ok()) return;
  for (std::uint32_t i = 0; i < buffer.count; ++i)
    report(q, buffer.contacts[i].position, buffer.contacts[i].normal, buffer.contacts[i].separation, index,
           alongFace(buffer.contacts[i].normal, tri));
}

// generateTriangleContacts takes capsules, boxes and hulls: a sphere is a capsule of zero length.
Geometry<Real> contactGeometry(const Geometry<Real>& g) {
  if (const auto* s = g.getIf<SphereGeometry<Real>>()) return CapsuleGeometry<Real>(s->radius, Real(0));
  return g;
}

Status overlappingTriangles(const PlacedShape& surface, const Geometry<Real>& query, const Pose& queryPose,
                            const TriangleOverlapPage& page, TriangleOverlapPageResult& received) {
  const Geometry<Real>& g = surface.view->geom;
  if (const auto* mesh = g.getIf<TriangleMeshGeometry<Real>>())
    return findOverlapTriangleMesh(query, queryPose, *mesh, surface.pose, page, received);
  return findOverlapHeightField(query, queryPose, g.get<HeightFieldGeometry<Real>>(), surface.pose, page, received);
}

// The midphase's query shape: the triangles within `reach` of the convex shape lie within its sphere or capsule
// grown by reach, or within its own (oriented) bounding box grown by reach, which is tighter than a world box
// around a turned shape.
struct QueryShape {
  Geometry<Real> geom;
  Pose pose;
};
bool queryShape(const PlacedShape& a, Real reach, QueryShape& out) {
  const Geometry<Real>& g = a.view->geom;
  if (const auto* sphere = g.getIf<SphereGeometry<Real>>()) {
    out = {SphereGeometry<Real>(sphere->radius + reach), a.pose};
    return true;
  }
  if (const auto* capsule = g.getIf<CapsuleGeometry<Real>>()) {
    out = {CapsuleGeometry<Real>(capsule->radius + reach, capsule->halfHeight), a.pose};
    return true;
  }
  Bounds3<Real> local;
  if (!computeGeomBounds(local, g, Pose(), reach, Real(1)).ok()) return false;
  out = {BoxGeometry<Real>(local.extents()), a.pose * Pose(local.center())};
  return true;
}

}  // namespace

void surfaceContacts(const PlacedShape& a, const PlacedShape& b, Real threshold, const HandOver& handOver,
                     ContactSink& sink) {
  const Real reach = std::max(threshold, Real(0)) + a.view->margin + b.view->margin;
  QueryShape query;
  if (!queryShape(a, reach, query)) return;
  const Geometry<Real> contactGeom = contactGeometry(a.view->geom);
  InternalEdgeFilter filter(sink);
  const SurfaceQuery q{a, b, threshold, filter};
  std::array<std::uint32_t, kTrianglePage> indices;
  TriangleOverlapPage page{indices.data(), kTrianglePage, 0};
  for (bool more = true; more;) {
    TriangleOverlapPageResult received;
    if (!overlappingTriangles(b, query.geom, query.pose, page, received).ok()) break;
    for (std::uint32_t i = 0; i < received.count; ++i) triangleContacts(q, indices[i], contactGeom);
    page.start += received.count;
    more = received.overflow;
    if (received.count == 0) break;
  }
  filter.flush(handOver);
}

}  // namespace gq::bullet
