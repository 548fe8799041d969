#pragma once
// Contact features for multi-point manifolds: the flat face of a box, hull or plane that supports a contact
// (reference), the points of the other shape that rest on it (incident: a face, a cylinder cap or side line, a
// capsule's side segment), and the clipping of the incident points to the reference face (Sutherland-Hodgman).
#include <array>

#include "contacts.h"

namespace gq::bullet {

// A face counts as supporting a contact when its normal is within this cosine of the contact normal (~8 degrees).
inline constexpr Real kFaceAlignmentCos = Real(0.99);
// Points sampled on a cylinder cap's rim (a rim is not a polygon; four points span its support).
inline constexpr int kCapRimPoints = 4;
inline constexpr int kMaxFeaturePoints = 64;

struct Feature {
  std::array<V3, kMaxFeaturePoints> points;
  int count = 0;
  V3 normal = V3::Zero();  // reference faces: outward unit normal
  V3 origin = V3::Zero();  // reference faces: a point of the face plane
  bool unbounded = false;  // a plane: nothing to clip against
  // A box face: the rectangle centre + x u + y w with |x| <= hu, |y| <= hw (clipped in its own 2D frame).
  bool rectangle = false;
  V3 centre = V3::Zero(), u = V3::Zero(), w = V3::Zero();
  Real hu = Real(0), hw = Real(0);
};

// The face of a box, convex hull or plane whose outward normal is within kFaceAlignmentCos of `dir` (unit).
bool referenceFace(const PlacedShape& s, const V3& dir, Feature& face);
// The points of `s` farthest along `dir` (unit) when they form a face, a cap or a segment; false for a single point.
bool incidentFeature(const PlacedShape& s, const V3& dir, Feature& feature);
// Clips the incident polygon (or segment, or point) to the prism over the reference face; returns the count left.
int clipToFace(const Feature& reference, Feature& incident);

}  // namespace gq::bullet
