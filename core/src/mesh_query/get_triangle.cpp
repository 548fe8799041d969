// PLACEHOLDER
#include "gq/mesh_query.h"
namespace gq {
template <class T>
Status getTriangle(const TriangleMeshGeometry<T>&, const Transform<T>&, std::uint32_t, Triangle<T>&, std::uint32_t*) {
  return Status::unsupported("getTriangle not implemented yet");
}
template Status getTriangle<float>(const TriangleMeshGeometry<float>&, const Transform<float>&, std::uint32_t, Triangle<float>&, std::uint32_t*);
template Status getTriangle<double>(const TriangleMeshGeometry<double>&, const Transform<double>&, std::uint32_t, Triangle<double>&, std::uint32_t*);
}  // namespace gq
