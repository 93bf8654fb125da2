#pragma once
// The scene as the renderer sees it: views of the mapped geometry and photon maps (host memory)
// and the file's camera. The files they point into must outlive the Renderer.
#include "formats/geometry_layout.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/photons/photon_maps.h"

namespace kdpm {

struct SceneViews {
    GeometryView geometry;
    CameraRecord camera{};
    PhotonMaps photons;  // empty maps when no photon file was given
};

}  // namespace kdpm
