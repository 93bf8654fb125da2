// Structural checks of a geometry kd-tree file (.kdg): required sections and record sizes,
// every index in range, the tree shape (each node reached exactly once from the root, depth
// bounded, splits inside their cells) and, exhaustively, full leaf coverage. Linear in the
// file size except for the exhaustive check. Never trusts a count or index before checking it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "formats/camera_check.h"
#include "formats/geometry_layout.h"
#include "formats/scene_limits.h"
#include "formats/section_ids.h"
#include "formats/repeated_triangles.h"
#include "formats/triangle_clip.h"
#include "formats/validate_kinds.h"
#include "formats/validate_wide_tree.h"

namespace kdpm {

namespace {

[[noreturn]] void fail(const ContainerReader& file, const std::string& why) {
    throw FormatError(file.name() + ": invalid geometry file: " + why);
}

}  // namespace

void check_scene_defaults(const ContainerReader& file, const GeometryInfo& info) {
    if (info.up_axis > 2) fail(file, "up_axis must be 0, 1 or 2");
    // The defaults reach the shooter and the renderer: the same limits as their options.
    if (info.default_photons > kMaxPhotons)
        fail(file, "default photons " + std::to_string(info.default_photons) + " exceed " + std::to_string(kMaxPhotons));
    if (info.default_bounces > kMaxBounces)
        fail(file, "default bounces " + std::to_string(info.default_bounces) + " exceed " + std::to_string(kMaxBounces));
    if (info.default_k > kMaxEstimateK)
        fail(file, "default k " + std::to_string(info.default_k) + " exceeds " + std::to_string(kMaxEstimateK));
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(info.bounds_min[a]) || !std::isfinite(info.bounds_max[a]) ||
            info.bounds_min[a] > info.bounds_max[a])
            fail(file, "scene bounds are not finite and ordered");
    }
}

void check_lights(const ContainerReader& file, std::span<const AreaLightRecord> lights, std::size_t tri_count) {
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const AreaLightRecord& l = lights[i];
        if (l.shape > static_cast<std::uint32_t>(LightShape::parallelogram))
            fail(file, "light " + std::to_string(i) + " has an unknown shape");
        if (l.triangle != 0xffffffffu && l.triangle >= tri_count)
            fail(file, "light " + std::to_string(i) + " names a triangle out of range");
        const float values[] = {l.p0[0], l.p0[1], l.p0[2], l.e1[0], l.e1[1], l.e1[2], l.e2[0], l.e2[1], l.e2[2],
                                l.radiance[0], l.radiance[1], l.radiance[2], l.area, l.power};
        for (float v : values)
            if (!std::isfinite(v)) fail(file, "light " + std::to_string(i) + " has a value that is not finite");
        if (!(l.area > 0.0f) || l.power < 0.0f || l.radiance[0] < 0.0f || l.radiance[1] < 0.0f || l.radiance[2] < 0.0f)
            fail(file, "light " + std::to_string(i) + " has a non-positive area or a negative power");
    }
}

namespace {

struct TreeArrays {
    std::span<const KdNode> nodes;
    std::span<const std::uint32_t> leaf;
    std::span<const TriangleRecord> tris;
};

struct WalkEntry {
    std::uint32_t node;
    std::uint32_t depth;
    AxisBox cell;
};

void check_info(const ContainerReader& file, const GeometryInfo& info, const TreeArrays& t) {
    if (info.triangle_count != t.tris.size()) fail(file, "info.triangle_count does not match geometry.triangles");
    if (info.node_count != t.nodes.size()) fail(file, "info.node_count does not match geometry.nodes");
    if (info.leaf_index_count != t.leaf.size())
        fail(file, "info.leaf_index_count does not match geometry.leaf_indices");
    if (info.max_depth > kMaxKdTreeDepth)
        fail(file, "tree depth " + std::to_string(info.max_depth) + " exceeds " + std::to_string(kMaxKdTreeDepth));
    check_scene_defaults(file, info);
    if (t.nodes.empty()) fail(file, "the tree has no nodes");
}

// Depth-first walk from the root: each node once, children in range, splits inside the cell.
void check_tree(const ContainerReader& file, const GeometryInfo& info, const TreeArrays& t) {
    const std::size_t count = t.nodes.size();
    std::vector<std::uint8_t> seen(count, 0);
    std::vector<WalkEntry> stack;
    stack.reserve(kMaxKdTreeDepth + 1);
    AxisBox root;
    for (int a = 0; a < 3; ++a) root.lo[a] = info.bounds_min[a], root.hi[a] = info.bounds_max[a];
    std::uint32_t max_depth = 0;
    std::size_t reached = 0;
    // Pre-order: the "below" child is walked next in place; only the "above" child is stacked.
    WalkEntry e{0, 0, root};
    for (bool more = true; more;) {
        if (seen[e.node]) fail(file, "node " + std::to_string(e.node) + " is reached twice");
        seen[e.node] = 1;
        ++reached;
        const KdNode& n = t.nodes[e.node];
        if (n.is_leaf()) {
            if (static_cast<std::uint64_t>(n.first()) + n.count() > t.leaf.size())
                fail(file, "leaf " + std::to_string(e.node) + " lists items past the leaf index array");
            max_depth = std::max(max_depth, e.depth);
            more = !stack.empty();
            if (more) {
                e = stack.back();
                stack.pop_back();
            }
            continue;
        }
        const int axis = n.axis();
        const float split = n.split();
        if (!(split >= e.cell.lo[axis] && split <= e.cell.hi[axis]))
            fail(file, "node " + std::to_string(e.node) + " splits outside its cell");
        const std::uint64_t below = static_cast<std::uint64_t>(e.node) + 1, above = n.above_child();
        if (below >= count || above >= count || above <= e.node)
            fail(file, "node " + std::to_string(e.node) + " has a child index out of range");
        if (e.depth + 1 > kMaxKdTreeDepth)
            fail(file, "tree deeper than " + std::to_string(kMaxKdTreeDepth) + " levels");
        WalkEntry& hi = stack.emplace_back(e);
        hi.node = static_cast<std::uint32_t>(above);
        hi.depth = e.depth + 1;
        hi.cell.lo[axis] = split;
        e.node = static_cast<std::uint32_t>(below);
        e.depth = hi.depth;
        e.cell.hi[axis] = split;
    }
    if (reached != count) fail(file, std::to_string(count - reached) + " nodes are not reachable from the root");
    if (max_depth != info.max_depth)
        fail(file, "info.max_depth is " + std::to_string(info.max_depth) + " but the tree is " +
                       std::to_string(max_depth) + " deep");
}

void check_indices(const ContainerReader& file, const TreeArrays& t, std::span<const MaterialRecord> materials,
                   std::span<const AreaLightRecord> lights, bool has_normals) {
    const std::size_t tri_count = t.tris.size();
    for (std::size_t i = 0; i < t.leaf.size(); ++i)
        if (t.leaf[i] >= tri_count)
            fail(file, "leaf index " + std::to_string(i) + " names triangle " + std::to_string(t.leaf[i]) +
                           " of " + std::to_string(tri_count));
    for (std::size_t i = 0; i < tri_count; ++i) {
        if (t.tris[i].material >= materials.size())
            fail(file, "triangle " + std::to_string(i) + " has material index out of range");
        if ((t.tris[i].flags & kTriangleHasNormals) && !has_normals)
            fail(file, "triangle " + std::to_string(i) + " claims shading normals but the file has none");
        if (t.tris[i].flags & ~kTriangleHasNormals)
            fail(file, "triangle " + std::to_string(i) + " has unknown flag bits");
        if (t.tris[i].source_index >= tri_count)
            fail(file, "triangle " + std::to_string(i) + " has source index out of range");
    }
    for (std::size_t i = 0; i < materials.size(); ++i) {
        if (materials[i].kind > static_cast<std::uint32_t>(MaterialKind::glass))
            fail(file, "material " + std::to_string(i) + " has an unknown kind");
        const MaterialRecord& m = materials[i];
        for (int c = 0; c < 3; ++c)
            if (!(m.diffuse[c] >= 0.0f && m.specular[c] >= 0.0f && m.transmission[c] >= 0.0f && m.emission[c] >= 0.0f) ||
                !std::isfinite(m.diffuse[c] + m.specular[c] + m.transmission[c] + m.emission[c]))
                fail(file, "material " + std::to_string(i) + " has a negative or non-finite colour");
        if (m.kind == static_cast<std::uint32_t>(MaterialKind::glass) && !(m.ior > 0.0f && std::isfinite(m.ior)))
            fail(file, "material " + std::to_string(i) + " has an index of refraction that is not positive");
    }
    check_lights(file, lights, tri_count);
}

// Every usable triangle (but exact copies of an earlier one) that overlaps the inside of a leaf cell (the cell shrunk by a small
// epsilon, so triangles merely touching a face need not be listed) is listed in that leaf.
void check_coverage(const ContainerReader& file, const GeometryInfo& info, const TreeArrays& t) {
    float extent = 0.0f;
    for (int a = 0; a < 3; ++a) extent = std::max(extent, info.bounds_max[a] - info.bounds_min[a]);
    const float eps = 1e-5f * extent + 1e-30f;

    // Sorted copy of each leaf's list, for membership tests.
    std::vector<std::uint32_t> sorted(t.leaf.begin(), t.leaf.end());
    for (const KdNode& n : t.nodes)
        if (n.is_leaf()) std::sort(sorted.begin() + n.first(), sorted.begin() + n.first() + n.count());

    AxisBox root;
    for (int a = 0; a < 3; ++a) root.lo[a] = info.bounds_min[a], root.hi[a] = info.bounds_max[a];
    std::vector<WalkEntry> stack;
    const std::vector<bool> repeated = repeated_triangles(t.tris);
    for (std::uint32_t ti = 0; ti < t.tris.size(); ++ti) {
        const TriangleRecord& tri = t.tris[ti];
        if (!triangle_is_usable(tri) || repeated[ti]) continue;
        double v[3][3];
        triangle_vertices(tri, v);
        const AxisBox bounds = triangle_bounds(tri);
        const float* lo = bounds.lo;
        const float* hi = bounds.hi;
        stack.clear();
        stack.push_back({0, 0, root});
        while (!stack.empty()) {
            WalkEntry e = stack.back();
            stack.pop_back();
            const KdNode& n = t.nodes[e.node];
            if (!n.is_leaf()) {
                const int axis = n.axis();
                const float split = n.split();
                AxisBox lo_cell = e.cell, hi_cell = e.cell;
                lo_cell.hi[axis] = split;
                hi_cell.lo[axis] = split;
                if (hi[axis] >= split) stack.push_back({n.above_child(), e.depth + 1, hi_cell});
                if (lo[axis] <= split) stack.push_back({e.node + 1, e.depth + 1, lo_cell});
                continue;
            }
            // The cell shrunk by eps on each axis (a thin cell by a quarter of its width): a
            // triangle only touching a face, or lying within that distance of it, need not be
            // listed. A flat axis (a flat scene) is not shrunk; a cell too thin to shrink in
            // float (a few ulps) requires nothing.
            AxisBox inner = e.cell;
            bool too_thin = false;
            for (int a = 0; a < 3; ++a) {
                const float width = inner.hi[a] - inner.lo[a];
                if (width == 0.0f) continue;
                const float shrink = std::min(eps, 0.25f * width);
                const float lo_in = inner.lo[a] + shrink, hi_in = inner.hi[a] - shrink;
                if (!(lo_in > inner.lo[a] && hi_in < inner.hi[a] && lo_in <= hi_in)) too_thin = true;
                inner.lo[a] = lo_in;
                inner.hi[a] = hi_in;
            }
            AxisBox clipped;
            if (too_thin || !clip_triangle_to_box(v, inner, clipped)) continue;
            const auto first = sorted.begin() + n.first(), last = first + n.count();
            if (!std::binary_search(first, last, ti))
                fail(file, "triangle " + std::to_string(ti) + " overlaps leaf node " + std::to_string(e.node) +
                               " but is not listed in it");
        }
    }
}

// Texture coordinates finite (the lookup wraps them, but NaN has no place to wrap to).
void check_uvs(const ContainerReader& file, std::span<const TriangleUVs> uvs, std::size_t tri_count) {
    if (uvs.size() != tri_count) fail(file, "geometry.uvs must hold one record per triangle");
    for (std::size_t i = 0; i < uvs.size(); ++i)
        for (const auto& corner : uvs[i].uv)
            if (!std::isfinite(corner[0]) || !std::isfinite(corner[1]))
                fail(file, "triangle " + std::to_string(i) + " has a texture coordinate that is not finite");
}

// Textures: sides in range, a full mip chain, levels laid end to end in texture order over
// exactly the texel array, every texel finite and non-negative; material texture indices in range.
void check_textures(const ContainerReader& file, std::span<const TextureRecord> textures, std::span<const Texel> texels,
                    std::span<const MaterialRecord> materials) {
    std::uint64_t next = 0;
    for (std::size_t i = 0; i < textures.size(); ++i) {
        const TextureRecord& t = textures[i];
        const std::string which = "texture " + std::to_string(i);
        if (t.width == 0 || t.height == 0 || t.width > kMaxTextureSide || t.height > kMaxTextureSide)
            fail(file, which + " has a side outside 1.." + std::to_string(kMaxTextureSide));
        if (t.levels != texture_level_count(t.width, t.height))
            fail(file, which + " does not hold a full mip chain");
        std::uint64_t count = 0;
        for (std::uint32_t l = 0; l < t.levels; ++l)
            count += std::uint64_t{texture_level_side(t.width, l)} * texture_level_side(t.height, l);
        if (t.texel_count != count) fail(file, which + " has a texel count that does not match its levels");
        if (t.first_texel != next) fail(file, which + " does not start where the previous texture ends");
        if (t.reserved0 != 0) fail(file, which + " has a non-zero reserved field");
        next += count;
    }
    if (next != texels.size()) fail(file, "geometry.texels does not hold exactly the textures' texels");
    for (std::size_t i = 0; i < texels.size(); ++i)
        for (float c : texels[i].rgb)
            if (!(c >= 0.0f) || !std::isfinite(c))
                fail(file, "texel " + std::to_string(i) + " is negative or not finite");
    for (std::size_t i = 0; i < materials.size(); ++i)
        if (materials[i].diffuse_texture > textures.size())
            fail(file, "material " + std::to_string(i) + " names a texture out of range");
}

// The element type each section's writer declares: a reader must not take u32s for records.
void check_element_types(const ContainerReader& file) {
    const std::pair<std::uint32_t, ElementType> expected[] = {
        {section::geo_info, ElementType::record},      {section::geo_nodes, ElementType::record},
        {section::geo_leaf_indices, ElementType::u32}, {section::geo_triangles, ElementType::record},
        {section::geo_normals, ElementType::record},   {section::geo_materials, ElementType::record},
        {section::geo_lights, ElementType::record},    {section::geo_camera, ElementType::record},
        {section::geo_uvs, ElementType::record},       {section::geo_textures, ElementType::record},
        {section::geo_texels, ElementType::record},    {section::geo_wide, ElementType::record},
        {section::metadata, ElementType::text}};
    for (const auto& [id, type] : expected)
        if (const SectionEntry* e = file.find(id); e && e->element_type != static_cast<std::uint32_t>(type))
            fail(file, "section " + ContainerReader::section_label(id) + " has element type " +
                           std::to_string(e->element_type) + ", expected " +
                           std::to_string(static_cast<std::uint32_t>(type)));
}

}  // namespace

void validate_geometry_file(const ContainerReader& file, const ValidationOptions& options) {
    if (file.find(section::geo_instances) || file.find(section::geo_objects)) {
        validate_instanced_scene_file(file, options);
        return;
    }
    const GeometryInfo& info = file.record<GeometryInfo>(section::geo_info);
    check_element_types(file);
    try {
        check_camera(file.record<CameraRecord>(section::geo_camera), file.name() + ": invalid geometry file");
    } catch (const std::runtime_error& e) {
        throw FormatError(e.what());
    }
    TreeArrays t{file.section<KdNode>(section::geo_nodes), file.section<std::uint32_t>(section::geo_leaf_indices),
                 file.section<TriangleRecord>(section::geo_triangles)};
    const auto materials = file.section<MaterialRecord>(section::geo_materials);
    const auto lights = file.section<AreaLightRecord>(section::geo_lights);
    const auto normals = file.optional_section<TriangleNormals>(section::geo_normals);
    if (normals && normals->size() != t.tris.size())
        fail(file, "geometry.normals must hold one record per triangle");

    check_info(file, info, t);
    check_tree(file, info, t);
    check_indices(file, t, materials, lights, normals.has_value());
    if (const auto uvs = file.optional_section<TriangleUVs>(section::geo_uvs)) check_uvs(file, *uvs, t.tris.size());
    const auto textures = file.optional_section<TextureRecord>(section::geo_textures);
    const auto texels = file.optional_section<Texel>(section::geo_texels);
    if (textures.has_value() != texels.has_value())
        fail(file, "geometry.textures and geometry.texels must come together");
    check_textures(file, textures.value_or(std::span<const TextureRecord>{}), texels.value_or(std::span<const Texel>{}),
                   materials);
    if (const auto wide = file.optional_section<WideNode>(section::geo_wide))
        check_wide_tree(file, info, WideTreeArrays{*wide, t.nodes, t.leaf, t.tris}, options.exhaustive);
    if (options.exhaustive) check_coverage(file, info, t);
}

}  // namespace kdpm
