#pragma once
// A random triangle soup turned into a real .kdg in memory by the geometry builder (SAH
// kd-tree), with one card light over it, opened through GeometryFile like kdpm-render does.
#include <cstdint>
#include <optional>

#include "builders/geometry/geometry_file_builder.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/render/scene_views.h"
#include "tests/geometry/random_scenes.h"

namespace kdpm::test {

struct BuiltScene {
    std::optional<GeometryFile> file;
    SceneViews views;

    BuiltScene(std::uint32_t triangles, std::uint32_t seed, std::uint32_t width, std::uint32_t height) {
        Scene scene = scene_from_triangles(random_soup(triangles, seed, 0.15f));
        const float p0[3] = {0.2f, 1.6f, 0.2f}, e1[3] = {0.6f, 0.0f, 0.0f}, e2[3] = {0.0f, 0.0f, 0.6f};
        const float radiance[3] = {4.0f, 3.0f, 2.0f};
        // cross(e1, e2) points down (-y): the light shines onto the soup.
        scene.lights.push_back(make_parallelogram_light(p0, e1, e2, radiance));
        frame_camera(scene);
        scene.camera.width = width;
        scene.camera.height = height;
        scene.has_camera = true;
        GeometryBuild build = build_geometry_file(scene, KdBuildParams{});
        file.emplace(GeometryFile::from_bytes(build.writer.bytes(), "soup.kdg"));
        views.geometry = file->view();
        views.camera = file->camera();
    }
};

}  // namespace kdpm::test
