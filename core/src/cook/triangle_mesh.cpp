// PLACEHOLDER
#include "gq/cooking.h"
namespace gq {
template <class T>
Status cookTriangleMesh(const std::vector<Vec3<T>>&, const std::vector<TriangleIndices>&, std::shared_ptr<const TriangleMesh<T>>&, MeshCookReport*) {
  return Status::unsupported("triangle mesh cooking not implemented yet");
}
template <class T> Status cookHeightField(const HeightFieldDesc<T>&, std::shared_ptr<const HeightField<T>>&) {
  return Status::unsupported("heightfield cooking not implemented yet");
}
template <class T> Status loadMeshFile(const std::string&, MeshData<T>&, bool) { return Status::unsupported("mesh files not implemented yet"); }
template Status cookTriangleMesh<float>(const std::vector<Vec3<float>>&, const std::vector<TriangleIndices>&, std::shared_ptr<const TriangleMesh<float>>&, MeshCookReport*);
template Status cookTriangleMesh<double>(const std::vector<Vec3<double>>&, const std::vector<TriangleIndices>&, std::shared_ptr<const TriangleMesh<double>>&, MeshCookReport*);
template Status cookHeightField<float>(const HeightFieldDesc<float>&, std::shared_ptr<const HeightField<float>>&);
template Status cookHeightField<double>(const HeightFieldDesc<double>&, std::shared_ptr<const HeightField<double>>&);
template Status loadMeshFile<float>(const std::string&, MeshData<float>&, bool);
template Status loadMeshFile<double>(const std::string&, MeshData<double>&, bool);
}  // namespace gq
