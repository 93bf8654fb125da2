#pragma once
// The lighting mode a tool renders when none is asked for: the one that measures best against
// converged path-traced references at equal time (kdpm-bench-quality), among those the scene's
// files allow. Final gathering where the .kdp carries the precomputed irradiance it reads
// (without it every gather hit makes a k-nearest estimate, ten times slower), the photon map
// alone with an older .kdp, direct light without one.
#include "runtime/render/render_modes.h"
#include "runtime/render/scene_views.h"

namespace kdpm {

inline RenderMode default_render_mode(const SceneViews& scene) {
    if (scene.photons.empty()) return RenderMode::direct;
    return scene.photons.irradiance.present() ? RenderMode::final_gather : RenderMode::photons;
}

// For --mode's help.
inline constexpr const char* kDefaultModeText =
    "final-gather with a .kdp holding the precomputed irradiance, photons with an older .kdp, direct without one";

}  // namespace kdpm
