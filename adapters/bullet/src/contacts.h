#pragma once
// Contact generation between two Bullet shapes seen through gq, in Bullet's conventions: normalOnB points from
// shape B to shape A, the point lies on B, and depth < 0 is penetration (pointOnA = pointOnB + normalOnB * depth).
#include "gq/query.h"
#include "shape_view.h"

namespace gq::bullet {

// A shape placed in the world: pose is the world pose of the gq geometry (Bullet object pose * view.localPose).
struct PlacedShape {
  const ShapeView* view = nullptr;
  Pose pose;
};

class ContactSink {
 public:
  virtual ~ContactSink() = default;
  // `surfaceIds` names the triangle of a mesh or heightfield involved (part -1 otherwise); `surfaceIsB` says
  // which of the two shapes it belongs to.
  virtual void add(const V3& normalOnB, const V3& pointOnB, Real depth, TriangleIds surfaceIds, bool surfaceIsB) = 0;
};

// Presents the contacts of (B, A) as contacts of (A, B).
class SwappedSink final : public ContactSink {
 public:
  explicit SwappedSink(ContactSink& inner) : inner_(inner) {}
  void add(const V3& normalOnB, const V3& pointOnB, Real depth, TriangleIds ids, bool surfaceIsB) override {
    inner_.add(-normalOnB, pointOnB + normalOnB * depth, depth, ids, !surfaceIsB);
  }

 private:
  ContactSink& inner_;
};

// Contacts closer than `threshold` (depth <= threshold), for:
//  - a convex shape A against a convex shape or plane B (signed distance, then face clipping for flat contacts);
//  - a convex shape A against a triangle mesh or heightfield B (per-triangle contacts, deepest first; of contacts
//    closer than HandOver's mergeRadius on A only the deepest, as the manifold would merge them; when one touches and
//    HandOver asks, only the touching ones, which a manifold's 4 places are for).
// How surface contacts are handed to the sink (see surfaceContacts): contacts closer than `mergeRadius` on A merge
// into the deepest; with `touchingOnly`, once one touches the ones still apart are left out. A persistent manifold
// wants both (its breaking threshold as the radius); a caller that widened the distance threshold (contactTest's
// closest-distance threshold) asked for the apart points too.
struct HandOver {
  Real mergeRadius = 0;
  bool touchingOnly = false;
};

// What a pair learned in earlier frames: GJK's warm start, whether the pair was in contact range, and the last axis
// that separated it beyond the threshold (in A's frame; zero when none), re-checked first each frame.
struct PairMemory {
  GjkCache<Real> gjk;
  V3 separatingAxis = V3::Zero();
  bool touching = false;
};

// `memory` (optional) carries what the pair learned from one frame to the next.
void convexContacts(const PlacedShape& a, const PlacedShape& b, Real threshold, ContactSink& sink,
                    PairMemory* memory = nullptr);
void surfaceContacts(const PlacedShape& a, const PlacedShape& b, Real threshold, const HandOver& handOver,
                     ContactSink& sink);

// Any supported pair in either order (the surface or plane may be A or B); false if the pair has no gq path.
bool pairContacts(const PlacedShape& a, const PlacedShape& b, Real threshold, const HandOver& handOver,
                  ContactSink& sink, PairMemory* memory = nullptr);

}  // namespace gq::bullet
