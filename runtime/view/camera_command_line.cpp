#include "runtime/view/camera_command_line.h"

#include <cstdio>

namespace kdpm {
namespace {

// %.9g: nine significant digits round-trip every float.
std::string three(const char* name, const float (&v)[3]) {
    char text[128];
    std::snprintf(text, sizeof text, "--%s %.9g %.9g %.9g", name, v[0], v[1], v[2]);
    return text;
}

}  // namespace

std::string camera_command_line(const CameraRecord& c) {
    char vfov[48];
    std::snprintf(vfov, sizeof vfov, "--vfov %.9g", c.vfov_degrees);
    return three("eye", c.eye) + " " + three("lookat", c.lookat) + " " + three("up", c.up) + " " + vfov;
}

}  // namespace kdpm
