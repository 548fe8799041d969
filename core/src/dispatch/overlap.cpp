// PLACEHOLDER: every pair answers Unsupported until this family lands.
#include "gq/query.h"

namespace gq {

template <class T>
Status overlap(const Geometry<T>&, const Transform<T>&, const Geometry<T>&, const Transform<T>&, bool&) {
  return Status::unsupported("overlap is not implemented yet");
}
template Status overlap<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&, const Transform<float>&, bool&);
template Status overlap<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&, const Transform<double>&, bool&);

}  // namespace gq
