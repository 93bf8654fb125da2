#pragma once
// The constants of light-transport math, one definition each (pi itself is defined where the
// file format needs it).
#include "formats/math_constants.h"

namespace kdpm {

inline constexpr float kInvPi = 1.0f / kPi;

}  // namespace kdpm
