#include "runtime/photons/photon_map_file.h"

#include "formats/tree_validation.h"

namespace kdpm {

PhotonMapFile::PhotonMapFile(ContainerReader reader) : reader_(std::move(reader)) {
    validate_file(reader_, ValidationOptions{});
}

PhotonMapFile PhotonMapFile::open(const std::filesystem::path& path) {
    return PhotonMapFile(ContainerReader::open(path, FileKind::photon_tree));
}

PhotonMapFile PhotonMapFile::from_bytes(std::span<const std::uint8_t> bytes, std::string name) {
    return PhotonMapFile(ContainerReader::from_bytes(bytes, std::move(name), FileKind::photon_tree));
}

bool PhotonMapFile::has_map(PhotonMapKind map) const {
    return reader_.find(photon_tree_section(map, ptree_field_info)) != nullptr;
}

PhotonTreeInfo PhotonMapFile::info(PhotonMapKind map) const {
    if (!has_map(map)) return PhotonTreeInfo{};
    return reader_.record<PhotonTreeInfo>(photon_tree_section(map, ptree_field_info));
}

PhotonMapView PhotonMapFile::view(PhotonMapKind map) const {
    PhotonMapView v;
    if (!has_map(map)) return v;
    auto id = [&](PhotonTreeField f) { return photon_tree_section(map, f); };
    const PhotonTreeInfo& info = reader_.record<PhotonTreeInfo>(id(ptree_field_info));
    auto nodes = reader_.section<KdNode>(id(ptree_field_nodes));
    v.nodes = nodes.data();
    v.node_count = static_cast<std::uint32_t>(nodes.size());
    v.photon_count = info.photon_count;
    v.x = reader_.section<float>(id(ptree_field_x)).data();
    v.y = reader_.section<float>(id(ptree_field_y)).data();
    v.z = reader_.section<float>(id(ptree_field_z)).data();
    v.power = reader_.section<std::uint32_t>(id(ptree_field_power)).data();
    v.directions = reader_.section<PackedPhotonDirections>(id(ptree_field_directions)).data();
    v.flags = reader_.section<std::uint32_t>(id(ptree_field_flags)).data();
    v.emitted_count = info.emitted_count;
    return v;
}

IrradianceMapView PhotonMapFile::irradiance_map() const {
    IrradianceMapView v;
    if (!has_map(PhotonMapKind::irradiance)) return v;
    v.photons = view(PhotonMapKind::irradiance);
    v.irradiance =
        reader_.section<PrecomputedIrradiance>(photon_tree_section(PhotonMapKind::irradiance, ptree_field_irradiance))
            .data();
    return v;
}

}  // namespace kdpm
