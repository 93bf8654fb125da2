#pragma once
// What the viewer shows, as changed by the keys: k, lighting mode, view, exposure, tone map.
// Pure state and rules (ranges, which modes need a photon map) so they are testable without GL.
#include <cstdint>
#include <string>
#include <string_view>

#include "formats/scene_limits.h"
#include "runtime/render/image/post_process.h"
#include "runtime/render/render_settings.h"

namespace kdpm {

enum class ViewKind { shaded, depth, normal, photon_density };
const char* view_name(ViewKind v);
ViewKind parse_view(std::string_view text);  // shaded, depth, normal, density; throws std::invalid_argument
const char* tone_map_name(ToneMap t);

struct ViewOptions {
    static constexpr std::uint32_t kMinK = kMinEstimateK, kMaxK = kMaxEstimateK;
    static constexpr float kExposureStep = 0.5f;

    std::uint32_t k = 64;
    RenderMode mode = RenderMode::direct;
    ViewKind view = ViewKind::shaded;
    float exposure_stops = 0.0f;
    ToneMap tone_map = ToneMap::aces;
    bool help = false;
    bool stats = true;

    void halve_k();
    void double_k();
    // The next mode of the key's cycle (render_modes.h: in_key_cycle) that this scene can render;
    // the slow ones are left to the panel's combo.
    void next_mode(bool have_photons);
    // shaded -> depth -> normal -> photon density (only with a photon map) -> shaded.
    void next_view(bool have_photons);
    void next_tone_map();  // aces -> reinhard -> none
    void brighter() {
        exposure_stops = exposure_stops + kExposureStep > kMaxExposureStops ? kMaxExposureStops : exposure_stops + kExposureStep;
    }
    void darker() {
        exposure_stops = exposure_stops - kExposureStep < -kMaxExposureStops ? -kMaxExposureStops : exposure_stops - kExposureStep;
    }
};

// The AOVs a frame needs for view v: depth or normals for those views, hit points and normals
// for the photon density (searched at each pixel's hit), none for the shaded image. The viewer
// renders only these, because the two AOVs add to a shaded frame's cost (trace, copies and
// composition), and switching views renders anew only when the needs differ.
AovSet aovs_for_view(ViewKind v);
// Whether switching views needs a new frame, not just a new composition of the last one: the
// density view renders a frame of its own, and a view may need AOVs the other's frame lacks.
bool view_switch_renders(ViewKind from, ViewKind to);

// k clamped to [kMinK, kMaxK]; the scene's default when 0.
std::uint32_t clamp_k(std::uint32_t k);

// The key list printed on start and shown by H.
std::string key_help_text();

}  // namespace kdpm
