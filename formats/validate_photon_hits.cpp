#include <cmath>
#include <string>

#include "formats/photon_layout.h"
#include "formats/section_ids.h"
#include "formats/validate_kinds.h"

namespace kdpm {
namespace {

bool finite3(const float v[3]) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

// A unit vector within the tolerance a writer's float rounding leaves.
bool unit3(const float v[3]) {
    if (!finite3(v)) return false;
    float len2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    return std::fabs(len2 - 1.0f) < 1e-3f;
}

}  // namespace

// Every hit: finite position inside the info bounds, finite non-negative power, unit direction
// and normal, only known flags, bounce within the limit; counts agree with the info record.
void validate_photon_hits_file(const ContainerReader& file, const ValidationOptions&) {
    const std::string& name = file.name();
    const auto& info = file.record<PhotonHitsInfo>(section::hits_info);
    auto hits = file.section<PhotonHit>(section::hits_photons);
    auto fail = [&](const std::string& why) { throw FormatError(name + ": " + why); };

    if (info.stored_count != hits.size())
        fail("hits.info says " + std::to_string(info.stored_count) + " photons but hits.photons holds " +
             std::to_string(hits.size()));
    if (info.stored_count > 0 && info.emitted_count == 0) fail("photons stored but none emitted");
    if (!finite3(info.bounds_min) || !finite3(info.bounds_max) || !finite3(info.emitted_power))
        fail("hits.info has a non-finite bound or power");
    if (info.max_bounces > 255) fail("hits.info max_bounces " + std::to_string(info.max_bounces) + " exceeds 255");

    std::uint64_t caustic = 0;
    for (std::size_t i = 0; i < hits.size(); ++i) {
        const PhotonHit& h = hits[i];
        auto bad = [&](const std::string& why) { fail("photon " + std::to_string(i) + " " + why); };
        if (!finite3(h.position)) bad("has a non-finite position");
        for (int a = 0; a < 3; ++a)
            if (h.position[a] < info.bounds_min[a] || h.position[a] > info.bounds_max[a]) bad("lies outside hits.info bounds");
        if (!finite3(h.power) || h.power[0] < 0.0f || h.power[1] < 0.0f || h.power[2] < 0.0f)
            bad("has a negative or non-finite power");
        if (!unit3(h.direction)) bad("has a direction that is not a unit vector");
        if (!unit3(h.normal)) bad("has a normal that is not a unit vector");
        if (h.flags & ~kPhotonKnownFlags) bad("has unknown flag bits");
        if (photon_bounce(h.flags) > info.max_bounces) bad("has a bounce beyond max_bounces");
        if (h.path >= info.emitted_count) bad("names a path beyond emitted_count");
        if (h.flags & kPhotonCaustic) ++caustic;
    }
    if (caustic != info.caustic_count)
        fail("hits.info says " + std::to_string(info.caustic_count) + " caustic photons, found " + std::to_string(caustic));
}

}  // namespace kdpm
