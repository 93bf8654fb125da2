#pragma once
// Limits of the numbers a scene carries to the shooter and the renderer, shared by the command
// lines, the scene card reader and the validator, so a default from a file or card is held to
// the same bounds as the option it stands in for.
#include <cstdint>

namespace kdpm {

inline constexpr std::uint32_t kMaxPhotons = 1u << 30;  // photon paths per shot
inline constexpr std::uint32_t kMaxBounces = 255;       // bounces per photon path
inline constexpr std::uint32_t kMaxGatherK = 256;       // photons per radiance estimate

}  // namespace kdpm
