#include "builders/photons/photon_shards.h"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <stdexcept>

#include "formats/container_reader.h"
#include "formats/format_error.h"
#include "formats/photon_hits_summary.h"
#include "formats/section_ids.h"
#include "formats/tree_validation.h"

namespace kdpm {
namespace {

bool parse_count(std::string_view text, std::uint64_t& value) {
    if (text.empty() || text.size() > 20) return false;
    for (char c : text)
        if (c < '0' || c > '9') return false;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc{} && end == text.data() + text.size();
}

std::string parameter(const Metadata& m, const std::string& name) {
    auto it = m.parameters.find(name);
    return it == m.parameters.end() ? std::string("(none)") : it->second;
}

// Every fact of the shooting run except the path range must agree between shards.
void require_same_run(const PhotonShard& a, const PhotonShard& b) {
    auto refuse = [&](const std::string& what, const std::string& x, const std::string& y) {
        throw std::invalid_argument(a.name + " and " + b.name + " " + what + " (" + x + " vs " + y + ")");
    };
    const Metadata &ma = a.metadata, &mb = b.metadata;
    if (ma.source_hash != mb.source_hash) refuse("were shot from different scenes", ma.source_hash, mb.source_hash);
    for (const auto& [key, what] : {std::pair{"seed", "have different seeds"},
                                    std::pair{"photons", "have different photon totals"},
                                    std::pair{"bounces", "have different bounce limits"}}) {
        if (parameter(ma, key) != parameter(mb, key)) refuse(what, parameter(ma, key), parameter(mb, key));
    }
    if (ma.tool_version != mb.tool_version)
        refuse("were written by different kdpm versions", ma.tool_version, mb.tool_version);
    if (ma.source_path != mb.source_path) refuse("name different scene files", ma.source_path, mb.source_path);
    auto without_paths = [](std::map<std::string, std::string> p) {
        p.erase(kPathsParameter);
        return p;
    };
    if (without_paths(ma.parameters) != without_paths(mb.parameters))
        throw std::invalid_argument(a.name + " and " + b.name + " were shot with different parameters");
    const PhotonHitsInfo &ia = a.set.info, &ib = b.set.info;
    if (ia.emitted_count != ib.emitted_count || ia.max_bounces != ib.max_bounces ||
        std::memcmp(ia.emitted_power, ib.emitted_power, sizeof ia.emitted_power) != 0)
        throw std::invalid_argument(a.name + " and " + b.name + " disagree on the emitted photons in hits.info");
}

// Concatenation keeps the path order only when each shard's hits lie in its range, in order.
void require_hits_in_range(const PhotonShard& s) {
    std::uint64_t previous = s.paths.begin;
    for (const PhotonHit& h : s.set.hits) {
        if (h.path < previous || h.path >= s.paths.end)
            throw std::invalid_argument(s.name + " holds a photon of path " + std::to_string(h.path) +
                                        (h.path < previous ? " out of path order" : " outside its paths " +
                                                                                         path_range_text(s.paths)));
        previous = h.path;
    }
}

}  // namespace

PathRange parse_path_range(std::string_view text, std::uint64_t total) {
    const auto colon = text.find(':');
    PathRange r;
    if (colon == std::string_view::npos || !parse_count(text.substr(0, colon), r.begin) ||
        !parse_count(text.substr(colon + 1), r.end))
        throw std::invalid_argument("'" + std::string(text) + "' is not BEGIN:END (two path indices)");
    if (!(r.begin < r.end)) throw std::invalid_argument("path range " + std::string(text) + " is empty (BEGIN must be < END)");
    if (r.end > total)
        throw std::invalid_argument("path range " + std::string(text) + " ends beyond the " + std::to_string(total) +
                                    " photon paths");
    return r;
}

std::string path_range_text(PathRange range) { return std::to_string(range.begin) + ":" + std::to_string(range.end); }

PathRange photon_hits_path_range(const Metadata& metadata, const PhotonHitsInfo& info) {
    auto it = metadata.parameters.find(kPathsParameter);
    if (it == metadata.parameters.end()) return {0, info.emitted_count};
    try {
        return parse_path_range(it->second, info.emitted_count);
    } catch (const std::invalid_argument& e) {
        throw FormatError(std::string("metadata parameter paths: ") + e.what());
    }
}

PhotonShard read_photon_shard(const std::filesystem::path& path) {
    PhotonShard s;
    s.name = path.string();
    auto reader = ContainerReader::open(path, FileKind::photon_hits);
    validate_file(reader, ValidationOptions{});
    if (!reader.has_metadata()) throw FormatError(s.name + ": no metadata section (not written by kdpm-shoot-photons)");
    s.metadata = reader.metadata();
    if (s.metadata.tool != "kdpm-shoot-photons")
        throw FormatError(s.name + ": written by " + s.metadata.tool + ", not kdpm-shoot-photons");
    s.set.info = reader.record<PhotonHitsInfo>(section::hits_info);
    auto hits = reader.section<PhotonHit>(section::hits_photons);
    s.set.hits.assign(hits.begin(), hits.end());
    try {
        s.paths = photon_hits_path_range(s.metadata, s.set.info);
    } catch (const FormatError& e) {
        throw FormatError(s.name + ": " + e.what());
    }
    return s;
}

MergedPhotons merge_photon_shards(std::vector<PhotonShard> shards) {
    if (shards.empty()) throw std::invalid_argument("no shards to merge");
    for (const PhotonShard& s : shards) {
        require_same_run(shards.front(), s);
        require_hits_in_range(s);
    }
    std::sort(shards.begin(), shards.end(),
              [](const PhotonShard& a, const PhotonShard& b) { return a.paths.begin < b.paths.begin; });
    const std::uint64_t total = shards.front().set.info.emitted_count;
    std::uint64_t covered = 0;
    for (std::size_t i = 0; i < shards.size(); ++i) {
        const PathRange r = shards[i].paths;
        if (r.begin > covered)
            throw std::invalid_argument("paths " + path_range_text({covered, r.begin}) + " are in no shard");
        if (r.begin < covered)
            throw std::invalid_argument(shards[i - 1].name + " and " + shards[i].name + " overlap (paths " +
                                        path_range_text({r.begin, std::min(covered, r.end)}) + ")");
        covered = r.end;
    }
    if (covered < total) throw std::invalid_argument("paths " + path_range_text({covered, total}) + " are in no shard");

    MergedPhotons merged;
    merged.set.info = shards.front().set.info;
    merged.metadata = shards.front().metadata;
    std::size_t stored = 0;
    double rays = 0.0;
    for (const PhotonShard& s : shards) {
        stored += s.set.hits.size();
        auto it = s.metadata.statistics.find("rays");
        rays += it == s.metadata.statistics.end() ? 0.0 : it->second;
    }
    if (stored > 0xffffffffull) throw std::invalid_argument("the shards hold more than 2^32 - 1 photons together");
    merged.set.hits.reserve(stored);
    for (PhotonShard& s : shards) {
        merged.set.hits.insert(merged.set.hits.end(), s.set.hits.begin(), s.set.hits.end());
        std::vector<PhotonHit>().swap(s.set.hits);
    }
    summarize_photon_hits(merged.set.hits, merged.set.info);
    merged.metadata.parameters[kPathsParameter] = path_range_text({0, total});
    merged.metadata.statistics["stored"] = merged.set.info.stored_count;
    merged.metadata.statistics["caustic"] = merged.set.info.caustic_count;
    merged.metadata.statistics["rays"] = rays;
    return merged;
}

}  // namespace kdpm
