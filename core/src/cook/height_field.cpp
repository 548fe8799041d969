// PLACEHOLDER
#include "gq/cooking.h"
namespace gq {
template <class T> Status cookHeightField(const HeightFieldDesc<T>&, std::shared_ptr<const HeightField<T>>&) {
  return Status::unsupported("heightfield cooking not implemented yet");
}
template Status cookHeightField<float>(const HeightFieldDesc<float>&, std::shared_ptr<const HeightField<float>>&);
template Status cookHeightField<double>(const HeightFieldDesc<double>&, std::shared_ptr<const HeightField<double>>&);
}  // namespace gq
