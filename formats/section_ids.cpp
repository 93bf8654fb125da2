#include "formats/section_ids.h"

namespace kdpm::section {

std::string_view name(std::uint32_t id) {
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
        case hits_info: return "hits.info";
        case hits_photons: return "hits.photons";
        case ptree_info: return "photon_tree.info";
        case ptree_nodes: return "photon_tree.nodes";
        case ptree_pos_x: return "photon_tree.x";
        case ptree_pos_y: return "photon_tree.y";
        case ptree_pos_z: return "photon_tree.z";
        case ptree_power: return "photon_tree.power";
        case ptree_direction: return "photon_tree.direction";
        case ptree_flags: return "photon_tree.flags";
        case ptree_caustic_info: return "caustic_tree.info";
        case ptree_caustic_nodes: return "caustic_tree.nodes";
        case ptree_caustic_pos_x: return "caustic_tree.x";
        case ptree_caustic_pos_y: return "caustic_tree.y";
        case ptree_caustic_pos_z: return "caustic_tree.z";
        case ptree_caustic_power: return "caustic_tree.power";
        case ptree_caustic_direction: return "caustic_tree.direction";
        case ptree_caustic_flags: return "caustic_tree.flags";
        default: return "";
    }
}

}  // namespace kdpm::section
