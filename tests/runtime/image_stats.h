#pragma once
// The mode comparisons' image statistics, under the names the tests use (they live in the
// runtime so that kdpm-bench-quality measures with the same definitions).
#include "runtime/render/image/image_stats.h"

namespace kdpm::test {
using kdpm::mean_of;
using kdpm::relative_mse;
}  // namespace kdpm::test
