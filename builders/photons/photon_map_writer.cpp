#include "builders/photons/photon_map_writer.h"

#include <string>
#include <vector>

#include <tbb/parallel_invoke.h>

#include "builders/photons/photon_tree_writer.h"

namespace kdpm {

PhotonMapBuild build_photon_map_file(const PhotonHitSet& set, const PhotonTreeOptions& options, Metadata metadata,
                                     const IrradiancePrecompute& irradiance) {
    std::vector<PhotonHit> caustic_hits;
    for (const auto& h : set.hits)
        if (h.flags & kPhotonCaustic) caustic_hits.push_back(h);
    // The two trees are independent: built side by side.
    BuiltPhotonTree global, caustic;
    tbb::parallel_invoke(
        [&] { global = build_photon_tree(set.hits, options, set.info.emitted_count, set.info.max_bounces); },
        [&] { caustic = build_photon_tree(caustic_hits, options, set.info.emitted_count, set.info.max_bounces); });

    PhotonMapBuild out;
    add_photon_tree_sections(out.writer, PhotonMapKind::global, global);
    add_photon_tree_sections(out.writer, PhotonMapKind::caustic, caustic);
    if (irradiance) {
        const BuiltIrradianceMap map = build_irradiance_map(global, set.hits, irradiance(global), options);
        add_irradiance_map_sections(out.writer, map);
        out.irradiance = map.tree.info;
        metadata.statistics["irradiance_photons"] = map.tree.info.photon_count;
    }
    const bool balanced = options.builder == PhotonTreeBuilder::balanced;
    metadata.parameters["builder"] = balanced ? "balanced" : "vvh";
    metadata.parameters["leaf_size"] = std::to_string(leaf_size_of(options));
    metadata.parameters["radius"] = options.query_radius > 0.0f ? std::to_string(options.query_radius) : "auto";
    metadata.statistics["photons"] = global.info.photon_count;
    metadata.statistics["caustic_photons"] = caustic.info.photon_count;
    metadata.statistics["nodes"] = global.info.node_count;
    metadata.statistics["leaves"] = global.info.leaf_count;
    metadata.statistics["max_depth"] = global.info.max_depth;
    metadata.statistics["query_radius"] = global.info.query_radius;
    metadata.statistics["emitted"] = static_cast<double>(set.info.emitted_count);
    out.writer.set_metadata(metadata);
    out.global = global.info;
    out.caustic = caustic.info;
    return out;
}

}  // namespace kdpm
