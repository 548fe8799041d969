// PLACEHOLDER
#include "gq/cooking.h"
namespace gq {
template <class T> Status loadMeshFile(const std::string&, MeshData<T>&, bool) { return Status::unsupported("mesh files not implemented yet"); }
template Status loadMeshFile<float>(const std::string&, MeshData<float>&, bool);
template Status loadMeshFile<double>(const std::string&, MeshData<double>&, bool);
}  // namespace gq
