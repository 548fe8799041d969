#pragma once
// gq::fcl::collide and gq::fcl::distance: FCL 0.7's entry points with FCL's signatures and conventions, answered
// by gq. They take real ::fcl objects (CollisionObject, or CollisionGeometry + Transform3) in float and double.
//
// Conventions kept from FCL (see docs/fcl.md for the full list):
//  - results are appended to, never cleared; collide returns result.numContacts();
//  - contact normal points from o1 to o2, penetration_depth > 0, positions in world frame, b1/b2 = triangle ids of
//    BVHModel sides (Contact::NONE for shapes); at most num_max_contacts contacts are held;
//  - without enable_contact a colliding pair adds one Contact(o1, o2, b1, b2) per primitive pair (as FCL does);
//  - DistanceResult::update semantics: min_distance, nearest points and b1/b2 change only when the new distance is
//    smaller than the current min_distance (hosts pre-seed it);
//  - pairs gq cannot answer run through ::fcl::collide / ::fcl::distance unchanged (counted in adapterCounters()).
// Converted geometry is cached per CollisionGeometry*; see docs/fcl.md for when a changed BVHModel is re-converted.
#include <cstddef>
#include <cstdint>

#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/collision_request.h>
#include <fcl/narrowphase/collision_result.h>
#include <fcl/narrowphase/distance_request.h>
#include <fcl/narrowphase/distance_result.h>

namespace gq::fcl {

struct MeshFitting;  // gq/fcl/fit.h

// Opt-in corrections. By default a contact (enable_contact) is FCL's own for the pairs FCL computes with libccd's
// MPR, so hosts tuned to FCL's numbers see no change; booleans and distances are always gq's. Two boxes' contacts
// are gq's contact set in FCL's size and placement in every mode (its deepest point the exact minimum translation).
struct Options {
  // The true minimum-translation penetration (exact SAT / EPA) for every pair. FCL's MPR path returns the portal
  // direction instead, wrong by up to sqrt(3) in depth for a cube corner (FCL bug fcl#545).
  bool minimumTranslation = false;
  // Accepted for hosts that set it; box-box contacts are gq's in every mode, so a box inside another box with
  // touching faces gets the exact depth, where FCL's box-box routine reports 1.0 or 0 depending on the boxes'
  // lengths (FCL bug fcl#628).
  bool exactContainedBoxDepth = false;
  // Triangle BVHModel<OBBRSS> sides answered by their gq::fitShape fit under these settings (gq/fcl/fit.h); null:
  // by their triangles.
  const MeshFitting* meshFitting = nullptr;
};

template <typename S>
std::size_t collide(const ::fcl::CollisionObject<S>* o1, const ::fcl::CollisionObject<S>* o2,
                    const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result);
template <typename S>
std::size_t collide(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                    const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                    const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result);
template <typename S>
std::size_t collide(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                    const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                    const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result,
                    const Options& options);

template <typename S>
std::size_t collide(const ::fcl::CollisionObject<S>* o1, const ::fcl::CollisionObject<S>* o2,
                    const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result,
                    const Options& options);

template <typename S>
S distance(const ::fcl::CollisionObject<S>* o1, const ::fcl::CollisionObject<S>* o2,
           const ::fcl::DistanceRequest<S>& request, ::fcl::DistanceResult<S>& result);
template <typename S>
S distance(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
           const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
           const ::fcl::DistanceRequest<S>& request, ::fcl::DistanceResult<S>& result);
// Of the options distance reads only meshFitting: distances and nearest points are gq's own in every contact mode.
template <typename S>
S distance(const ::fcl::CollisionObject<S>* o1, const ::fcl::CollisionObject<S>* o2,
           const ::fcl::DistanceRequest<S>& request, ::fcl::DistanceResult<S>& result, const Options& options);
template <typename S>
S distance(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
           const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
           const ::fcl::DistanceRequest<S>& request, ::fcl::DistanceResult<S>& result, const Options& options);

// How calls were answered on this thread since the last reset (diagnostics and tests).
struct AdapterCounters {
  std::uint64_t gq = 0;        // answered by gq
  std::uint64_t fallback = 0;  // handed to ::fcl (unsupported pair, gq status not ok, or an FCL-computed contact)
};
AdapterCounters adapterCounters();
void resetAdapterCounters();

// The geometry cache: forget one geometry (call it before destroying a geometry whose address may be reused, or
// after editing a BVHModel/Convex in place), or everything.
template <typename S> void forgetGeometry(const ::fcl::CollisionGeometry<S>* geometry);
void clearGeometryCache();

}  // namespace gq::fcl
