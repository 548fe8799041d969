#pragma once
// Internal name of the public kernels in gq/kernels/gjk.h (declared there, defined in core/src).
#include "gq/kernels/gjk.h"

namespace gq::detail {
using namespace kernels;
}  // namespace gq::detail
