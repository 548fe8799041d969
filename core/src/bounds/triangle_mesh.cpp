// PLACEHOLDER
#include "bounds/bounds.h"
namespace gq::detail {
template <class T> Bounds3<T> boundsTriangleMesh(const TriangleMeshGeometry<T>&, const Transform<T>&) { return {}; }
template Bounds3<float> boundsTriangleMesh<float>(const TriangleMeshGeometry<float>&, const Transform<float>&);
template Bounds3<double> boundsTriangleMesh<double>(const TriangleMeshGeometry<double>&, const Transform<double>&);
}  // namespace gq::detail
