#pragma once
// Where the geometry benches find the real scenes: $KDPM_SCENES, else ../shared/scenes beside the
// source tree (KDPM_SOURCE_DIR, set by tools/geometry/tools.cmake).
#include <cstdlib>
#include <filesystem>

namespace kdpm::cli {

inline std::filesystem::path shared_scenes() {
    if (const char* env = std::getenv("KDPM_SCENES"); env && *env) return env;
    return std::filesystem::path(KDPM_SOURCE_DIR) / ".." / "shared" / "scenes";
}

}  // namespace kdpm::cli
