// Builds without OpenImageIO (scripts/gpu-bundle) read PPM textures only, with kdpm's own reader.
#include "builders/geometry/texture_import.h"
#include "builders/geometry/texture_ppm.h"

namespace kdpm {

std::optional<TextureImage> read_texture_image(const std::filesystem::path& path, std::string& why) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        why = std::filesystem::exists(path, ec) ? "not a regular file" : "no such file";
        return std::nullopt;
    }
    if (path.extension() != ".ppm") {
        why = "this kdpm was built without OpenImageIO and reads only .ppm textures";
        return std::nullopt;
    }
    return read_ppm_texture(path, why);
}

}  // namespace kdpm
