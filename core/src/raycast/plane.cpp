// PLACEHOLDER: replaced by the real kernel.
#include "raycast/raycast.h"

namespace gq::detail {

template <class T>
std::uint32_t raycastPlane(const PlaneGeometry<T>&, const Transform<T>&, const RayQuery<T>&, RaycastHit<T>*) {
  return 0;
}

template std::uint32_t raycastPlane<float>(const PlaneGeometry<float>&, const Transform<float>&, const RayQuery<float>&, RaycastHit<float>*);
template std::uint32_t raycastPlane<double>(const PlaneGeometry<double>&, const Transform<double>&, const RayQuery<double>&, RaycastHit<double>*);

}  // namespace gq::detail
