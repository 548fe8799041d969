#pragma once
// The pieces of a convex pair's contact set (gq/contacts.h generateContacts): the flat face of a box, hull or plane
// that supports a contact (reference), the points of the other shape that rest on it (incident: a face, a cylinder cap
// or side line, a capsule's side segment), the clipping of the incident points to the reference face
// (Sutherland-Hodgman), and the reduction of a point set to the few that span it.
#include <array>

#include "gq/contacts.h"
#include "gq/geometry.h"
#include "gq/kernels/clip.h"
#include "gq/math.h"
#include "gq/query.h"
#include "gq/transform.h"

namespace gq::detail {

// A face counts as supporting a contact when its normal is within this cosine of the contact normal (~8 degrees).
inline constexpr double kFaceAlignmentCos = 0.99;
// Points sampled on a cylinder cap's rim (a rim is not a polygon; four points span its support).
inline constexpr int kCapRimPoints = 4;
inline constexpr int kMaxFeaturePoints = 64;

template <class T> struct Feature {
  std::array<Vec3<T>, kMaxFeaturePoints> points;
  int count = 0;
  Vec3<T> normal = Vec3<T>::Zero();  // reference faces: outward unit normal
  Vec3<T> origin = Vec3<T>::Zero();  // reference faces: a point of the face plane
  bool unbounded = false;            // a plane: nothing to clip against
  // A box face: the rectangle centre + x u + y w with |x| <= hu, |y| <= hw (clipped in its own 2D frame).
  bool rectangle = false;
  Vec3<T> centre = Vec3<T>::Zero(), u = Vec3<T>::Zero(), w = Vec3<T>::Zero();
  T hu = T(0), hw = T(0);
};

// Box and convex mesh: the shapes with flat faces and an exact penetration by separating axes.
template <class T> bool isPolytope(const Geometry<T>& g) {
  return g.type() == GeometryType::Box || g.type() == GeometryType::ConvexMesh;
}

// The face of a box, convex mesh or plane (at `pose`) whose outward normal is the most aligned with `dir` (unit):
// true when within kFaceAlignmentCos of it. `alignment` (optional) receives the cosine (-1: no face).
template <class T>
bool referenceFace(const Geometry<T>& g, const Transform<T>& pose, const Vec3<T>& dir, Feature<T>& face,
                   T* alignment = nullptr);
// The points of `g` farthest along `dir` (unit) when they form a face, a cap or a segment; false for a single point.
template <class T>
bool incidentFeature(const Geometry<T>& g, const Transform<T>& pose, const Vec3<T>& dir, Feature<T>& feature);
// Clips the incident polygon (or segment, or point) to the prism over the reference face; returns the count left.
template <class T> int clipToFace(const Feature<T>& reference, Feature<T>& incident);

// A point in a rectangle's frame and its clipping (gq/kernels/clip.h).
template <class T> using FacePoint = kernels::RectanglePoint<T>;
using kernels::clipToRectangle;

// Picks at most `maxKeep` (<= kMaxFeaturePoints) of `count` points (common normal n) spanning the largest area: the
// deepest, the farthest from it, the farthest from their line on each side, then the deepest of the rest. Writes
// their indices to `keep`; returns how many.
template <class T>
int reduceContactPoints(const Vec3<T>* points, const T* separations, int count, const Vec3<T>& n, int maxKeep,
                        int* keep);

// ---- Box pairs (box_box.cpp) ----------------------------------------------------------------------------------

// The settings of a box pair's contact set, checked by the caller.
template <class T> struct BoxContactSettings {
  T threshold;  // contactDistance
  T margin0, margin1;
  T tolerance;  // separations within it are equal
  int maxContacts;
};

// The contact set of two boxes (poses validated by the caller). Penetrating cores: the whole set (SAT depth and
// normal, the incident face clipped to the reference face), true. A separating axis with a gap beyond the threshold:
// an empty set, true. Otherwise false and nothing written: the caller takes the exact signed distance of the cores
// and passes it to boxContactsApart.
template <class T>
bool boxContactsPenetrating(const BoxGeometry<T>& box0, const Transform<T>& pose0, const BoxGeometry<T>& box1,
                            const Transform<T>& pose1, const BoxContactSettings<T>& settings, ContactSet<T>& out);
// The contact set of two boxes whose cores' signed distance is `d` (distanceWithin of the pair).
template <class T>
void boxContactsApart(const BoxGeometry<T>& box0, const Transform<T>& pose0, const BoxGeometry<T>& box1,
                      const Transform<T>& pose1, const BoxContactSettings<T>& settings, const DistanceResult<T>& d,
                      ContactSet<T>& out);

}  // namespace gq::detail
