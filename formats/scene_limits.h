#pragma once
// Limits of the numbers a scene carries to the shooter and the renderer, shared by the command
// lines, the scene card reader and the validator, so a default from a file or card is held to
// the same bounds as the option it stands in for.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

namespace kdpm {

inline constexpr std::uint32_t kMaxPhotons = 1u << 30;  // photon paths per shot
inline constexpr std::uint32_t kMaxBounces = 255;       // bounces per photon path
inline constexpr std::uint32_t kMinEstimateK = 1;        // photons per radiance estimate: --k of both tools
inline constexpr std::uint32_t kMaxEstimateK = 256;      // (kMaxGatherK)

// A photon search radius below this fraction of the scene's diagonal finds no photons at all
// (the image loses its photon light without a word); 0 stands for "automatic" or "none".
inline constexpr double kMinRadiusFraction = 1e-6;

inline double bounds_diagonal(const float (&lo)[3], const float (&hi)[3]) {
    double d = 0.0;
    for (int a = 0; a < 3; ++a) d += (double(hi[a]) - lo[a]) * (double(hi[a]) - lo[a]);
    return std::sqrt(d);
}

// "R is below F of the D diagonal" with the numbers in %g form, for messages.
inline std::string radius_limit_text(double radius, const float (&lo)[3], const float (&hi)[3]) {
    char text[128];
    std::snprintf(text, sizeof text, "%g is below %g of the bounds' diagonal %g", radius, kMinRadiusFraction,
                  bounds_diagonal(lo, hi));
    return text;
}

// True for a positive radius too small for a scene with these bounds.
inline bool radius_too_small(double radius, const float (&lo)[3], const float (&hi)[3]) {
    return radius > 0.0 && radius < kMinRadiusFraction * bounds_diagonal(lo, hi);
}

}  // namespace kdpm
