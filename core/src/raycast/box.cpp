// PLACEHOLDER: replaced by the real kernel.
#include "raycast/raycast.h"

namespace gq::detail {

template <class T>
std::uint32_t raycastBox(const BoxGeometry<T>&, const Transform<T>&, const RayQuery<T>&, RaycastHit<T>*) {
  return 0;
}

template std::uint32_t raycastBox<float>(const BoxGeometry<float>&, const Transform<float>&, const RayQuery<float>&, RaycastHit<float>*);
template std::uint32_t raycastBox<double>(const BoxGeometry<double>&, const Transform<double>&, const RayQuery<double>&, RaycastHit<double>*);

}  // namespace gq::detail
