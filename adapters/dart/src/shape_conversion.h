#pragma once
// DART shapes as gq geometries (docs/dart.md, "Shapes").
#include <gq/shape.h>
#include <gq/status.h>
#include <gq/transform.h>

namespace dart {
namespace dynamics {
class Shape;
}  // namespace dynamics
}  // namespace dart

namespace gq {
namespace dart {

// A DART shape converted: the prepared gq shape and where its frame sits in the DART shape's frame (gq's capsule,
// cylinder and cone run along local X, DART's along Z; gq's plane is x = 0, DART's n.x = offset; gq's heightfield
// rows run from a corner, DART's heightmap is centred).
struct ConvertedShape {
  Shape<double> shape;
  Transform<double> offset;
};

// Converts `shape`; on failure (a shape type gq does not model, or a shape gq rejects: empty mesh, zero size) returns
// the Status and leaves `out` unchanged.
Status convertShape(const ::dart::dynamics::Shape& shape, ConvertedShape& out);

}  // namespace dart
}  // namespace gq
