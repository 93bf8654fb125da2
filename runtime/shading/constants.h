#pragma once
// The constants of light-transport math, one definition each.
namespace kdpm {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 1.0f / kPi;

}  // namespace kdpm
