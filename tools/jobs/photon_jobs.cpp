#include "tools/jobs/photon_jobs.h"

#include <chrono>
#include <stdexcept>

#include "builders/photons/photon_hits_file.h"
#include "builders/photons/photon_map_writer.h"
#include "builders/photons/photon_tree_builder.h"
#include "formats/container_reader.h"
#include "formats/metadata.h"
#include "formats/output_file.h"
#include "formats/scene_limits.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/photons/knn_best.h"
#include "runtime/photons/photon_shooter.h"

namespace kdpm {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Metadata metadata_of(const char* tool, const std::filesystem::path& input) {
    Metadata meta;
    meta.tool = tool;
    meta.tool_version = kdpm_version();
    meta.source_path = input.filename().string();
    meta.source_hash = hash_file(input.string());
    return meta;
}

}  // namespace

ShootJobResult shoot_photons_job(const std::filesystem::path& geometry_path, const std::filesystem::path& output,
                                 const ShootJob& job, const std::function<void(double)>& progress) {
    const std::filesystem::path inputs[] = {geometry_path};
    check_output_destination(output, inputs);
    const GeometryFile geometry = GeometryFile::open(geometry_path);  // checksums verified on open
    const GeometryInfo& info = geometry.info();
    ShootOptions options;
    options.photons = job.photons > 0 ? job.photons : (info.default_photons > 0 ? info.default_photons : 262144u);
    options.max_bounces = job.bounces >= 0 ? static_cast<std::uint32_t>(job.bounces)
                                           : (info.default_bounces > 0 && info.default_bounces <= 255 ? info.default_bounces : 4u);
    options.seed = job.seed;
    const PathRange range = job.paths.empty() ? PathRange{0, options.photons} : parse_path_range(job.paths, options.photons);
    options.path_begin = range.begin;
    options.path_end = range.end;
    options.backend = job.backend;

    const auto start = std::chrono::steady_clock::now();
    ShotPhotons shot = shoot_photons(geometry.view(), options, progress);
    ShootJobResult result;
    result.seconds = seconds_since(start);

    PhotonHitSet set{shot.info, std::move(shot.hits)};
    Metadata meta = metadata_of("kdpm-shoot-photons", geometry_path);
    meta.parameters["photons"] = std::to_string(options.photons);
    meta.parameters["bounces"] = std::to_string(options.max_bounces);
    meta.parameters["seed"] = std::to_string(options.seed);
    meta.parameters[kPathsParameter] = path_range_text(range);
    meta.parameters["store_direct"] = "true";
    meta.statistics["stored"] = set.info.stored_count;
    meta.statistics["caustic"] = set.info.caustic_count;
    meta.statistics["rays"] = static_cast<double>(shot.rays);
    photon_hits_writer(set, meta).write(output);

    result.emitted = options.photons;
    result.bounces = options.max_bounces;
    result.range = range;
    result.info = set.info;
    for (const auto& h : set.hits) result.direct_hits += photon_bounce(h.flags) == 0;
    result.rays = shot.rays;
    return result;
}

PhotonMapJobResult build_photon_map_job(const std::filesystem::path& input, const std::filesystem::path& output,
                                        const PhotonMapJob& job) {
    const std::filesystem::path inputs[] = {input};
    check_output_destination(output, inputs);
    if (job.irradiance_k < 1 || job.irradiance_k > kMaxGatherK)
        throw std::invalid_argument("irradiance k " + std::to_string(job.irradiance_k) + " is outside 1.." +
                                    std::to_string(kMaxGatherK));
    const auto start = std::chrono::steady_clock::now();
    PhotonHitSet set = read_photon_hits(input);
    // A shard's photons carry the power of 1/N each but are only some of the N paths: its map
    // would be too dark.
    if (auto reader = ContainerReader::open(input, FileKind::photon_hits); reader.has_metadata()) {
        const PathRange paths = photon_hits_path_range(reader.metadata(), set.info);
        if (paths != PathRange{0, set.info.emitted_count})
            throw std::invalid_argument(input.string() + " is a shard (paths " + path_range_text(paths) + " of " +
                                        std::to_string(set.info.emitted_count) +
                                        "): merge the shards with kdpm-merge-photons first");
    }
    if (radius_too_small(job.radius, set.info.bounds_min, set.info.bounds_max))
        throw std::invalid_argument("--radius " + radius_limit_text(job.radius, set.info.bounds_min, set.info.bounds_max) +
                                    ": no photon would be found (0 picks it)");

    PhotonTreeOptions options;
    options.builder = job.balanced ? PhotonTreeBuilder::balanced : PhotonTreeBuilder::vvh;
    options.leaf_size = job.leaf_size;
    options.query_radius = static_cast<float>(job.radius);
    Metadata meta = metadata_of("kdpm-build-photons", input);
    IrradiancePrecompute irradiance;
    if (job.irradiance_every > 0) {
        meta.parameters["irradiance_every"] = std::to_string(job.irradiance_every);
        meta.parameters["irradiance_k"] = std::to_string(job.irradiance_k);
        irradiance = every_nth_photon_irradiance(job.irradiance_every, job.irradiance_k);
    }
    PhotonMapBuild built = build_photon_map_file(set, options, meta, irradiance);
    built.writer.write(output);
    PhotonMapJobResult result;
    result.global = built.global;
    result.caustic = built.caustic;
    result.irradiance_photons = built.irradiance.photon_count;
    result.seconds = seconds_since(start);
    return result;
}

}  // namespace kdpm
