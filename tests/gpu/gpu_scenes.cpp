#include "tests/gpu/gpu_scenes.h"

#include <cstdlib>

#include "builders/geometry/geometry_file_builder.h"
#include "builders/geometry/scene_card.h"
#include "builders/photons/photon_map_writer.h"
#include "runtime/photons/photon_shooter.h"
#include "tests/support/run_command.h"
#include "tools/photons/irradiance_step.h"

namespace kdpm::test {

namespace {

std::filesystem::path card_of(const std::string& name) {
    const char* root = std::getenv("KDPM_SOURCE_DIR");
    const std::filesystem::path base = root && *root ? std::filesystem::path(root) : std::filesystem::path(KDPM_SOURCE_DIR);
    return base / "scenes" / name / (name + ".json");
}

}  // namespace

bool gpu_test_scene_available(const std::string& name) {
    std::error_code ec;
    const auto card = card_of(name);
    if (!std::filesystem::exists(card, ec)) return false;
    if (name != "cornell-box" && shared_scenes_dir().empty()) return false;
    try {
        return std::filesystem::exists(card_mesh_path(card), ec);
    } catch (const std::exception&) {
        return false;
    }
}

GpuTestScene build_gpu_test_scene(const std::string& name, std::uint64_t photons) {
    GpuTestScene s;
    const Scene scene = load_scene_input(card_of(name));
    GeometryBuild build = build_geometry_file(scene, KdBuildParams{});
    s.geometry.emplace(GeometryFile::from_bytes(build.writer.bytes(), name + ".kdg"));
    s.views.geometry = s.geometry->view();
    s.views.camera = s.geometry->camera();
    if (photons > 0) {
        ShootOptions options;
        options.photons = photons;
        ShotPhotons shot = shoot_photons(s.views.geometry, options);
        PhotonHitSet set{shot.info, std::move(shot.hits)};
        PhotonMapBuild map =
            build_photon_map_file(set, PhotonTreeOptions{}, Metadata{}, default_photon_irradiance());
        s.photons.emplace(PhotonMapFile::from_bytes(map.writer.bytes(), name + ".kdp"));
        s.views.photons.global = s.photons->view(PhotonMapKind::global);
        s.views.photons.caustic = s.photons->view(PhotonMapKind::caustic);
        s.views.photons.irradiance = s.photons->irradiance_map();
        s.views.photons.present = true;
        s.views.photons.typical_radius = s.photons->info(PhotonMapKind::global).query_radius;
    }
    return s;
}

}  // namespace kdpm::test
