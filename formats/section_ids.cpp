#include "formats/section_ids.h"

#include "formats/photon_layout.h"

namespace kdpm::section {

namespace {

// The section of each map's field, or "" when `id` is no photon tree section.
std::string photon_tree_name(std::uint32_t id) {
    static constexpr const char* kFields[] = {"info", "nodes", "x", "y", "z", "power", "direction", "flags",
                                              "irradiance", "source"};
    static constexpr const char* kMaps[] = {"photon_tree.", "caustic_tree.", "irradiance_tree."};
    for (PhotonMapKind map : {PhotonMapKind::global, PhotonMapKind::caustic, PhotonMapKind::irradiance}) {
        // Only the irradiance map has the fields past flags.
        const std::uint32_t fields = map == PhotonMapKind::irradiance ? 10 : 8;
        for (std::uint32_t f = 0; f < fields; ++f)
            if (id == photon_tree_section(map, static_cast<PhotonTreeField>(f)))
                return std::string(kMaps[static_cast<std::uint32_t>(map)]) + kFields[f];
    }
    return "";
}

}  // namespace

std::string name(std::uint32_t id) {
    switch (id) {
        case metadata: return "metadata";
        case geo_info: return "geometry.info";
        case geo_nodes: return "geometry.nodes";
        case geo_leaf_indices: return "geometry.leaf_indices";
        case geo_triangles: return "geometry.triangles";
        case geo_normals: return "geometry.normals";
        case geo_materials: return "geometry.materials";
        case geo_lights: return "geometry.lights";
        case geo_camera: return "geometry.camera";
        case geo_uvs: return "geometry.uvs";
        case geo_textures: return "geometry.textures";
        case geo_texels: return "geometry.texels";
        case geo_wide: return "geometry.wide";
        case geo_objects: return "geometry.objects";
        case geo_instances: return "geometry.instances";
        case hits_info: return "hits.info";
        case hits_photons: return "hits.photons";
        default: return photon_tree_name(id);
    }
}

}  // namespace kdpm::section
