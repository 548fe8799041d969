#pragma once
// Internal name of the public kernels in gq/kernels/vector.h (declared there, defined in core/src).
#include "gq/kernels/vector.h"

namespace gq::detail {
using namespace kernels;
}  // namespace gq::detail
