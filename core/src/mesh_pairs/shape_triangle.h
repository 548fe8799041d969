#pragma once
// Internal name of the public kernels in gq/kernels/mesh.h (declared there, defined in core/src).
#include "gq/kernels/mesh.h"

namespace gq::detail {
using namespace kernels;
}  // namespace gq::detail
