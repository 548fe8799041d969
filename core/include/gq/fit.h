#pragma once
// Fitting: the cheapest shape that stands for a triangle mesh within a stated error, with a certified bound.
//
// fitShape tries the allowed representations from the cheapest (sphere, capsule, box, cylinder, simplified hull,
// convex hull, convex decomposition, the mesh itself) and returns the first whose certified error bound is within
// the tolerance. The bound is an upper bound of the two-sided Hausdorff distance between the mesh surface and the
// surface of the fitted solid, computed from the geometry (convexity and Lipschitz arguments, docs/fit.md), never
// from samples. With `contain`, every fit encloses every mesh vertex (and so the mesh, the fits being convex or
// unions of convex parts that each enclose their piece), for conservative safety checks.
#include <cstdint>
#include <utility>
#include <vector>

#include "gq/cooking.h"
#include "gq/geometry.h"
#include "gq/status.h"
#include "gq/transform.h"

namespace gq {

// In the order fitShape tries them (cheapest query first).
enum class FitRepresentation : std::uint8_t {
  Sphere,
  Capsule,
  Box,
  Cylinder,             // a CustomGeometry (gq/custom_shapes.h), axis local X
  SimplifiedHull,       // a convex hull of few vertices (ConvexMeshGeometry)
  ConvexHull,           // the convex hull of the vertices (ConvexMeshGeometry)
  ConvexDecomposition,  // several ConvexMeshGeometry parts
  Mesh,                 // the mesh itself (TriangleMeshGeometry): error 0
};
inline constexpr std::size_t kFitRepresentationCount = 8;
const char* toString(FitRepresentation representation);

// A set of representations (bit i = FitRepresentation i).
using FitRepresentationSet = std::uint32_t;
inline constexpr FitRepresentationSet fitBit(FitRepresentation r) { return FitRepresentationSet(1u) << unsigned(r); }
inline constexpr FitRepresentationSet kAllFitRepresentations = (1u << kFitRepresentationCount) - 1u;
inline constexpr FitRepresentationSet kFitPrimitives = fitBit(FitRepresentation::Sphere) |
                                                       fitBit(FitRepresentation::Capsule) |
                                                       fitBit(FitRepresentation::Box) |
                                                       fitBit(FitRepresentation::Cylinder);

template <class T> struct FitOptions {
  T tolerance = T(0);  // absolute, in the mesh's units; > 0
  FitRepresentationSet allowed = kAllFitRepresentations;
  std::uint32_t maxParts = 16;    // convex decomposition: at most this many parts (>= 1)
  bool contain = false;           // every fit must enclose every mesh vertex (conservative)
  bool measureCost = true;        // time overlap queries against the fit and the mesh (FitResult::relativeCost)
  // The bound's effort: surface patches evaluated per representation before the bound is reported as it stands
  // (still an upper bound, maybe looser than needed to prove the tolerance).
  std::uint32_t maxBoundPatches = 400000;
};

// One representation tried: its certified bound (infinity when it could not be built) and its number of parts.
template <class T> struct FitCandidate {
  FitRepresentation representation = FitRepresentation::Mesh;
  T errorBound = T(0);
  std::uint32_t parts = 0;
  std::uint32_t vertices = 0;  // hull vertices over all parts (0 for primitives and the mesh)
  // A one-part fit's volume over the volume of the mesh's convex hull (0 for several parts and the mesh). With
  // `contain`, the least-volume shape of the same kind enclosing the mesh encloses the hull too, so this is also an
  // upper bound of the fit's volume over that optimum: its stated optimality gap (1: optimal).
  T volumeRatio = T(0);
};

template <class T> struct FitResult {
  std::vector<std::pair<Geometry<T>, Transform<T>>> parts;  // in the mesh's frame
  T errorBound = T(0);  // certified upper bound of the two-sided Hausdorff distance of the surfaces
  FitRepresentation representation = FitRepresentation::Mesh;
  // Measured time of an overlap query (a sphere at fixed poses around the mesh) against the parts, over the same
  // against the cooked mesh; 0 when not measured (FitOptions::measureCost false).
  double relativeCost = 0.0;
  std::vector<FitCandidate<T>> candidates;  // every representation tried, in the order tried
};

// Fits `mesh` (vertices and triangles in one frame) by the cheapest allowed representation whose certified bound is
// within options.tolerance. Fails with InvalidArgument for a tolerance <= 0 or not finite, non-finite vertices,
// indices out of range, maxParts 0 or no representation allowed; DegenerateMesh for an empty mesh or one with no
// triangle of positive area, or all vertices in one plane. When no allowed representation is proven within the
// tolerance, `result` holds the one with the smallest bound and the status is a Warning saying so (check
// result.errorBound). Deterministic: the same input gives the same parts and bounds (relativeCost is a measured
// time and varies).
template <class T> Status fitShape(const MeshData<T>& mesh, const FitOptions<T>& options, FitResult<T>& result);

// The certified bound of any fit given as parts (sphere, capsule, box, convex mesh or cylinder, in the mesh's frame)
// against `mesh`: the two-sided Hausdorff distance between the mesh surface and the boundary of the union of the
// parts, from above. `target` stops refinement once the bound is proven at most max(target, the largest distance
// seen); 0 refines to the patch budget.
template <class T>
Status certifyFit(const MeshData<T>& mesh, const std::vector<std::pair<Geometry<T>, Transform<T>>>& parts, T target,
                  std::uint32_t maxPatches, T& errorBound);

}  // namespace gq
