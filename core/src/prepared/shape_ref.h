#pragma once
// What a query's shared code path reads from a shape: the geometry and its feature radius. A prepared Shape gives
// both as stored; a Geometry<T> call validates the geometry and computes the radius, then runs the same code.
#include <cstdint>
#include <mutex>

#include "common/pair_frame.h"
#include "common/validate.h"
#include "gq/shape.h"

namespace gq::detail {

template <class T> struct ShapeRef {
  const Geometry<T>& geom;
  T radius;  // featureRadius(geom)

  GeometryType type() const { return geom.type(); }
  template <class G> const G& get() const { return geom.template get<G>(); }
};

template <class T> ShapeRef<T> shapeRef(const Geometry<T>& g) { return {g, featureRadius(g)}; }

// Lazily built data of a shape (gq/shape.h): built once under std::call_once, then read without a lock.
template <class T> struct ShapeDerived {
  std::once_flag once;
  ShapeBalls<T> balls;
  const void* supportStartTable = nullptr;  // the hull's shared start table (gjk/support_table.h), if it has one
  std::uint32_t builds = 0;                 // how many times the data was built (1 once built): a test reads it
};

template <class T> struct ShapeAccess {
  static ShapeRef<T> ref(const Shape<T>& s) { return {s.geometry_, s.featureRadius_}; }
  // The pair queries' rejection of the shape (empty, or too large for them).
  static Problem pairProblem(const Shape<T>& s) {
    return s.pairProblem_ ? Problem{s.pairCode_, s.pairProblem_} : Problem{};
  }
  static bool made(const Shape<T>& s) { return s.made_; }
  // Both shapes go to a pair query's table once their poses are valid.
  static bool pairReady(const Shape<T>& s0, const Shape<T>& s1) { return s0.pairReady_ & s1.pairReady_; }
  static bool nonConvexCustom(const Shape<T>& s) { return s.nonConvexCustom_; }
  static const ShapeDerived<T>* derived(const Shape<T>& s) { return s.derived_.get(); }
  // A made triangle-mesh shape (raycast takes the mesh kernel directly), and whether its scale is the identity.
  static bool rayMesh(const Shape<T>& s) { return s.rayMesh_; }
  static bool rayMeshUnscaled(const Shape<T>& s) { return s.rayMeshUnscaled_; }
};

inline const char* emptyShapeText() { return "the shape is empty (not made by Shape::make)"; }

}  // namespace gq::detail
