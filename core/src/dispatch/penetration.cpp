// PLACEHOLDER: every pair answers Unsupported until this family lands.
#include "gq/query.h"

namespace gq {

template <class T>
Status computePenetration(PenetrationResult<T>&, const Geometry<T>&, const Transform<T>&, const Geometry<T>&, const Transform<T>&) {
  return Status::unsupported("computePenetration is not implemented yet");
}
template Status computePenetration<float>(PenetrationResult<float>&, const Geometry<float>&, const Transform<float>&, const Geometry<float>&, const Transform<float>&);
template Status computePenetration<double>(PenetrationResult<double>&, const Geometry<double>&, const Transform<double>&, const Geometry<double>&, const Transform<double>&);

}  // namespace gq
