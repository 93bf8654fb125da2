#include "runtime/render/scene_loader.h"

#include <optional>

#include "runtime/geometry/geometry_file.h"
#include "runtime/photons/photon_map_file.h"
#include "runtime/render/stage_times.h"

namespace kdpm {

struct LoadedScene::Files {
    std::optional<GeometryFile> geometry;
    std::optional<PhotonMapFile> photons;
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
    if (photons) {
        scene.files_->photons.emplace(PhotonMapFile::open(*photons));
        scene.views_.photons.global = scene.files_->photons->view(PhotonMapKind::global);
        scene.views_.photons.caustic = scene.files_->photons->view(PhotonMapKind::caustic);
        scene.views_.photons.irradiance = scene.files_->photons->irradiance_map();
        scene.views_.photons.present = true;
        scene.views_.photons.typical_radius = scene.files_->photons->info(PhotonMapKind::global).query_radius;
    }
    scene.load_ms_ = watch.lap_ms();
    return scene;
}

}  // namespace kdpm
