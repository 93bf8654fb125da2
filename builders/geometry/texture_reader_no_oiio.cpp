// Builds without OpenImageIO (scripts/gpu-bundle) read no texture files.
#include "builders/geometry/texture_import.h"

namespace kdpm {

std::optional<TextureImage> read_texture_image(const std::filesystem::path&, std::string& why) {
    why = "this kdpm was built without OpenImageIO and reads no texture files";
    return std::nullopt;
}

}  // namespace kdpm
