#pragma once
// Internal name of the public kernels in gq/kernels/segment.h (declared there, defined in core/src).
#include "gq/kernels/segment.h"

namespace gq::detail {
using namespace kernels;
}  // namespace gq::detail
