#pragma once
// A backend answers parsed cases. gq is the reference; fcl, bullet, libccd and embree backends plug in beside it
// by adding a factory to backend_registry.cpp, without touching the others.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "case.h"
#include "result.h"

namespace gq::cases {

class Backend {
 public:
  virtual ~Backend() = default;
  virtual const char* name() const = 0;
  // Runs the query `repeat` (>= 1) times and reports the last answer with the median time of one run.
  // Never throws; a case the backend cannot answer gives Result::failure("unsupported: ...").
  virtual Result run(const Case& c, int repeat) = 0;
};

using BackendFactory = std::function<std::unique_ptr<Backend>()>;

// The names --backend accepts, in registry order.
std::vector<std::string> backendNames();
// nullptr for an unknown name.
std::unique_ptr<Backend> makeBackend(const std::string& name);

}  // namespace gq::cases
