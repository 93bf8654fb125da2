#pragma once
// Maps a geometry file (.kdg) and, optionally, a photon map file (.kdp) for rendering; both are
// validated before any kernel sees them. Sections stay in the mapping (used in place).
#include <filesystem>
#include <memory>
#include <optional>

#include "runtime/render/scene_views.h"

namespace kdpm {

class GeometryFile;
class PhotonMapFile;

// The renderer's views of files already open (photons may be null: no photon maps).
SceneViews scene_views_of(const GeometryFile& geometry, const PhotonMapFile* photons);

class LoadedScene {
public:
    // Throws FormatError / std::runtime_error with a one-line reason.
    static LoadedScene load(const std::filesystem::path& geometry,
                            const std::optional<std::filesystem::path>& photons);
    LoadedScene(LoadedScene&&) noexcept;
    LoadedScene& operator=(LoadedScene&&) noexcept;
    ~LoadedScene();

    const SceneViews& views() const { return views_; }
    double load_ms() const { return load_ms_; }

private:
    LoadedScene();
    struct Files;
    std::unique_ptr<Files> files_;
    SceneViews views_;
    double load_ms_ = 0.0;
};

}  // namespace kdpm
