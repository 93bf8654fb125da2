#pragma once
// The viewer's Dear ImGui panel: lighting mode, k, exposure, tone mapper, view, samples, light
// samples as widgets; per-stage timings plotted over the last frames; the density view's colour
// legend; the camera and a button that prints it as kdpm-render options. Keyboard shortcuts stay.
#include <cstdint>
#include <optional>
#include <string>

#include "formats/geometry_layout.h"
#include "runtime/view/frame_composer.h"
#include "runtime/view/frame_history.h"
#include "runtime/view/view_options.h"

namespace kdpm {

// What the panel shows and may change; the viewer owns it all.
struct PanelModel {
    ViewOptions* options = nullptr;
    std::uint32_t* max_spp = nullptr;
    std::uint32_t* light_samples = nullptr;
    bool have_photons = false;
    std::string backend;
    std::string frame_line;    // resolution, samples, "moving"
    std::string photons_line;  // photon counts
    const FrameHistory* history = nullptr;
    CameraRecord camera{};
    std::optional<DensityScale> density;  // the shown frame's scale, in the density view
};

struct PanelActions {
    bool rerender = false;      // what is rendered changed (mode, k, samples, density view)
    bool recompose = false;     // only how it is shown changed (exposure, tone map, view)
    bool reset_camera = false;
    bool copy_camera = false;   // print (and put on the clipboard) the camera as options
};

// Builds the panel inside the current ImGui frame.
PanelActions draw_control_panel(const PanelModel& model);
// The key list in its own window, when help is on.
void draw_key_help();

}  // namespace kdpm
