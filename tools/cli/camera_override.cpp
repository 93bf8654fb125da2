#include "tools/cli/camera_override.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace kdpm::cli {

void add_camera_options(Args& args, CameraOverride& camera) {
    args.group("Camera (default: the file's)");
    args.option("eye", &camera.eye, "camera position (default: the file's camera)")
        .option("lookat", &camera.lookat, "point the camera looks at (default: the file's)")
        .option("up", &camera.up, "camera up direction (default: the file's)")
        .option("vfov", "DEG", "vertical field of view in degrees, in (0, 180) (default: the file's)",
                [&camera](const std::string& v) {
                    char* end = nullptr;
                    const double deg = std::strtod(v.c_str(), &end);
                    if (v.empty() || *end != '\0' || !(deg > 0.0 && deg < 180.0))
                        throw std::invalid_argument("'" + v + "' is not an angle in (0, 180) degrees");
                    camera.vfov_degrees = deg;
                });
}

}  // namespace kdpm::cli
