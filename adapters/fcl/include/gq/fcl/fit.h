#pragma once
// Opt-in: answer a triangle BVHModel by its gq::fitShape fit (gq/fit.h) instead of its triangles.
//
// With Options::meshFitting set, collide and distance replace each side that is a finished triangle
// BVHModel<OBBRSS> by the fit of its triangles under those settings: the cheapest allowed representation whose
// certified bound (two-sided Hausdorff distance of the surfaces) is within the tolerance, containing the mesh by
// default. The fit is cooked on first use and cached per model and settings (forgetGeometry / clearGeometryCache
// drop it). A query then runs once per fitted part, each part an FCL shape (Sphere, Capsule, Box, Cylinder, Convex)
// at its pose in the model's frame; contacts and nearest points name the model (o1/o2) with b1/b2 = Contact::NONE,
// and the distance is the least over the parts. A model the fitter rejects (see fitShape's statuses) or whose fit
// is only a warning (no allowed representation within the tolerance) is answered by its triangles, as without the
// option. Off by default: Options::meshFitting is null.
#include <cstdint>
#include <memory>
#include <vector>

#include <fcl/geometry/collision_geometry.h>

#include "gq/fit.h"
#include "gq/status.h"

namespace gq::fcl {

// The fitter's settings for Options::meshFitting (FitOptions without the cost measurement).
struct MeshFitting {
  double tolerance = 0.0;  // absolute, in the model's units; > 0
  FitRepresentationSet allowed = kAllFitRepresentations;
  std::uint32_t maxParts = 16;
  bool contain = true;  // the fit encloses the mesh: a query never misses a contact of the mesh
};

// One part of a fit: an FCL shape at `pose` in the model's frame.
template <typename S> struct FittedPart {
  std::shared_ptr<const ::fcl::CollisionGeometry<S>> geometry;
  ::fcl::Transform3<S> pose = ::fcl::Transform3<S>::Identity();
};

// A model's fit: status of the fit (ok: `parts` stand for the model), the representation and its certified bound.
template <typename S> struct MeshFit {
  Status status;
  FitRepresentation representation = FitRepresentation::Mesh;
  S errorBound = S(0);
  std::vector<FittedPart<S>> parts;
};

// The cached fit of `geometry` under `fitting` (cooked on first call): InvalidArgument for a geometry that is not a
// finished triangle BVHModel<OBBRSS>, else fitShape's status. The reference stays valid until the geometry is
// forgotten or the cache cleared.
template <typename S> const MeshFit<S>& meshFit(const ::fcl::CollisionGeometry<S>* geometry, const MeshFitting& fitting);

}  // namespace gq::fcl
