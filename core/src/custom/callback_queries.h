#pragma once
// Internal name of the public kernels in gq/kernels/custom.h (declared there, defined in core/src).
#include "gq/kernels/custom.h"

namespace gq::detail {
using namespace kernels;
}  // namespace gq::detail
