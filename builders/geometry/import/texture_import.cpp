#include "builders/geometry/import/texture_import.h"

#include <cmath>
#include <map>

#include "builders/geometry/import/texture_mips.h"

namespace kdpm {

namespace {
constexpr std::size_t kWarningsPerTexture = 3;
}  // namespace

std::optional<TextureImage> read_texture_image(const std::filesystem::path& path, std::string& why) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        why = std::filesystem::exists(path, ec) ? "not a regular file" : "no such file";
        return std::nullopt;
    }
    return decode_texture_file(path, why);
}

float srgb_to_linear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

void load_textures(Scene& scene) {
    if (scene.texture_paths.empty()) return;
    std::map<std::string, std::uint32_t> loaded;  // path -> 1 + texture index, 0 when unusable
    std::vector<std::string> unusable;            // "path: why"
    for (std::size_t m = 0; m < scene.materials.size() && m < scene.texture_paths.size(); ++m) {
        const std::string& path = scene.texture_paths[m];
        if (path.empty()) continue;
        auto [it, fresh] = loaded.emplace(path, 0u);
        if (fresh) {
            std::string why;
            if (scene.uvs.empty()) {
                why = "the mesh has no texture coordinates";
            } else if (auto image = read_texture_image(path, why)) {
                TextureRecord t{};
                t.width = image->width;
                t.height = image->height;
                t.levels = texture_level_count(t.width, t.height);
                t.first_texel = scene.texels.size();
                std::vector<Texel> chain = build_mip_chain(std::move(image->texels), t.width, t.height);
                t.texel_count = chain.size();
                scene.texels.insert(scene.texels.end(), chain.begin(), chain.end());
                scene.textures.push_back(t);
                it->second = static_cast<std::uint32_t>(scene.textures.size());
            }
            if (it->second == 0) unusable.push_back(path + ": " + why);
        }
        scene.materials[m].diffuse_texture = it->second;
    }
    // One line per texture, or one line for them all when there are many (a mesh copied
    // without its texture folder).
    if (unusable.size() <= kWarningsPerTexture) {
        for (const std::string& u : unusable) scene.warnings.push_back("texture " + u + "; using the material's diffuse colour");
    } else {
        scene.warnings.push_back(std::to_string(unusable.size()) + " textures cannot be used (the first: " + unusable[0] +
                                 "); their materials use their diffuse colours");
    }
}

}  // namespace kdpm
