#include "builders/photons/photon_tree_writer.h"

namespace kdpm {

void add_photon_tree_sections(ContainerWriter& w, PhotonMapKind map, const BuiltPhotonTree& t) {
    auto id = [&](PhotonTreeField f) { return photon_tree_section(map, f); };
    w.add_record(id(ptree_field_info), t.info);
    w.add(id(ptree_field_nodes), ElementType::record, t.nodes);
    w.add(id(ptree_field_x), ElementType::f32, t.x);
    w.add(id(ptree_field_y), ElementType::f32, t.y);
    w.add(id(ptree_field_z), ElementType::f32, t.z);
    w.add(id(ptree_field_power), ElementType::u32, t.power);
    w.add(id(ptree_field_directions), ElementType::record, t.directions);
    w.add(id(ptree_field_flags), ElementType::u32, t.flags);
}

}  // namespace kdpm
