#pragma once
// A custom shape whose support mapping and raycast are Python callables. The callables run with the GIL held
// (acquired on whatever thread the query runs); an exception they raise is kept and re-raised after the query.
#include <memory>
#include <mutex>
#include <string>

#include "common.h"
#include "gq/custom.h"

namespace gqpy {

// The first error a shape's Python callables raised since the last query that checked it.
struct CallbackErrors {
  std::mutex mutex;
  bool failed = false;
  std::string message;
  void record(const std::string& m) {
    std::lock_guard<std::mutex> lock(mutex);
    if (!failed) { failed = true; message = m; }
  }
};

// After a query touching `g`: raises RuntimeError when one of its Python callables failed.
void rethrowCallbackError(const GeometryObject& g);

}  // namespace gqpy
