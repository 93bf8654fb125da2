#pragma once
// Diffuse texture lookups in the mapped geometry.textures / geometry.texels sections: bilinear
// within one mip level and trilinear between two, with wrap (repeat) addressing. Texel (x, y)
// of a w x h level has its centre at uv ((x + 0.5) / w, (y + 0.5) / h).
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/instance_hit.h"
#include "runtime/geometry/ray.h"

namespace kdpm {

struct TextureLevel {
    std::uint64_t first;  // index of its texel (0, 0) in geometry.texels
    std::uint32_t width, height;
};

KDPM_HD KDPM_INLINE TextureLevel texture_level(const TextureRecord& t, std::uint32_t level) {
    std::uint64_t first = t.first_texel;
    for (std::uint32_t l = 0; l < level; ++l)
        first += std::uint64_t{texture_level_side(t.width, l)} * texture_level_side(t.height, l);
    return TextureLevel{first, texture_level_side(t.width, level), texture_level_side(t.height, level)};
}

// The fractional part in [0, 1): repeat addressing for any finite coordinate.
KDPM_HD KDPM_INLINE float wrap_unit(float u) {
    const float f = u - floorf(u);
    return f < 1.0f ? f : 0.0f;  // a tiny negative u rounds up to 1
}

KDPM_HD KDPM_INLINE glm::vec3 texel_value(const Texel* texels, const TextureLevel& lv, std::uint32_t x, std::uint32_t y) {
    const Texel& t = texels[lv.first + std::uint64_t{y} * lv.width + x];
    return glm::vec3(t.rgb[0], t.rgb[1], t.rgb[2]);
}

// Bilinear interpolation of the four texels around uv, wrapping across the edges.
KDPM_HD KDPM_INLINE glm::vec3 bilinear_lookup(const Texel* texels, const TextureLevel& lv, glm::vec2 uv) {
    const float x = wrap_unit(uv.x) * static_cast<float>(lv.width) - 0.5f;
    const float y = wrap_unit(uv.y) * static_cast<float>(lv.height) - 0.5f;
    const float xf = floorf(x), yf = floorf(y);
    const float tx = x - xf, ty = y - yf;
    // xf in [-1, width - 1]: -1 wraps to the last column, width to the first.
    const std::int64_t xi = static_cast<std::int64_t>(xf), yi = static_cast<std::int64_t>(yf);
    const std::uint32_t x0 = static_cast<std::uint32_t>(xi < 0 ? xi + lv.width : xi);
    const std::uint32_t y0 = static_cast<std::uint32_t>(yi < 0 ? yi + lv.height : yi);
    const std::uint32_t x1 = x0 + 1 < lv.width ? x0 + 1 : 0;
    const std::uint32_t y1 = y0 + 1 < lv.height ? y0 + 1 : 0;
    const glm::vec3 bottom = (1.0f - tx) * texel_value(texels, lv, x0, y0) + tx * texel_value(texels, lv, x1, y0);
    const glm::vec3 top = (1.0f - tx) * texel_value(texels, lv, x0, y1) + tx * texel_value(texels, lv, x1, y1);
    return (1.0f - ty) * bottom + ty * top;
}

// Trilinear lookup: `footprint` is the width of the filter region in uv units (0 when unknown:
// level 0, bilinear). The level is log2 of the footprint in level-0 texels, clamped to the chain.
KDPM_HD KDPM_INLINE glm::vec3 texture_lookup(const Texel* texels, const TextureRecord& t, glm::vec2 uv, float footprint) {
    const float side = static_cast<float>(t.width > t.height ? t.width : t.height);
    const float texels_across = footprint * side;
    float level = texels_across > 1.0f ? log2f(texels_across) : 0.0f;
    const float last = static_cast<float>(t.levels - 1);
    if (!(level <= last)) level = last;  // NaN too
    const float lf = floorf(level);
    const std::uint32_t l0 = static_cast<std::uint32_t>(lf);
    const glm::vec3 a = bilinear_lookup(texels, texture_level(t, l0), uv);
    const float blend = level - lf;
    if (blend <= 0.0f) return a;
    return (1.0f - blend) * a + blend * bilinear_lookup(texels, texture_level(t, l0 + 1), uv);
}

// Texture coordinates at barycentrics (u, v) of a triangle.
KDPM_HD KDPM_INLINE glm::vec2 uv_at(const TriangleUVs& t, float u, float v) {
    const float w = 1.0f - u - v;
    return glm::vec2(w * t.uv[0][0] + u * t.uv[1][0] + v * t.uv[2][0], w * t.uv[0][1] + u * t.uv[1][1] + v * t.uv[2][1]);
}

// A filter width in world units at the hit as a width in texture coordinates: the triangle's uv
// area over its world area, square-rooted. 0 (finest level) without uvs.
KDPM_HD KDPM_INLINE float uv_footprint(const GeometryView& scene, const Hit& hit, float world_width) {
    const GeometryView& g = object_of(scene, hit);
    if (g.uvs == nullptr) return 0.0f;
    const TriangleRecord t = world_triangle(scene, hit);
    const TriangleUVs& q = g.uvs[hit.triangle];
    const float world = glm::length(glm::cross(glm::vec3(t.e1[0], t.e1[1], t.e1[2]), glm::vec3(t.e2[0], t.e2[1], t.e2[2])));
    const float du1 = q.uv[1][0] - q.uv[0][0], dv1 = q.uv[1][1] - q.uv[0][1];
    const float du2 = q.uv[2][0] - q.uv[0][0], dv2 = q.uv[2][1] - q.uv[0][1];
    const float uv = fabsf(du1 * dv2 - dv1 * du2);
    if (!(world > 0.0f)) return 0.0f;
    return world_width * sqrtf(uv / world);
}

// The texture of a material at a triangle, or nullptr when it has none (or the scene has no uvs).
KDPM_HD KDPM_INLINE const TextureRecord* diffuse_texture_of(const GeometryView& g, const MaterialRecord& m) {
    if (m.diffuse_texture == 0 || m.diffuse_texture > g.texture_count || g.uvs == nullptr || g.texels == nullptr)
        return nullptr;
    return &g.textures[m.diffuse_texture - 1];
}

}  // namespace kdpm
