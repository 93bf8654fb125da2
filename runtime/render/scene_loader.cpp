#include "runtime/render/scene_loader.h"

#include <exception>
#include <optional>
#include <system_error>
#include <thread>

#include "runtime/geometry/geometry_file.h"
#include "runtime/photons/photon_map_file.h"
#include "runtime/render/stage_times.h"

namespace kdpm {

SceneViews scene_views_of(const GeometryFile& geometry, const PhotonMapFile* photons) {
    SceneViews views;
    views.geometry = geometry.view();
    views.camera = geometry.camera();
    if (photons) {
        views.photons.global = photons->view(PhotonMapKind::global);
        views.photons.caustic = photons->view(PhotonMapKind::caustic);
        views.photons.irradiance = photons->irradiance_map();
        views.photons.present = true;
        views.photons.typical_radius = photons->info(PhotonMapKind::global).query_radius;
    }
    return views;
}

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
    // The photon file is opened (mapped and checked) on a second thread while this one opens the
    // geometry: each check keeps a thread busy only part of the time. A geometry error is reported
    // first, as when the files were opened one after the other.
    std::exception_ptr photons_error;
    std::thread photons_thread;
    auto open_photons = [&] {
        try {
            scene.files_->photons.emplace(PhotonMapFile::open(*photons));
        } catch (...) {
            photons_error = std::current_exception();
        }
    };
    if (photons) {
        try {
            photons_thread = std::thread(open_photons);
        } catch (const std::system_error&) {
            // No thread to be had: after the geometry, below.
        }
    }
    try {
        scene.files_->geometry.emplace(GeometryFile::open(geometry));
    } catch (...) {
        if (photons_thread.joinable()) photons_thread.join();
        throw;
    }
    if (photons_thread.joinable()) photons_thread.join();
    else if (photons) open_photons();
    if (photons_error) std::rethrow_exception(photons_error);
    scene.views_ = scene_views_of(*scene.files_->geometry, photons ? &*scene.files_->photons : nullptr);
    scene.load_ms_ = watch.lap_ms();
    return scene;
}

}  // namespace kdpm
