#pragma once
// Constants that the file contents are defined with (a light's power is pi * area * mean
// radiance, geometry_layout.h), so that the builders and the runtime share one definition.
namespace kdpm {

inline constexpr float kPi = 3.14159265358979323846f;

}  // namespace kdpm
