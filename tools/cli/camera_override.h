#pragma once
// The camera options shared by kdpm-render and kdpm-view.
#include "runtime/render/camera_override.h"
#include "tools/cli/args.h"

namespace kdpm::cli {

void add_camera_options(Args& args, CameraOverride& camera);

}  // namespace kdpm::cli
