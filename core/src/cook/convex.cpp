// PLACEHOLDER
#include "gq/cooking.h"
namespace gq {
template <class T>
Status cookConvexMesh(const std::vector<Vec3<T>>&, std::shared_ptr<const ConvexMesh<T>>&, const ConvexCookParams&) {
  return Status::unsupported("convex cooking not implemented yet");
}
template Status cookConvexMesh<float>(const std::vector<Vec3<float>>&, std::shared_ptr<const ConvexMesh<float>>&, const ConvexCookParams&);
template Status cookConvexMesh<double>(const std::vector<Vec3<double>>&, std::shared_ptr<const ConvexMesh<double>>&, const ConvexCookParams&);
}  // namespace gq
