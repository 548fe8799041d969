#pragma once
// The optional query callbacks of custom geometry (gq/custom.h): the dispatch tables ask them before running the
// generic kernel of a custom cell. Poses are handed over relative to the custom shape and answers are brought back
// to the caller's frame here, once for every cell.
#include "gq/custom.h"
#include "gq/geometry.h"
#include "gq/query.h"
#include "gq/status.h"
#include "gq/transform.h"

namespace gq::kernels {

// geom0's callbacks first (if custom), then geom1's. Returns whether one answered (else `overlapping` is untouched).
template <class T>
bool customOverlap(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                   bool& overlapping);

// Same order for penetration; `answered` false: neither answered, outputs untouched. `direction` moves geom0 (the
// façade's convention), whichever shape answered. A non-finite, negative or non-unit answer is an InternalError
// naming the callback.
template <class T>
Status customPenetration(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                         bool& answered, bool& penetrating, Vec3<T>& direction, T& depth);

// Same order for distance; `answered` false: neither answered, `out` untouched. The answer is brought to the
// caller's frame and order (a custom geom1's answer flipped: witnesses exchanged, normal negated). A non-finite
// answer or a normal that is not unit is an InternalError naming the callback.
template <class T>
Status customDistance(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                      bool& answered, DistanceResult<T>& out);

}  // namespace gq::kernels
