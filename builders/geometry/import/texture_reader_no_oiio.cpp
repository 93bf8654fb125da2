// Builds without OpenImageIO (scripts/gpu-bundle) read PPM textures only, with kdpm's own reader.
#include "builders/geometry/import/texture_import.h"
#include "builders/geometry/import/texture_ppm.h"

namespace kdpm {

std::optional<TextureImage> decode_texture_file(const std::filesystem::path& path, std::string& why) {
    if (path.extension() != ".ppm") {
        why = "this kdpm was built without OpenImageIO and reads only .ppm textures";
        return std::nullopt;
    }
    return read_ppm_texture(path, why);
}

}  // namespace kdpm
