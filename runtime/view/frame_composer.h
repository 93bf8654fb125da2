#pragma once
// Turns a rendered frame into the displayed image: the chosen view (shaded through the same
// post-processing as kdpm-render, depth, normals, or a photon-density heat map), scaled up to
// the window's image size when it was a reduced-resolution preview, plus the optional text.
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/render/image.h"
#include "runtime/render/render_settings.h"
#include "runtime/view/view_options.h"

namespace kdpm {

// The view alone, at the frame's own resolution, values in [0, 1] (sRGB-encoded for shaded).
// `density`: per-pixel photon density for the density view (empty otherwise).
Image compose_view(const RenderResult& frame, const std::vector<float>& density, const ViewOptions& options);

// Nearest-neighbour resize (previews are shown blocky rather than blurred: it reads as "not final").
Image resize_nearest(const Image& source, int width, int height);

// Stats in the top-left corner and, when options.help, the key list in a dark panel.
void draw_overlay(Image& image, const std::string& stats, const ViewOptions& options);

// Packs [0, 1] floats into 8-bit RGB, rounding like OpenImageIO's conversion.
void to_rgb8(const Image& image, std::vector<unsigned char>& out);

// False colour for a value in [0, 1]: black, blue, red, yellow, white.
glm::vec3 heat_color(float t);

}  // namespace kdpm
