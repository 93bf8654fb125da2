#pragma once
// The render modes as data: one row per mode, from which --mode's parsing and help, the viewer's
// panel and key cycle, the renderer's plan and the bench's rows derive. Adding a mode is a row
// here, its pass file and its case in run_frame (frame_loop.h).
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace kdpm {

enum class RenderMode : std::uint32_t {
    photons = 0,         // the report's method: all light from the k nearest photons at the first diffuse hit
    direct_photons = 1,  // direct light by shadow rays + indirect (global map, bounce >= 1) + caustics map
    direct = 2,          // direct light only (no photon map needed)
    path = 3,            // the reference: unbiased path tracing with next-event estimation (no photon map)
    sppm = 4,            // stochastic progressive photon mapping: photons re-shot each pass (no photon map)
    final_gather = 5,    // direct light by shadow rays + caustics map + gather rays reading the global map
    albedo = 6,          // debug: the reflectance at the first hit, no light
};

struct RenderModeInfo {
    RenderMode mode;
    const char* name;        // on the command line, in the panel and in the bench's tables
    const char* help;        // a clause for --help
    bool needs_photons;      // reads the photon map of a .kdp at the diffuse points
    bool direct_light;       // shadow rays at the diffuse points (else all light from the photons)
    bool diffuse_vertices;   // the trace pass keeps each pixel's diffuse vertices for a gather and shade pass
    bool in_key_cycle;       // kdpm-view's M key steps through it (the slow ones only in the panel)
};

inline constexpr RenderModeInfo kRenderModes[] = {
    // mode, name, help, needs photons, direct light, diffuse vertices, in the key cycle
    {RenderMode::photons, "photons", "all light from the photon map", true, false, true, true},
    {RenderMode::direct_photons, "direct+photons", "shadow rays for direct light, the photon map for the rest", true,
     true, true, true},
    {RenderMode::direct, "direct", "direct light only; no photon map needed", false, true, true, true},
    {RenderMode::path, "path", "the path-traced reference; no photon map needed", false, true, false, false},
    {RenderMode::sppm, "sppm", "progressive photon mapping, photons shot anew each pass; no photon map needed", false,
     true, false, false},
    {RenderMode::final_gather, "final-gather", "gather rays read the photon map", true, true, true, false},
    {RenderMode::albedo, "albedo", "debug: the reflectance at the first hit, no light", false, false, false, false},
};

inline std::span<const RenderModeInfo> render_modes() { return kRenderModes; }
const RenderModeInfo& mode_info(RenderMode mode);
inline const char* render_mode_name(RenderMode mode) { return mode_info(mode).name; }
inline bool mode_needs_photons(RenderMode mode) { return mode_info(mode).needs_photons; }
RenderMode parse_render_mode(std::string_view text);  // throws std::invalid_argument listing the names
// "photons, direct+photons, ... or final-gather", for messages.
std::string render_mode_names();
// --mode's help: every mode with its clause, after the tool's sentence on its default.
std::string render_mode_help(std::string_view default_text);

}  // namespace kdpm
