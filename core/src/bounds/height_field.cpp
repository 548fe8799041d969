// PLACEHOLDER
#include "bounds/bounds.h"
namespace gq::detail {
template <class T> Bounds3<T> boundsHeightField(const HeightFieldGeometry<T>&, const Transform<T>&) { return {}; }
template Bounds3<float> boundsHeightField<float>(const HeightFieldGeometry<float>&, const Transform<float>&);
template Bounds3<double> boundsHeightField<double>(const HeightFieldGeometry<double>&, const Transform<double>&);
}  // namespace gq::detail
