#pragma once
// Turns linear radiance into a displayable image: exposure, optional bloom, tone mapping and
// the sRGB transfer curve. Per-pixel work runs through the CPU backend (deterministic).
#include <string_view>

#include "runtime/render/image/image.h"

namespace kdpm {

enum class ToneMap { none, reinhard, aces };
ToneMap parse_tone_map(std::string_view text);  // throws std::invalid_argument

// The exposure range of the tools' --exposure and of the viewer's keys, in stops.
inline constexpr float kMaxExposureStops = 32.0f;

struct PostSettings {
    float exposure_stops = 0.0f;  // radiance is scaled by 2^stops
    ToneMap tone_map = ToneMap::aces;
    bool bloom = false;
    float bloom_threshold = 1.0f;  // after exposure
    float bloom_strength = 0.15f;
    float bloom_radius = 0.01f;  // Gaussian sigma as a fraction of the image height
};

// Linear radiance scaled by the exposure (what EXR files receive), with bloom if asked.
Image expose(const Image& linear, const PostSettings& s);
// Tone-mapped, sRGB-encoded values in [0, 1] (what PNG files receive).
Image to_display(const Image& exposed, ToneMap tone_map);

// Both of a frame's finished images, what expose and to_display make, written into `exposed`
// and `display` (resized to the frame, their storage reused): one pass over the pixels where
// there is no bloom.
void post_process(const Image& linear, const PostSettings& s, Image& exposed, Image& display);

float tone_map_value(float v, ToneMap tone_map);
float srgb_encode(float linear01);

}  // namespace kdpm
