// generateMeshContacts: the crossing triangle pairs of two surfaces (dual BVH traversal for mesh against mesh,
// triangles under each other's boxes when a heightfield is involved), each turned into one contact along the
// shallower of the two face normals.
#include <cmath>
#include <optional>

#include "common/validate.h"
#include "gq/contacts.h"
#include "mesh_pairs/mesh_mesh.h"
#include "mesh_pairs/surface_pairs.h"

namespace gq {
namespace {

template <class T> struct FacePush {
  Vec3<T> normal;  // unit, from the face's triangle towards the pushed one
  Vec3<T> point;
  T depth;
};

// Triangle `pushed` out through the face of triangle `face`: along the face normal turned towards pushed's centroid,
// by as far as pushed's deepest vertex lies below the face's plane. None when `face` has no normal (zero area).
template <class T> std::optional<FacePush<T>> pushThroughFace(const Triangle<T>& pushed, const Triangle<T>& face) {
  Vec3<T> n = (face.verts[1] - face.verts[0]).cross(face.verts[2] - face.verts[0]);
  const T length = n.norm();
  if (!(length > T(0)) || !std::isfinite(length)) return std::nullopt;
  n /= length;
  const Vec3<T> centroid = (pushed.verts[0] + pushed.verts[1] + pushed.verts[2]) / T(3);
  if (n.dot(centroid - face.verts[0]) < T(0)) n = -n;
  int deepest = 0;
  T lowest = n.dot(pushed.verts[0] - face.verts[0]);
  for (int k = 1; k < 3; ++k) {
    const T height = n.dot(pushed.verts[k] - face.verts[0]);
    if (height < lowest) {
      lowest = height;
      deepest = k;
    }
  }
  const T depth = std::max(T(0), -lowest);
  return FacePush<T>{n, Vec3<T>(pushed.verts[deepest] + T(0.5) * depth * n), depth};
}

// The contact of crossing triangles a (surface 0) and b (surface 1), in the frame the triangles are given in.
template <class T>
std::optional<MeshContact<T>> crossingContact(const Triangle<T>& a, std::uint32_t ia, const Triangle<T>& b,
                                              std::uint32_t ib) {
  const auto alongB = pushThroughFace(a, b);  // from b towards a: surface 1 towards surface 0
  const auto alongA = pushThroughFace(b, a);  // from a towards b: turned below
  if (!alongB && !alongA) return std::nullopt;
  MeshContact<T> c;
  if (alongB && (!alongA || alongB->depth <= alongA->depth)) {
    c.normal = alongB->normal;
    c.position = alongB->point;
    c.depth = alongB->depth;
  } else {
    c.normal = -alongA->normal;
    c.position = alongA->point;
    c.depth = alongA->depth;
  }
  c.triangle0 = ia;
  c.triangle1 = ib;
  return c;
}

// Coordinates near the scalar's range can overflow the push (vertex + depth * normal): such a pair is not reported.
template <class T> bool isFiniteContact(const MeshContact<T>& c) {
  return c.position.allFinite() && c.normal.allFinite() && std::isfinite(c.depth);
}

bool isSurface(GeometryType t) { return t == GeometryType::TriangleMesh || t == GeometryType::HeightField; }

template <class T> using Report = MeshContactCallback<T>;

// Mesh against mesh: the dual traversal in mesh 0's frame; contacts are taken back to world space.
template <class T>
bool meshMeshContacts(const Report<T>& report, const TriangleMeshGeometry<T>& mesh0, const Transform<T>& pose0,
                      const TriangleMeshGeometry<T>& mesh1, const Transform<T>& pose1) {
  const detail::MeshSurface<T> a(mesh0, Transform<T>());
  const detail::MeshSurface<T> b(mesh1, pose1.relativeTo(pose0));
  bool found = false;
  detail::forEachTrianglePair(a, b, T(0), [&](std::uint32_t ka, const Triangle<T>& ta, std::uint32_t kb,
                                              const Triangle<T>& tb) {
    if (!detail::overlapTriangleTriangle(ta, tb)) return false;
    auto c = crossingContact(ta, a.inputIndex(ka), tb, b.inputIndex(kb));
    if (!c) return false;
    c->position = pose0.transform(c->position);
    c->normal = pose0.rotate(c->normal);
    if (!isFiniteContact(*c)) return false;
    found = true;
    return !report(*c);
  });
  return found;
}

// Pairs involving a heightfield: surface a's triangles under b's box, each against b's triangles under its own box
// (world space). `swapped`: a is surface 1.
template <class T, class SurfaceA, class SurfaceB>
bool surfacePairContacts(const Report<T>& report, const SurfaceA& a, const SurfaceB& b, bool swapped) {
  bool found = false;
  detail::forEachSurfacePair(a, b, T(0), [&](std::uint32_t ia, const Triangle<T>& ta, std::uint32_t ib,
                                             const Triangle<T>& tb) {
    const auto c = swapped ? crossingContact(tb, ib, ta, ia) : crossingContact(ta, ia, tb, ib);
    if (!c || !isFiniteContact(*c)) return false;
    found = true;
    return !report(*c);
  });
  return found;
}

template <class T>
bool surfaceContacts(const Report<T>& report, const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                     const Transform<T>& p1) {
  const auto* m0 = g0.template getIf<TriangleMeshGeometry<T>>();
  const auto* m1 = g1.template getIf<TriangleMeshGeometry<T>>();
  if (m0 && m1) return meshMeshContacts(report, *m0, p0, *m1, p1);
  if (m0) {
    return surfacePairContacts(report, detail::MeshSurface<T>(*m0, p0),
                               detail::HeightFieldSurface<T>(g1.template get<HeightFieldGeometry<T>>(), p1), false);
  }
  const detail::HeightFieldSurface<T> h0(g0.template get<HeightFieldGeometry<T>>(), p0);
  if (m1) return surfacePairContacts(report, detail::MeshSurface<T>(*m1, p1), h0, true);
  return surfacePairContacts(report, h0, detail::HeightFieldSurface<T>(g1.template get<HeightFieldGeometry<T>>(), p1),
                             false);
}

}  // namespace

template <class T>
Status generateMeshContacts(const MeshContactCallback<T>& callback, const Geometry<T>& surface0,
                            const Transform<T>& pose0, const Geometry<T>& surface1, const Transform<T>& pose1,
                            bool& contactFound) noexcept {
  return detail::guarded([&]() -> Status {
    if (!callback) return Status::invalid("callback is empty");
    if (Status s = detail::checkGeometryAndPose(surface0, pose0, detail::kPose0Field); !s.ok()) return s;
    if (Status s = detail::checkGeometryAndPose(surface1, pose1, detail::kPose1Field); !s.ok()) return s;
    if (!isSurface(surface0.type()) || !isSurface(surface1.type())) {
      return Status::unsupported("generateMeshContacts takes a triangle mesh or heightfield on each side");
    }
    contactFound = surfaceContacts(callback, surface0, pose0, surface1, pose1);
    return Status();
  });
}

template Status generateMeshContacts<float>(const MeshContactCallback<float>&, const Geometry<float>&,
                                            const Transform<float>&, const Geometry<float>&, const Transform<float>&,
                                            bool&) noexcept;
template Status generateMeshContacts<double>(const MeshContactCallback<double>&, const Geometry<double>&,
                                             const Transform<double>&, const Geometry<double>&,
                                             const Transform<double>&, bool&) noexcept;

}  // namespace gq
