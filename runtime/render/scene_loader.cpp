#include "runtime/render/scene_loader.h"

#include <optional>

#include "runtime/geometry/geometry_file.h"
#include "runtime/render/stage_times.h"

namespace kdpm {

struct LoadedScene::Files {
    std::optional<GeometryFile> geometry;
};

LoadedScene::LoadedScene() : files_(std::make_unique<Files>()) {}
LoadedScene::LoadedScene(LoadedScene&&) noexcept = default;
LoadedScene& LoadedScene::operator=(LoadedScene&&) noexcept = default;
LoadedScene::~LoadedScene() = default;

LoadedScene LoadedScene::load(const std::filesystem::path& geometry,
                              const std::optional<std::filesystem::path>& photons) {
    StopWatch watch;
    LoadedScene scene;
    scene.files_->geometry.emplace(GeometryFile::open(geometry));
    scene.views_.geometry = scene.files_->geometry->view();
    scene.views_.camera = scene.files_->geometry->camera();
    (void)photons;
    scene.load_ms_ = watch.lap_ms();
    return scene;
}

}  // namespace kdpm
