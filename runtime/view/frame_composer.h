#pragma once
// Turns a rendered frame into the displayed image: the chosen view (shaded through the same
// post-processing as kdpm-render, depth, normals, or a photon-density heat map), scaled up to
// the window's image size when it was a reduced-resolution preview.
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/render/image/image.h"
#include "runtime/render/render_settings.h"
#include "runtime/view/view_options.h"

namespace kdpm {

// The view alone, at the frame's own resolution, values in [0, 1] (sRGB-encoded for shaded).
// `density`: per-pixel photon density for the density view (empty otherwise).
Image compose_view(const RenderResult& frame, const std::vector<float>& density, const ViewOptions& options);

// Nearest-neighbour resize (previews are shown blocky rather than blurred: it reads as "not final").
// `source` itself (moved, not copied) when it has that size already.
Image resize_nearest(Image source, int width, int height);

// The density view's colour scale: natural logs of the densities shown at its dark and bright
// ends (the frame's 1st and 99th percentiles). valid is false when nothing has a density.
struct DensityScale {
    float log_lo = 0.0f, log_hi = 0.0f;
    bool valid = false;
};
DensityScale density_scale(const std::vector<float>& density);
// Where a log density falls on the scale, in [0, 1] (the input of heat_color).
float density_scale_position(const DensityScale& scale, float log_density);

// Packs [0, 1] floats into 8-bit RGB, rounding like OpenImageIO's conversion.
void to_rgb8(const Image& image, std::vector<unsigned char>& out);

// False colour for a value in [0, 1]: black, blue, red, yellow, white.
glm::vec3 heat_color(float t);

}  // namespace kdpm
