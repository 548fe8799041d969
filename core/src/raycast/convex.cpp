// PLACEHOLDER: replaced by the real kernel.
#include "raycast/raycast.h"

namespace gq::detail {

template <class T>
std::uint32_t raycastConvex(const ConvexMeshGeometry<T>&, const Transform<T>&, const RayQuery<T>&, RaycastHit<T>*) {
  return 0;
}

template std::uint32_t raycastConvex<float>(const ConvexMeshGeometry<float>&, const Transform<float>&, const RayQuery<float>&, RaycastHit<float>*);
template std::uint32_t raycastConvex<double>(const ConvexMeshGeometry<double>&, const Transform<double>&, const RayQuery<double>&, RaycastHit<double>*);

}  // namespace gq::detail
