// The contact set of a convex pair (gq/contacts.h generateContacts).
//
// 1. The exact separation and normal: for a pair of polytopes (box, hull; or one of them and a plane) the
//    penetration by separating axes when the shapes penetrate (resting contacts do), otherwise the signed distance
//    (GJK, EPA when penetrating), stopping early once the pair is proven farther than contactDistance.
// 2. When a flat face of one side supports the contact, the other side's incident feature is clipped to it
//    (features.cpp, clipping.cpp); no clipped point is deeper than the exact separation. The exact point joins the
//    clipped ones unless one of them already carries the exact separation.
// 3. The points are reduced to maxContacts (reduction.cpp).
// Rounded shapes (margins) rest with their cores apart: their distance answers first and the penetration runs only
// when the cores touch. Exact polytopes (boxes) rest penetrating: their penetration runs first.
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "common/validate.h"
#include "contacts/contact_features.h"
#include "gjk/gjk.h"
#include "gq/contacts.h"

namespace gq {
namespace {

using detail::Feature;
using detail::kMaxFeaturePoints;

// The queries of one side's representation: geometries (validated by each query) or prepared shapes.
template <class T> struct GeometryQueries {
  const Geometry<T>* g0;
  const Geometry<T>* g1;
  const Geometry<T>& geometry0() const { return *g0; }
  const Geometry<T>& geometry1() const { return *g1; }
  GeometryQueries swapped() const { return {g1, g0}; }
  Status penetration(PenetrationResult<T>& r, const Transform<T>& p0, const Transform<T>& p1) const {
    return computePenetration(r, *g0, p0, *g1, p1);
  }
  Status distanceUpTo(DistanceResult<T>& d, bool& beyond, T within, const Transform<T>& p0, const Transform<T>& p1,
                      GjkCache<T>* cache) const {
    return distanceWithin(d, beyond, within, *g0, p0, *g1, p1, cache);
  }
};

template <class T> struct ShapeQueries {
  const Shape<T>* s0;
  const Shape<T>* s1;
  const Geometry<T>& geometry0() const { return s0->geometry(); }
  const Geometry<T>& geometry1() const { return s1->geometry(); }
  ShapeQueries swapped() const { return {s1, s0}; }
  Status penetration(PenetrationResult<T>& r, const Transform<T>& p0, const Transform<T>& p1) const {
    return computePenetration(r, *s0, p0, *s1, p1);
  }
  Status distanceUpTo(DistanceResult<T>& d, bool& beyond, T within, const Transform<T>& p0, const Transform<T>& p1,
                      GjkCache<T>* cache) const {
    return distanceWithin(d, beyond, within, *s0, p0, *s1, p1, cache);
  }
};

// Points gathered before the reduction: positions on geom1 and separations along `normal`.
template <class T> struct Candidates {
  std::array<Vec3<T>, kMaxFeaturePoints + 1> points;
  std::array<T, kMaxFeaturePoints + 1> separations;
  int count = 0;
  Vec3<T> normal = Vec3<T>::Zero();
};

// The pair seen as geom0 = a (convex), geom1 = b (convex or plane).
template <class T> struct Pair {
  const Geometry<T>& a;
  const Transform<T>& pa;
  const Geometry<T>& b;
  const Transform<T>& pb;
  T ma, mb;       // margins
  T threshold;    // contactDistance
  T tolerance;    // separations within it are equal
  // A face whose normal is within this of 1 (cosine) is the separating axis's own face: no other face is sought.
  T alignmentSlack = std::is_same_v<T, float> ? T(1e-5) : T(1e-9);
};

// The incident points clipped to the reference face, appended to `out` (normal: the face's, from b towards a).
// Returns the smallest separation added (+max when none).
template <class T> T clippedContacts(const Pair<T>& pair, const Vec3<T>& normal, T exactSeparation, Candidates<T>& out) {
  T deepest = std::numeric_limits<T>::max();
  // The reference face is b's, or a's when a's face is better aligned with the normal (the separating axis's own
  // face, exactly aligned, when two faces qualify). a's face is looked at only when b's is not already that aligned.
  Feature<T> reference, incident;
  bool referenceIsB = true;
  T alignment = T(-1);
  const bool faceB = detail::referenceFace(pair.b, pair.pb, normal, reference, &alignment);
  if (!(faceB && alignment >= T(1) - pair.alignmentSlack &&
        detail::incidentFeature(pair.a, pair.pa, Vec3<T>(-normal), incident))) {
    Feature<T> faceOfA;
    T alignmentA = T(-1);
    const bool faceA = detail::referenceFace(pair.a, pair.pa, Vec3<T>(-normal), faceOfA, &alignmentA);
    if (faceA && (!faceB || alignmentA > alignment) && detail::incidentFeature(pair.b, pair.pb, normal, incident)) {
      referenceIsB = false;
      reference = faceOfA;
    } else if (!(faceB && detail::incidentFeature(pair.a, pair.pa, Vec3<T>(-normal), incident))) {
      if (!(faceA && detail::incidentFeature(pair.b, pair.pb, normal, incident))) return deepest;
      referenceIsB = false;
      reference = faceOfA;
    }
  }
  detail::clipToFace(reference, incident);
  const Vec3<T> n = referenceIsB ? reference.normal : Vec3<T>(-reference.normal);
  for (int i = 0; i < incident.count; ++i) {
    const Vec3<T>& p = incident.points[i];
    const T s = std::max((p - reference.origin).dot(reference.normal) - pair.ma - pair.mb, exactSeparation);
    if (s > pair.threshold) continue;
    out.points[out.count] = referenceIsB ? Vec3<T>(p - n * pair.ma - n * s) : Vec3<T>(p + n * pair.mb);
    out.separations[out.count++] = s;
    deepest = std::min(deepest, s);
  }
  if (deepest < std::numeric_limits<T>::max()) out.normal = n;  // the set's normal is the face's once it has points
  return deepest;
}

// Penetrating polytopes: the separating-axis normal and depth, then the clipped face contacts. False when the cores
// do not penetrate or no clipped point carries the exact depth (the signed distance then answers; `out` is left
// empty).
template <class T, class Q>
bool penetratingPolytopeContacts(const Q& q, const Pair<T>& pair, Candidates<T>& out) {
  PenetrationResult<T> mtd;
  if (!q.penetration(mtd, pair.pa, pair.pb).ok() || !mtd.penetrating) return false;
  const T separation = -mtd.depth - pair.ma - pair.mb;
  const Vec3<T> normal = mtd.direction;  // moving a along it separates: it points from b to a
  if (!isFinite(normal) || normal.squaredNorm() < T(0.5)) return false;
  if (clippedContacts(pair, normal, separation, out) > separation + pair.tolerance) {
    out.count = 0;
    return false;
  }
  return true;
}

// The signed-distance path: contacts of a pair whose core distance `d` is known.
template <class T> void distanceContacts(const Pair<T>& pair, const DistanceResult<T>& d, Candidates<T>& out) {
  const T separation = d.distance - pair.ma - pair.mb;
  const Vec3<T> normal = -d.normal;  // d.normal runs from a to b
  if (!(separation <= pair.threshold) || !isFinite(normal) || normal.squaredNorm() < T(0.5)) return;
  out.normal = normal;
  if (clippedContacts(pair, normal, separation, out) > separation + pair.tolerance) {
    out.points[out.count] = d.point1 + normal * pair.mb;
    out.separations[out.count++] = separation;
  }
}

template <class T, class Q>
Status convexContacts(const Q& q, const Pair<T>& pair, GjkCache<T>* cache, Candidates<T>& out) {
  const auto flat = [](const Geometry<T>& g) { return detail::isPolytope(g) || g.type() == GeometryType::Plane; };
  const bool sat = flat(pair.a) && flat(pair.b) && (detail::isPolytope(pair.a) || detail::isPolytope(pair.b));
  const T margins = pair.ma + pair.mb;
  DistanceResult<T> d;
  bool beyond = false;
  const T within = pair.threshold + margins;
  if (sat && margins > T(0)) {
    if (Status s = q.distanceUpTo(d, beyond, within, pair.pa, pair.pb, cache); !s.ok() || beyond) return s;
    if (d.distance > pair.tolerance || !penetratingPolytopeContacts(q, pair, out)) distanceContacts(pair, d, out);
    return Status();
  }
  if (sat && penetratingPolytopeContacts(q, pair, out)) return Status();
  if (Status s = q.distanceUpTo(d, beyond, within, pair.pa, pair.pb, cache); !s.ok() || beyond) return s;
  distanceContacts(pair, d, out);
  return Status();
}

template <class T> Status checkSettings(const ContactSetSettings<T>& s) {
  if (!(std::isfinite(s.contactDistance) && s.contactDistance >= T(0)))
    return Status::invalid("contactDistance must be finite and >= 0");
  if (s.maxContacts < 1 || s.maxContacts > kMaxContactSetPoints)
    return Status::invalid("maxContacts must be in [1, kMaxContactSetPoints]");
  if (!(std::isfinite(s.margin0) && s.margin0 >= T(0)) || !(std::isfinite(s.margin1) && s.margin1 >= T(0)))
    return Status::invalid("margins must be finite and >= 0");
  if (!(std::isfinite(s.toleranceLength) && s.toleranceLength > T(0)))
    return Status::invalid("toleranceLength must be finite and > 0");
  return Status();
}

// Two boxes: the compact box-pair path (box_box.cpp); the signed distance of the cores answers pairs apart within
// the threshold.
template <class T, class Q>
Status boxContactSet(const Q& q, const Transform<T>& pose0, const Transform<T>& pose1, ContactSet<T>& out,
                     const ContactSetSettings<T>& settings, T tolerance) {
  if (!detail::pairPosesAreValid(pose0, pose1)) return detail::pairPosesStatus(pose0, pose1);
  const auto& box0 = q.geometry0().template get<BoxGeometry<T>>();
  const auto& box1 = q.geometry1().template get<BoxGeometry<T>>();
  const detail::BoxContactSettings<T> s{settings.contactDistance, settings.margin0, settings.margin1, tolerance,
                                        int(settings.maxContacts)};
  if (detail::boxContactsPenetrating(box0, pose0, box1, pose1, s, out)) return Status();
  DistanceResult<T> d;
  bool beyond = false;
  const T within = settings.contactDistance + settings.margin0 + settings.margin1;
  if (Status st = q.distanceUpTo(d, beyond, within, pose0, pose1, settings.cache); !st.ok()) return st;
  if (beyond) {
    out.normal = Vec3<T>::Zero();
    out.count = 0;
    return Status();
  }
  detail::boxContactsApart(box0, pose0, box1, pose1, s, d, out);
  return Status();
}

template <class T, class Q>
Status contactSet(const Q& q, const Transform<T>& pose0, const Transform<T>& pose1, ContactSet<T>& out,
                  const ContactSetSettings<T>& settings) {
  // The poses are validated by the penetration and distance queries every path starts with (nothing is written
  // before they answer).
  if (Status s = checkSettings(settings); !s.ok()) return s;
  const Geometry<T>& g0 = q.geometry0();
  const Geometry<T>& g1 = q.geometry1();
  const bool convex0 = detail::isConvexShapeType(g0.type()), convex1 = detail::isConvexShapeType(g1.type());
  const bool plane0 = g0.type() == GeometryType::Plane, plane1 = g1.type() == GeometryType::Plane;
  if (!((convex0 && (convex1 || plane1)) || (plane0 && convex1)))
    return Status::unsupported("contact sets are defined for convex pairs and a plane against a convex shape");
  const T tolerance = T(tol::Rel<T>::kEpsilon) * settings.toleranceLength;
  if (g0.type() == GeometryType::Box && g1.type() == GeometryType::Box)
    return boxContactSet(q, pose0, pose1, out, settings, tolerance);
  Candidates<T> c;
  const bool swap = plane0;  // the plane goes second
  if (!swap) {
    const Pair<T> pair{g0, pose0, g1, pose1, settings.margin0, settings.margin1, settings.contactDistance, tolerance};
    if (Status s = convexContacts(q, pair, settings.cache, c); !s.ok()) return s;
  } else {
    // The cache belongs to (geom0, geom1): the swapped pair runs cold.
    const Pair<T> pair{g1, pose1, g0, pose0, settings.margin1, settings.margin0, settings.contactDistance, tolerance};
    if (Status s = convexContacts(q.swapped(), pair, static_cast<GjkCache<T>*>(nullptr), c); !s.ok()) return s;
    // Contacts of (geom1, geom0) as contacts of (geom0, geom1): the normal flips and the point moves to geom0's
    // counterpart along the old normal.
    for (int i = 0; i < c.count; ++i) c.points[i] += c.normal * c.separations[i];
    c.normal = -c.normal;
  }
  std::array<int, kMaxContactSetPoints> keep;
  const int kept = detail::reduceContactPoints(c.points.data(), c.separations.data(), c.count, c.normal,
                                               int(settings.maxContacts), keep.data());
  out.normal = kept > 0 ? c.normal : Vec3<T>::Zero();
  out.count = std::uint32_t(kept);
  for (int k = 0; k < kept; ++k) out.points[k] = {c.points[keep[k]], c.separations[keep[k]]};
  return Status();
}

}  // namespace

template <class T>
Status generateContacts(const Geometry<T>& geom0, const Transform<T>& pose0, const Geometry<T>& geom1,
                        const Transform<T>& pose1, ContactSet<T>& out, const ContactSetSettings<T>& settings) noexcept {
  return detail::guarded([&]() -> Status {
    if (detail::Problem p = detail::pairGeometryProblem(geom0)) return p.status();
    if (detail::Problem p = detail::pairGeometryProblem(geom1)) return p.status();
    return contactSet(GeometryQueries<T>{&geom0, &geom1}, pose0, pose1, out, settings);
  });
}

template <class T>
Status generateContacts(const Shape<T>& shape0, const Transform<T>& pose0, const Shape<T>& shape1,
                        const Transform<T>& pose1, ContactSet<T>& out, const ContactSetSettings<T>& settings) noexcept {
  return detail::guarded([&]() -> Status {
    if (shape0.empty() || shape1.empty()) return Status::invalid("the shape is empty (not made by Shape::make)");
    return contactSet(ShapeQueries<T>{&shape0, &shape1}, pose0, pose1, out, settings);
  });
}

#define GQ_INSTANTIATE(T)                                                                                         \
  template Status generateContacts<T>(const Geometry<T>&, const Transform<T>&, const Geometry<T>&,                \
                                      const Transform<T>&, ContactSet<T>&, const ContactSetSettings<T>&) noexcept; \
  template Status generateContacts<T>(const Shape<T>&, const Transform<T>&, const Shape<T>&, const Transform<T>&, \
                                      ContactSet<T>&, const ContactSetSettings<T>&) noexcept;
GQ_INSTANTIATE(float)
GQ_INSTANTIATE(double)
#undef GQ_INSTANTIATE

}  // namespace gq
