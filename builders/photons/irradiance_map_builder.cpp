#include "builders/photons/irradiance_map_builder.h"

#include <stdexcept>

#include "builders/photons/photon_tree_writer.h"

namespace kdpm {

BuiltIrradianceMap build_irradiance_map(const BuiltPhotonTree& global, std::span<const PhotonHit> hits,
                                        const IrradianceSamples& samples, const PhotonTreeOptions& options) {
    if (samples.slots.size() != samples.irradiance.size())
        throw std::invalid_argument("irradiance samples: slots and values differ in number");
    std::vector<PhotonHit> chosen;
    chosen.reserve(samples.slots.size());
    for (std::size_t i = 0; i < samples.slots.size(); ++i) {
        const std::uint32_t slot = samples.slots[i];
        if (slot >= global.source.size() || (i > 0 && slot <= samples.slots[i - 1]))
            throw std::invalid_argument("irradiance samples: slots out of range or not ascending");
        chosen.push_back(hits[global.source[slot]]);
    }
    BuiltIrradianceMap out;
    out.tree = build_photon_tree(chosen, options, global.info.emitted_count, global.info.max_bounces);
    out.irradiance.reserve(out.tree.source.size());
    out.global_slot.reserve(out.tree.source.size());
    for (std::uint32_t i : out.tree.source) {
        out.irradiance.push_back(samples.irradiance[i]);
        out.global_slot.push_back(samples.slots[i]);
    }
    return out;
}

void add_irradiance_map_sections(ContainerWriter& writer, const BuiltIrradianceMap& map) {
    add_photon_tree_sections(writer, PhotonMapKind::irradiance, map.tree);
    writer.add(photon_tree_section(PhotonMapKind::irradiance, ptree_field_irradiance), ElementType::record,
               map.irradiance);
    writer.add(photon_tree_section(PhotonMapKind::irradiance, ptree_field_source), ElementType::u32, map.global_slot);
}

}  // namespace kdpm
