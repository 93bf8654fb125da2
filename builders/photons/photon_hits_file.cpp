#include "builders/photons/photon_hits_file.h"

#include <algorithm>

#include "formats/container_reader.h"
#include "formats/section_ids.h"
#include "formats/tree_validation.h"

namespace kdpm {

void update_hits_info(PhotonHitSet& set) {
    auto& info = set.info;
    info.stored_count = static_cast<std::uint32_t>(set.hits.size());
    info.caustic_count = 0;
    for (int a = 0; a < 3; ++a) info.bounds_min[a] = info.bounds_max[a] = 0.0f;
    bool first = true;
    for (const auto& h : set.hits) {
        if (h.flags & kPhotonCaustic) ++info.caustic_count;
        for (int a = 0; a < 3; ++a) {
            info.bounds_min[a] = first ? h.position[a] : std::min(info.bounds_min[a], h.position[a]);
            info.bounds_max[a] = first ? h.position[a] : std::max(info.bounds_max[a], h.position[a]);
        }
        first = false;
    }
}

ContainerWriter photon_hits_writer(const PhotonHitSet& set, const Metadata& metadata) {
    ContainerWriter w(FileKind::photon_hits);
    w.add_record(section::hits_info, set.info);
    w.add(section::hits_photons, ElementType::record, set.hits);
    w.set_metadata(metadata);
    return w;
}

PhotonHitSet read_photon_hits(const std::filesystem::path& path) {
    auto reader = ContainerReader::open(path, FileKind::photon_hits);
    validate_file(reader, ValidationOptions{});
    PhotonHitSet set;
    set.info = reader.record<PhotonHitsInfo>(section::hits_info);
    auto hits = reader.section<PhotonHit>(section::hits_photons);
    set.hits.assign(hits.begin(), hits.end());
    return set;
}

}  // namespace kdpm
