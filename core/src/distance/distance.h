#pragma once
// Internal name of the public kernels in gq/kernels/distance.h (declared there, defined in core/src).
#include "gq/kernels/distance.h"

namespace gq::detail {
using namespace kernels;
}  // namespace gq::detail
