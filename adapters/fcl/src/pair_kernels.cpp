// Contacts and distances of converted pairs with a mesh or a two-sided plane side, through gq's public queries.
//  - Two solids are not answered here: solid_pairs.h (the fast path) answers them before.
//  - FCL's two-sided Plane n.x = d: the shape's signed distances to the solid half-spaces below (n.x <= d) and
//    above (n.x >= d) are lo - d and d - hi (lo/hi = the shape's extent along n). The plane answer is the larger
//    one: the gap when the shape lies on one side, else minus the smaller push-out depth (FCL's rule
//    depth = r - |signed distance| for a sphere).
//  - BVHModel against a shape: one contact per triangle touched, as FCL's mesh-shape traversal. Candidates come from
//    findOverlapTriangleMesh (exact for sphere/capsule/box; a bounding box or sphere otherwise, then core's exact
//    shape-triangle test, prepared once per call); a triangle's depth and normal come from distance() against the
//    triangle as a support shape.
//  - BVHModel against BVHModel: one contact per intersecting triangle pair (core's generateMeshContacts, or
//    findOverlapTriangleMeshPairs without contact geometry).
//  - BVHModel against Halfspace/Plane: distance by core's plane-mesh distance; contacts per triangle from its
//    vertices' heights (FCL reports one a triangle, placed by its rule: fclTrianglePosition), after core's plane-mesh
//    overlap rejects a mesh that cannot touch.
#include "pair_kernels.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "fcl_tree.h"
#include "plane_crossing.h"
#include "gq/contacts.h"
#include "gq/cooking.h"
#include "gq/kernels/mesh.h"
#include "gq/mesh_query.h"
#include "gq/query.h"

namespace gq::fcl::internal {
namespace {

// Triangles fetched per findOverlapTriangleMesh call: a first page of kFirstTrianglePage, then pages four times as
// large up to kTrianglePage. A further page re-runs the query (it skips the triangles already returned), while a
// large first page makes the query gather candidates a request for one contact never tests: mesh-convex30 collide
// (one contact) 44,129 instructions with pages of 64, 35,752 with 16, 38,872 with 8, 48,474 with 4, 59,991 with 256.
constexpr std::uint32_t kFirstTrianglePage = 16;
constexpr std::uint32_t kTrianglePage = 256;

template <class T> Vec3<T> midpoint(const Vec3<T>& a, const Vec3<T>& b) { return (a + b) * T(0.5); }

template <class T> void flip(PairContact<T>& c) {
  c.normal = -c.normal;
  std::swap(c.b1, c.b2);
}
template <class T> void flip(PairDistance<T>& d) {
  std::swap(d.point1, d.point2);
  std::swap(d.b1, d.b2);
}

// A stack object as a CustomGeometry without allocating (empty control block: the caller keeps it alive).
template <class T> CustomGeometry<T> borrowed(const CustomGeometryCallbacks<T>& callbacks) {
  return CustomGeometry<T>(std::shared_ptr<const CustomGeometryCallbacks<T>>(std::shared_ptr<const void>(), &callbacks));
}

template <class T> PairContact<T> contactFrom(const DistanceResult<T>& d) {
  PairContact<T> c;
  c.position = midpoint(d.point0, d.point1);
  c.normal = d.normal;
  c.depth = std::max(T(0), -d.distance);
  return c;
}

// The gq plane whose solid side is FCL's Plane's upper side n.x >= d: the plane frame turned half a turn about its
// Y axis (+X onto -X).
template <class T> Transform<T> upperSide(const Transform<T>& planePose) {
  return planePose * Transform<T>(Vec3<T>::Zero(), Quat<T>(0, 0, 1, 0));
}

// Signed distance from `shape` to FCL's two-sided plane (see the file comment); normal from the shape to the plane.
template <class T>
Status twoSidedPlaneDistance(const Geometry<T>& shape, const Transform<T>& poseShape, const Transform<T>& planePose,
                             DistanceResult<T>& out) {
  const Geometry<T> plane = PlaneGeometry<T>();
  const Transform<T> above = upperSide(planePose);  // the solid side n.x >= d
  DistanceResult<T> toBelow, toAbove;
  Status s = distance(toBelow, shape, poseShape, plane, planePose);
  if (!s.ok()) return s;
  s = distance(toAbove, shape, poseShape, plane, above);
  if (!s.ok()) return s;
  out = toBelow.distance >= toAbove.distance ? toBelow : toAbove;
  return s;
}

template <class T> bool isPrimitiveQuery(const Geometry<T>& g) {
  const GeometryType t = g.type();
  return t == GeometryType::Sphere || t == GeometryType::Capsule || t == GeometryType::Box;
}


// The candidates of a boolean test in the order of their centroids' distance from the candidate volume's centre,
// nearest first: they overlap the shape most often, and a test that wants one contact stops at the first hit (in the
// bench's hull/sphere-mesh pairs the first hit came after ~5.7 exact GJK tests in the query's order). Distances are
// taken in mesh space (the cooked triangles' vertex copies; a non-uniform scale only changes the order); ties keep
// the query's order (the page position is the second key: std::sort then orders as a stable sort would, without
// the temporary buffer std::stable_sort allocates on every call).
template <class T>
void nearestFirst(const gq::kernels::MeshInstance<T>& instance, const Vec3<T>& centre, std::uint32_t* page,
                  std::uint32_t count) {
  if (count < 2) return;
  struct Keyed {
    T distanceSq;  // 9 |centroid - centre|^2
    std::uint32_t position, triangle;
  };
  thread_local std::vector<Keyed> keyed;
  keyed.clear();
  const TriangleMesh<T>& m = instance.mesh;
  const Vec3<T> c = T(3) * (instance.invScale * instance.pose.transformInv(centre));
  for (std::uint32_t i = 0; i < count; ++i) {
    std::uint32_t s;
    const T* x = m.triangleValues(m.cookedIndex[page[i]], s);
    const Vec3<T> sum = TriangleMesh<T>::vertexIn(x, s, 0) + TriangleMesh<T>::vertexIn(x, s, 1) +
                        TriangleMesh<T>::vertexIn(x, s, 2);
    const T d = (sum - c).squaredNorm();
    // NaN (an overflowing centre) would break the sort's ordering: such keys go last, as +inf.
    keyed.push_back({d <= std::numeric_limits<T>::max() ? d : std::numeric_limits<T>::infinity(), i, page[i]});
  }
  std::sort(keyed.begin(), keyed.end(), [](const Keyed& x, const Keyed& y) {
    return x.distanceSq < y.distanceSq || (x.distanceSq == y.distanceSq && x.position < y.position);
  });
  for (std::uint32_t i = 0; i < count; ++i) page[i] = keyed[i].triangle;
}

// Mesh first: b1 = triangle, normal from the mesh to the shape.
template <class T>
Status meshShapeContacts(const TriangleMeshGeometry<T>& mesh, const Transform<T>& meshPose,
                         const Converted<T>& converted, const Transform<T>& shapePose, bool withGeometry,
                         std::size_t room, std::vector<PairContact<T>>& out) {
  const Geometry<T>& shape = converted.geometry();
  const bool exactCandidates = isPrimitiveQuery(shape);
  Geometry<T> query = shape;
  Transform<T> queryPose = shapePose;
  if (!exactCandidates) {
    std::optional<CandidateVolume<T>> computed;  // only for a shape converted without the cache
    const CandidateVolume<T>* candidate = converted.cachedCandidate();
    if (!candidate) {
      const Status s = candidateVolume(shape, computed.emplace());
      if (!s.ok()) return s;
      candidate = &*computed;
    }
    query = candidate->volume;
    queryPose = shapePose * Transform<T>(candidate->centre);
  }
  // Set up once per call, on the first candidate: the mesh's world triangles (the arithmetic of getTriangle, whose
  // checks findOverlapTriangleMesh has made) and the shape for core's boolean shape-triangle test.
  std::optional<gq::kernels::MeshInstance<T>> instance;
  std::optional<gq::kernels::TriangleQueryShape<T>> boolean;
  std::uint32_t page[kTrianglePage];
  std::uint32_t start = 0, nextPage = kFirstTrianglePage;
  const std::size_t first = out.size();
  for (;;) {
    // Exact candidates are contacts themselves: fetch no more than the result has room for (the query stops there).
    const std::uint32_t pageSize =
        exactCandidates && !withGeometry && room < nextPage ? std::uint32_t(room) : nextPage;
    nextPage = std::min(kTrianglePage, 4 * nextPage);
    TriangleOverlapPageResult received;
    Status s =
        findOverlapTriangleMesh(query, queryPose, mesh, meshPose, TriangleOverlapPage{page, pageSize, start}, received);
    if (!s.ok()) return s;
    const std::uint32_t count = received.count;
    if (!withGeometry && !exactCandidates) {
      if (!instance) instance.emplace(mesh, meshPose);
      nearestFirst(*instance, queryPose.p, page, count);
    }
    for (std::uint32_t i = 0; i < count; ++i) {
      PairContact<T> c;
      bool hit = true;
      if (withGeometry || !exactCandidates) {
        if (!instance) instance.emplace(mesh, meshPose);
        const Triangle<T> triangle = instance->worldTriangle(mesh.mesh->cookedIndex[page[i]]);
        if (withGeometry) s = triangleContact(shape, shapePose, triangle, c, hit);
        else hit = (boolean ? *boolean : boolean.emplace(shape, shapePose)).overlaps(triangle);
        if (!s.ok()) return s;
      }
      if (!hit) continue;
      c.b1 = int(page[i]);
      out.push_back(c);
      if (out.size() - first >= room) return s;
    }
    start += count;
    if (!received.overflow) return s;
  }
}

// BVHModel against BVHModel: one contact per intersecting triangle pair (at most `room`, sorted by the pair's ids: a
// fixed order whatever the traversal's). With geometry, core's generateMeshContacts (each pair pushed out through
// the shallower of the two faces); without, core's pair overlap.
template <class T>
Status meshMeshContacts(const TriangleMeshGeometry<T>& m1, const Transform<T>& p1, const TriangleMeshGeometry<T>& m2,
                        const Transform<T>& p2, bool withGeometry, std::size_t room, std::vector<PairContact<T>>& out) {
  const std::size_t first = out.size();
  bool found = false;
  Status s;
  if (withGeometry) {
    s = generateMeshContacts<T>(
        [&](const MeshContact<T>& m) {
          PairContact<T> c;
          c.position = m.position;
          c.normal = -m.normal;  // core's from surface 1 towards surface 0
          c.depth = m.depth;
          c.b1 = int(m.triangle0);
          c.b2 = int(m.triangle1);
          out.push_back(c);
          return out.size() - first < room;
        },
        Geometry<T>(m1), p1, Geometry<T>(m2), p2, found);
  } else {
    s = findOverlapTriangleMeshPairs<T>(
        [&](std::uint32_t t1, std::uint32_t t2) {
          PairContact<T> c;
          c.b1 = int(t1);
          c.b2 = int(t2);
          out.push_back(c);
          return out.size() - first < room;
        },
        m1, p1, m2, p2, found);
  }
  if (!s.ok()) {
    out.resize(first);
    return s;
  }
  std::sort(out.begin() + std::ptrdiff_t(first), out.end(), [](const PairContact<T>& x, const PairContact<T>& y) {
    return std::make_pair(x.b1, x.b2) < std::make_pair(y.b1, y.b2);
  });
  return s;
}

// A triangle's heights above FCL's Halfspace / Plane (n.x = d, n = the gq plane frame's +X).
template <class T> struct TriangleHeights {
  Vec3<T> vertex[3];  // world vertices, in the triangle's order
  T height[3];
  int lowest = 0, highest = 0;  // the first vertex of least / greatest height (FCL's choice on a tie)
  T lo() const { return height[lowest]; }
  T hi() const { return height[highest]; }
};
template <class T>
TriangleHeights<T> heightsOf(const TriangleMesh<T>& mesh, std::size_t cooked, const Transform<T>& meshPose,
                             const Vec3<T>& n, T d) {
  TriangleHeights<T> h;
  for (int k = 0; k < 3; ++k) {
    h.vertex[k] = meshPose.transform(mesh.vertices[mesh.triangles[cooked][k]]);
    h.height[k] = n.dot(h.vertex[k]) - d;
    if (h.height[k] < h.height[h.lowest]) h.lowest = k;
    if (h.height[k] > h.height[h.highest]) h.highest = k;
  }
  return h;
}

// FCL 0.7's contact position of a triangle against its Halfspace (midway between the deepest vertex and the
// boundary) or crossing its Plane (the midpoint of the two points where its edges cross the plane).
template <class T> Vec3<T> fclTrianglePosition(const TriangleHeights<T>& h, const Vec3<T>& n, bool twoSided) {
  if (twoSided) return straddleMidpoint(h.vertex, h.height, false);
  return h.vertex[h.lowest] - n * (h.lo() * T(0.5));
}

// Whether any triangle can reach FCL's Halfspace (core's mesh-plane overlap) or cross its Plane (then the mesh
// reaches both sides: core's overlap with the half-spaces below and above; necessary, not sufficient, as two
// triangles may lie one on each side).
template <class T>
Status meshMayTouchPlane(const TriangleMeshGeometry<T>& mesh, const Transform<T>& meshPose, bool twoSided,
                         const Transform<T>& planePose, bool& may) {
  const Geometry<T> plane = PlaneGeometry<T>(), g = mesh;
  Status s = overlap(g, meshPose, plane, planePose, may);
  if (s.ok() && may && twoSided) s = overlap(g, meshPose, plane, upperSide(planePose), may);
  return s;
}

// BVHModel against Halfspace / Plane, mesh first: one contact per triangle reaching the solid side (half-space) or
// crossing the plane, as FCL's mesh-shape traversal does; the whole mesh is first rejected by core's overlap when
// it cannot touch. A triangle's depth: its deepest vertex's (two-sided: towards the side the triangle mostly lies
// on), the normal along -n (or n), the position FCL's.
template <class T>
Status meshPlaneContacts(const TriangleMeshGeometry<T>& mesh, const Transform<T>& meshPose, const Converted<T>& plane,
                         const Transform<T>& planePose, bool withGeometry, std::size_t room,
                         std::vector<PairContact<T>>& out) {
  const bool twoSided = plane.shape == FclShape::Plane;
  bool may = false;
  if (Status s = meshMayTouchPlane(mesh, meshPose, twoSided, planePose, may); !s.ok() || !may) return s;
  const Vec3<T> n = planePose.rotate(Vec3<T>::UnitX());
  const T d = n.dot(planePose.p);
  const TriangleMesh<T>& m = *mesh.mesh;
  const std::size_t first = out.size();
  for (std::size_t k = 0; k < m.triangles.size() && out.size() - first < room; ++k) {
    const TriangleHeights<T> h = heightsOf(m, k, meshPose, n, d);
    const bool below = !twoSided || -h.lo() <= h.hi();
    const T signedDistance = below ? (twoSided ? std::max(h.lo(), -h.hi()) : h.lo()) : -h.hi();
    if (signedDistance > T(0)) continue;
    PairContact<T> c;
    if (withGeometry) {
      c.depth = -signedDistance;
      c.normal = below ? Vec3<T>(-n) : n;
      c.position = fclTrianglePosition(h, n, twoSided);
    }
    c.b1 = int(m.inputIndex[k]);
    out.push_back(c);
  }
  return {};
}

// Triangle of `mesh` nearest to the world point `p` (a witness of the mesh distance).
template <class T> int nearestTriangle(const TriangleMeshGeometry<T>& mesh, const Transform<T>& pose, const Vec3<T>& p) {
  PointDistanceResult<T> r;
  if (!pointDistance(p, Geometry<T>(mesh), pose, r).ok() || r.closestIndex == kInvalidFaceIndex) return kNoPrimitive;
  return int(r.closestIndex);
}

// BVHModel against Halfspace / Plane distance, mesh first: core's plane-mesh distance (the lowest vertex's signed
// height); a two-sided Plane takes the larger of the distances to its two sides (the file comment). b1 is a triangle
// holding the witness vertex.
template <class T>
Status meshPlaneDistance(const TriangleMeshGeometry<T>& mesh, const Transform<T>& meshPose, const Converted<T>& plane,
                         const Transform<T>& planePose, PairDistance<T>& out) {
  const Geometry<T> g = mesh;
  DistanceResult<T> d;
  const Status s = plane.shape == FclShape::Plane ? twoSidedPlaneDistance(g, meshPose, planePose, d)
                                                  : distance(d, g, meshPose, Geometry<T>(PlaneGeometry<T>()), planePose);
  if (!s.ok()) return s;
  out = PairDistance<T>{d.distance, d.point0, d.point1, nearestTriangle(mesh, meshPose, d.point0), kNoPrimitive};
  return s;
}

template <class T> const TriangleMeshGeometry<T>* meshOf(const Converted<T>& c) {
  return c.shape == FclShape::Mesh ? c.geometry().template getIf<TriangleMeshGeometry<T>>() : nullptr;
}

}  // namespace

template <class T>
Status triangleContact(const Geometry<T>& shape, const Transform<T>& pose, const Triangle<T>& triangle,
                       PairContact<T>& contact, bool& hit) {
  const TriangleCallbacks<T> callbacks(triangle.verts[0], triangle.verts[1], triangle.verts[2]);
  const Geometry<T> tri = borrowed<T>(callbacks);
  DistanceResult<T> d;
  const Status s = distance(d, tri, Transform<T>(), shape, pose);
  if (!s.ok()) return s;
  hit = d.distance <= T(0);
  if (!hit) return s;
  contact = contactFrom(d);
  // A sphere: FCL's point, the triangle's point nearest the centre (the witness on the triangle).
  if (shape.type() == GeometryType::Sphere) contact.position = d.point0;
  return s;
}

template <class T> Status candidateVolume(const Geometry<T>& g, CandidateVolume<T>& out) {
  Bounds3<T> local;
  const Status s = computeGeomBounds(local, g, Transform<T>(), T(0), T(1));
  if (!s.ok()) return s;
  const Vec3<T> half = local.extents().cwiseMax(Vec3<T>::Constant(std::numeric_limits<T>::min()));
  out.centre = local.center();
  out.volume = BoxGeometry<T>(half);
  if (const ConvexMeshGeometry<T>* hull = g.template getIf<ConvexMeshGeometry<T>>()) {
    const Mat3<T> scale = hull->scale.toMatrix();
    T r2 = 0;
    for (const Vec3<T>& v : hull->mesh->vertices) r2 = std::max(r2, (scale * v - out.centre).squaredNorm());
    const T r = std::sqrt(r2) * (T(1) + 8 * std::numeric_limits<T>::epsilon());  // rounding: never inside a vertex
    const T sphereVolume = T(4.18879) * r * r * r;  // 4/3 pi r^3
    if (sphereVolume < T(8) * half.x() * half.y() * half.z()) out.volume = SphereGeometry<T>(r);
  }
  return s;
}

template <class T>
Status pairContacts(const Converted<T>& a, const Transform<T>& pa, const Converted<T>& b, const Transform<T>& pb,
                    bool withGeometry, std::size_t room, std::vector<PairContact<T>>& out) {
  if (room == 0) return {};
  if (a.isTree() || b.isTree()) {  // a BVHModel not cooked yet, against a solid: on FCL's tree
    if (!treeAgainstSolid(a, b)) return Status::unsupported("a BVHModel's FCL tree against a plane or a mesh");
    const std::size_t first = out.size();
    const Status s = a.isTree() ? treeContacts(a.tree(), pa, b, pb, withGeometry, room, out)
                                : treeContacts(b.tree(), pb, a, pa, withGeometry, room, out);
    if (b.isTree())
      for (std::size_t i = first; i < out.size(); ++i) flip(out[i]);
    return s;
  }
  const TriangleMeshGeometry<T>* ma = meshOf(a);
  const TriangleMeshGeometry<T>* mb = meshOf(b);
  if (ma && mb) return meshMeshContacts(*ma, pa, *mb, pb, withGeometry, room, out);
  // One mesh: the kernel takes the mesh first; contacts it adds for a mesh in b are flipped back to a -> b.
  auto meshFirst = [&](auto&& contacts) {
    const std::size_t first = out.size();
    const Status s = ma ? contacts(*ma, pa, b, pb) : contacts(*mb, pb, a, pa);
    if (mb)
      for (std::size_t i = first; i < out.size(); ++i) flip(out[i]);
    return s;
  };
  if ((ma && b.isPlaneLike()) || (mb && a.isPlaneLike()))
    return meshFirst([&](const auto& m, const auto& pm, const auto& o, const auto& po) {
      return meshPlaneContacts(m, pm, o, po, withGeometry, room, out);
    });
  if (ma || mb)
    return meshFirst([&](const auto& m, const auto& pm, const auto& o, const auto& po) {
      return meshShapeContacts(m, pm, o, po, withGeometry, room, out);
    });
  if (a.shape == FclShape::Plane || b.shape == FclShape::Plane) {
    if (a.isPlaneLike() && b.isPlaneLike()) return Status::unsupported("plane against plane");
    const bool planeFirst = a.shape == FclShape::Plane;
    DistanceResult<T> d;
    const Status s = planeFirst ? twoSidedPlaneDistance(b.geometry(), pb, pa, d) : twoSidedPlaneDistance(a.geometry(), pa, pb, d);
    if (!s.ok() || d.distance > T(0)) return s;
    PairContact<T> c = contactFrom(d);
    if (planeFirst) flip(c);
    out.push_back(c);
    return s;
  }
  return Status::unsupported("two solids: solid_pairs.h answers them");
}

template <class T>
Status pairDistance(const Converted<T>& a, const Transform<T>& pa, const Converted<T>& b, const Transform<T>& pb,
                    PairDistance<T>& out, T farEnough) {
  if (a.isTree() || b.isTree()) {  // a BVHModel not cooked yet, against a solid: on FCL's tree
    if (!treeAgainstSolid(a, b)) return Status::unsupported("a BVHModel's FCL tree against a plane or a mesh");
    const Status s = a.isTree() ? treeDistance(a.tree(), pa, b, pb, out, farEnough)
                                : treeDistance(b.tree(), pb, a, pa, out, farEnough);
    if (b.isTree()) flip(out);
    return s;
  }
  const TriangleMeshGeometry<T>* ma = meshOf(a);
  const TriangleMeshGeometry<T>* mb = meshOf(b);
  DistanceResult<T> d;
  Status s;
  if ((ma && b.isPlaneLike()) || (mb && a.isPlaneLike())) {
    s = ma ? meshPlaneDistance(*ma, pa, b, pb, out) : meshPlaneDistance(*mb, pb, a, pa, out);
    if (mb) flip(out);
    return s;
  }
  if (a.shape == FclShape::Plane || b.shape == FclShape::Plane) {
    if (a.isPlaneLike() && b.isPlaneLike()) return Status::unsupported("plane against plane");
    const bool planeFirst = a.shape == FclShape::Plane;
    s = planeFirst ? twoSidedPlaneDistance(b.geometry(), pb, pa, d) : twoSidedPlaneDistance(a.geometry(), pa, pb, d);
    if (!s.ok()) return s;
    out = PairDistance<T>{d.distance, d.point0, d.point1, kNoPrimitive, kNoPrimitive};
    if (planeFirst) flip(out);
    return s;
  }
  if (a.isSolid() && b.isSolid()) return Status::unsupported("two solids: solid_pairs.h answers them");
  bool beyond = false;
  s = distanceWithin(d, beyond, farEnough, a.geometry(), pa, b.geometry(), pb);
  if (!s.ok()) return s;
  out = PairDistance<T>{d.distance, d.point0, d.point1, kNoPrimitive, kNoPrimitive};
  if (beyond) return s;
  if (ma) out.b1 = nearestTriangle(*ma, pa, d.point0);
  if (mb) out.b2 = nearestTriangle(*mb, pb, d.point1);
  return s;
}

template Status triangleContact<float>(const Geometry<float>&, const Transform<float>&, const Triangle<float>&,
                                       PairContact<float>&, bool&);
template Status triangleContact<double>(const Geometry<double>&, const Transform<double>&, const Triangle<double>&,
                                        PairContact<double>&, bool&);
template Status candidateVolume<float>(const Geometry<float>&, CandidateVolume<float>&);
template Status candidateVolume<double>(const Geometry<double>&, CandidateVolume<double>&);
template Status pairContacts<float>(const Converted<float>&, const Transform<float>&, const Converted<float>&,
                                    const Transform<float>&, bool, std::size_t, std::vector<PairContact<float>>&);
template Status pairContacts<double>(const Converted<double>&, const Transform<double>&, const Converted<double>&,
                                     const Transform<double>&, bool, std::size_t, std::vector<PairContact<double>>&);
template Status pairDistance<float>(const Converted<float>&, const Transform<float>&, const Converted<float>&,
                                    const Transform<float>&, PairDistance<float>&, float);
template Status pairDistance<double>(const Converted<double>&, const Transform<double>&, const Converted<double>&,
                                     const Transform<double>&, PairDistance<double>&, double);

}  // namespace gq::fcl::internal
