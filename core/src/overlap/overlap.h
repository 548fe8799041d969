#pragma once
// Internal name of the public kernels in gq/kernels/overlap.h (declared there, defined in core/src).
#include "gq/kernels/overlap.h"

namespace gq::detail {
using namespace kernels;
}  // namespace gq::detail
