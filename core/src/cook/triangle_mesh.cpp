// PLACEHOLDER
#include "gq/cooking.h"
namespace gq {
template <class T>
Status cookTriangleMesh(const std::vector<Vec3<T>>&, const std::vector<TriangleIndices>&, std::shared_ptr<const TriangleMesh<T>>&, MeshCookReport*) {
  return Status::unsupported("triangle mesh cooking not implemented yet");
}
template Status cookTriangleMesh<float>(const std::vector<Vec3<float>>&, const std::vector<TriangleIndices>&, std::shared_ptr<const TriangleMesh<float>>&, MeshCookReport*);
template Status cookTriangleMesh<double>(const std::vector<Vec3<double>>&, const std::vector<TriangleIndices>&, std::shared_ptr<const TriangleMesh<double>>&, MeshCookReport*);
}  // namespace gq
