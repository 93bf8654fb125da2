#pragma once
// What a final-gather ray reads at its first diffuse hit: the light leaving that surface toward
// the gathering point. Three ways, of decreasing speed and bias:
//   irradiance-map  the value precomputed at the nearest chosen photon of the .kdp's irradiance
//                   map on the hit's surface (Christensen 1999; the k-nearest estimate where the
//                   .kdp has none or no chosen photon is near), the default;
//   estimate        the global map's k-nearest estimate at the hit itself;
//   path            a path traced on from the hit (next-event estimation, roulette): no photon
//                   is read, so what stays wrong in the image is the gather's, not the map's
//                   (the error analysis of kdpm-bench-quality, and a slow exact mode).
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace kdpm {

enum class GatherLookup : std::uint8_t { irradiance_map, estimate, path };

inline const char* gather_lookup_name(GatherLookup lookup) {
    switch (lookup) {
        case GatherLookup::irradiance_map: return "irradiance-map";
        case GatherLookup::estimate: return "estimate";
        case GatherLookup::path: return "path";
    }
    return "?";
}

// Throws std::invalid_argument naming the choices.
inline GatherLookup parse_gather_lookup(std::string_view text) {
    for (GatherLookup l : {GatherLookup::irradiance_map, GatherLookup::estimate, GatherLookup::path})
        if (text == gather_lookup_name(l)) return l;
    throw std::invalid_argument("expected irradiance-map, estimate or path, got '" + std::string(text) + "'");
}

}  // namespace kdpm
