#include <utility>

#include "backend.h"
#include "bullet_forward.h"
#include "embree_backend.h"
#include "fcl_backend.h"
#include "gq_backend.h"
#include "libccd_backend.h"

// The adapters' rows (gq through ::fcl types, gq through Bullet's world), defined by CMake when the adapters are built.
#ifdef GQ_HAVE_FCL_ADAPTER_BACKEND
#include "gq_fcl_backend.h"
#endif
#ifdef GQ_HAVE_BULLET_ADAPTER_BACKEND
#include "gq_bullet_forward.h"
#endif

namespace gq::cases {
namespace {

// One entry per backend; native backends (fcl, bullet, libccd, embree) add theirs here.
const std::vector<std::pair<std::string, BackendFactory>>& registry() {
  static const std::vector<std::pair<std::string, BackendFactory>> entries = {
      {"gq", [] { return std::unique_ptr<Backend>(new GqBackend()); }},
      {"fcl", [] { return std::unique_ptr<Backend>(new FclBackend(FclSolver::Libccd)); }},
      {"fcl-indep", [] { return std::unique_ptr<Backend>(new FclBackend(FclSolver::Indep)); }},
      {"libccd", [] { return std::unique_ptr<Backend>(new LibccdBackend(CcdPenetration::Gjk)); }},
      {"libccd-mpr", [] { return std::unique_ptr<Backend>(new LibccdBackend(CcdPenetration::Mpr)); }},
      {"embree", [] { return std::unique_ptr<Backend>(new EmbreeBackend()); }},
      {"bullet", [] { return std::unique_ptr<Backend>(new BulletForwardingBackend()); }},
#ifdef GQ_HAVE_FCL_ADAPTER_BACKEND
      {"gq-fcl", [] { return std::unique_ptr<Backend>(new GqFclBackend()); }},
#endif
#ifdef GQ_HAVE_BULLET_ADAPTER_BACKEND
      {"gq-bullet", [] { return std::unique_ptr<Backend>(new GqBulletForwardingBackend()); }},
#endif
  };
  return entries;
}

}  // namespace

std::vector<std::string> backendNames() {
  std::vector<std::string> names;
  for (const auto& entry : registry()) names.push_back(entry.first);
  return names;
}

std::unique_ptr<Backend> makeBackend(const std::string& name) {
  for (const auto& entry : registry())
    if (entry.first == name) return entry.second();
  return nullptr;
}

}  // namespace gq::cases
