#pragma once
// A Bullet collision shape seen as a gq geometry: the geometry, its pose in the shape's frame, and the rounding
// radius Bullet adds outside it (hull and cone margins). Boxes and cylinders keep their margin inside (their gq
// size is Bullet's size with margin); a sphere's or capsule's margin is its radius, already in the geometry.
#include <cstdint>
#include <memory>
#include <vector>

#include <BulletCollision/CollisionShapes/btCollisionShape.h>

#include "bt_convert.h"
#include "gq/geometry.h"
#include "gq/shape.h"
#include "support.h"

namespace gq::bullet {

enum class ShapeKind : std::uint8_t { Convex, Plane, Mesh, HeightField };

// Maps a gq triangle index back to Bullet's (partId, triangleIndex) of the shape.
struct TriangleIds {
  int part = -1;
  int index = -1;
};

struct ShapeView {
  Geometry<Real> geom;
  Pose localPose;          // gq geometry frame in the Bullet shape frame
  Real margin = Real(0);   // rounding radius outside the geometry
  Real size = Real(1);     // a length scale of the shape (tolerances are relative to it)
  ShapeKind kind = ShapeKind::Convex;
  // Meshes: first gq (input) triangle index of each Bullet sub-part; heightfields: columns of the gq grid and
  // whether gq rows are Bullet's x index (else its second index).
  std::shared_ptr<const std::vector<std::uint32_t>> partStarts;
  std::uint32_t heightFieldColumns = 0;
  bool heightFieldRowsAreX = true;
  // The geometry prepared once (validated, derived data kept) by the owner of a long-lived view; null otherwise.
  const Shape<Real>* prepared = nullptr;

  TriangleIds triangleIds(std::uint32_t gqTriangle) const;
  bool isPolytope() const {
    return geom.type() == GeometryType::Box || geom.type() == GeometryType::ConvexMesh;
  }
};

// Whether gq models this proxy type at all (a given shape may still be refused by viewShape).
bool isGqShapeType(int proxyType);
bool isGqConvexType(int proxyType);

// Gq: `view` is filled. Bullet: valid parameters gq does not model, Bullet's algorithms stay in charge. Invalid:
// bad input (a null shape, non-finite numbers, sizes or scaling factors <= 0 or non-finite, a hull without points,
// an empty or degenerate mesh, an absurd heightfield): nothing is reported for the shape. `view` is unspecified
// unless Gq.
Support viewShape(const btCollisionShape* shape, ShapeView& view);

}  // namespace gq::bullet
