#include "builders/photons/photon_hits_file.h"

#include <algorithm>

#include "formats/photon_hits_summary.h"
#include "formats/container_reader.h"
#include "formats/section_ids.h"
#include "formats/tree_validation.h"

namespace kdpm {

void update_hits_info(PhotonHitSet& set) { summarize_photon_hits(set.hits, set.info); }

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
