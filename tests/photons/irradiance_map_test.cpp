// The .kdp's optional irradiance map (format 1.1): what kdpm-build-photons stores equals a
// brute-force k-nearest estimate at the chosen photons, the validator refuses broken maps,
// and 1.0 files without the map still load.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "builders/photons/photon_map_writer.h"
#include "builders/photons/photon_tree_writer.h"
#include "formats/container_reader.h"
#include "formats/tree_validation.h"
#include "runtime/photons/irradiance_precompute.h"
#include "runtime/photons/photon_map_file.h"
#include "runtime/shading/constants.h"
#include "runtime/shading/diffuse.h"
#include "tests/photons/synthetic_photons.h"
#include "tests/support/error_text.h"
#include "tests/support/built_tree_view.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"
#include "tools/photons/irradiance_step.h"

using namespace kdpm;

namespace {

constexpr std::uint32_t kK = 48;  // over 32: the sector share applies

IrradiancePrecompute every_nth(std::uint32_t every) { return every_nth_photon_irradiance(every, kK); }

// Jensen's estimate by sorting every photon by distance: the k nearest that may light the
// surface (the runtime's photon filter and plane test), r the k-th distance or the search limit,
// the disc's area counted over its 16 cells (45-degree sectors about the normal in two rings of
// equal area) that hold a photon, over the share a full disc's photons would cover on average.
// Returns false when the k-th and (k+1)-th distances tie (then the choice of photon is arbitrary).
bool brute_force_irradiance(const PhotonMapView& map, std::uint32_t slot, const RadianceEstimateParams& params,
                            glm::vec3& out) {
    const glm::vec3 p(map.x[slot], map.y[slot], map.z[slot]);
    float n[3];
    decode_octahedral(map.directions[slot].normal, n);
    const SurfacePhotonFilter filter(map, glm::vec3(n[0], n[1], n[2]), params.min_normal_cos, 0, 0);
    const float limit2 = params.max_radius > 0.0f ? params.max_radius * params.max_radius : INFINITY;
    std::vector<std::pair<float, std::uint32_t>> near;
    for (std::uint32_t j = 0; j < map.photon_count; ++j) {
        const glm::vec3 d = glm::vec3(map.x[j], map.y[j], map.z[j]) - p;
        const float d2 = d.x * d.x + d.y * d.y + d.z * d.z;
        const float h = glm::dot(d, glm::vec3(n[0], n[1], n[2]));
        const bool on_plane = std::fabs(h) <= params.plane_distance ||
                              std::fabs(h) <= kPlaneSlope * std::sqrt(std::max(0.0f, d2 - h * h));
        if (d2 < limit2 && filter(j) && on_plane) near.emplace_back(d2, j);
    }
    std::sort(near.begin(), near.end());
    if (near.size() > params.k && near[params.k - 1].first == near[params.k].first) return false;
    const std::size_t used = std::min<std::size_t>(near.size(), params.k);
    const float r2 = used == params.k ? near[used - 1].first : limit2;
    glm::vec3 flux(0.0f), t, b;
    tangent_frame(glm::vec3(n[0], n[1], n[2]), t, b);
    bool cell[16] = {};
    for (std::size_t i = 0; i < used; ++i) {
        const std::uint32_t j = near[i].second;
        flux += photon_power(map.power[j]);
        const glm::vec3 d = glm::vec3(map.x[j], map.y[j], map.z[j]) - p;
        const double u = glm::dot(d, t), v = glm::dot(d, b);
        const double angle = std::atan2(v, u);  // (-pi, pi]
        const int ring = u * u + v * v < 0.5 * r2 ? 0 : 8;
        cell[(static_cast<int>(std::floor((angle + kPi) / (kPi / 4.0))) & 7) + ring] = true;
    }
    const double full = 1.0 - std::pow(15.0 / 16.0, static_cast<double>(used));
    const double share =
        used >= 32 ? std::min(1.0, static_cast<double>(std::count(cell, cell + 16, true)) / (16.0 * full)) : 1.0;
    out = used == 0 ? glm::vec3(0.0f) : flux / static_cast<float>(kPi * r2 * share);
    REQUIRE(params.plane_distance > 0.0f);
    return true;
}

std::vector<std::uint8_t> map_file_bytes(const PhotonHitSet& set, std::uint32_t every) {
    return build_photon_map_file(set, PhotonTreeOptions{}, Metadata{}, every_nth(every)).writer.bytes();
}

// A .kdp holding a global map and an irradiance map over it, as the builders write them.
std::vector<std::uint8_t> photon_file_bytes(const BuiltPhotonTree& global, const BuiltIrradianceMap& irradiance) {
    ContainerWriter w(FileKind::photon_tree);
    add_photon_tree_sections(w, PhotonMapKind::global, global);
    add_irradiance_map_sections(w, irradiance);
    w.set_metadata(Metadata{});
    return w.bytes();
}

void validate_bytes(const std::vector<std::uint8_t>& bytes) {
    auto reader = ContainerReader::from_bytes(bytes, "x.kdp");
    validate_file(reader, ValidationOptions{});
}

}  // namespace

TEST_CASE("the irradiance map round-trips and holds the k-nearest irradiance at every 4th photon",
          "[photons][irradiance]") {
    const PhotonHitSet set = test::synthetic_photons(3000, 21);
    const auto bytes = map_file_bytes(set, 4);
    const PhotonMapFile file = PhotonMapFile::from_bytes(bytes, "m.kdp");
    CHECK(file.container().header().version_minor == 1);
    const PhotonMapView global = file.view(PhotonMapKind::global);
    const IrradianceMapView irr = file.irradiance_map();
    REQUIRE(irr.present());
    REQUIRE(irr.photons.photon_count == (global.photon_count + 3) / 4);
    auto source =
        file.container().section<std::uint32_t>(photon_tree_section(PhotonMapKind::irradiance, ptree_field_source));
    std::vector<std::uint32_t> sorted(source.begin(), source.end());
    std::sort(sorted.begin(), sorted.end());
    CHECK(sorted == every_nth_photon(global.photon_count, 4));

    const RadianceEstimateParams params = irradiance_estimate_params(kK, file.info().query_radius);
    REQUIRE(params.max_radius > 0.0f);
    std::uint32_t compared = 0, lit = 0;
    for (std::uint32_t i = 0; i < irr.photons.photon_count; ++i) {
        const std::uint32_t s = source[i];
        CHECK(irr.photons.x[i] == global.x[s]);
        CHECK(irr.photons.z[i] == global.z[s]);
        glm::vec3 expected;
        if (!brute_force_irradiance(global, s, params, expected)) continue;
        ++compared;
        for (int c = 0; c < 3; ++c) {
            INFO("photon " << i << " (global " << s << ") channel " << c);
            CHECK(irr.irradiance[i].rgb[c] == Approx(expected[c]).epsilon(1e-5).margin(1e-12));
        }
        lit += expected.x > 0.0f;
    }
    CHECK(compared > irr.photons.photon_count * 9 / 10);
    CHECK(lit > compared / 2);
}

TEST_CASE("broken irradiance maps are refused by the validator and the loader", "[photons][irradiance][corrupt]") {
    const PhotonHitSet set = test::synthetic_photons(2000, 22);
    const BuiltPhotonTree global =
        build_photon_tree(set.hits, PhotonTreeOptions{}, set.info.emitted_count, set.info.max_bounces);
    const BuiltIrradianceMap good = build_irradiance_map(global, set.hits, every_nth(4)(global), PhotonTreeOptions{});
    auto bytes_with = [&](auto edit) {
        BuiltIrradianceMap m = good;
        edit(m);
        return photon_file_bytes(global, m);
    };
    CHECK_NOTHROW(validate_bytes(bytes_with([](BuiltIrradianceMap&) {})));
    const std::pair<const char*, std::vector<std::uint8_t>> cases[] = {
        {"one irradiance too few", bytes_with([](BuiltIrradianceMap& m) { m.irradiance.pop_back(); })},
        {"one source too many", bytes_with([](BuiltIrradianceMap& m) { m.global_slot.push_back(0); })},
        {"NaN", bytes_with([](BuiltIrradianceMap& m) { m.irradiance[5].rgb[1] = std::nanf(""); })},
        {"infinity", bytes_with([](BuiltIrradianceMap& m) { m.irradiance[0].rgb[2] = INFINITY; })},
        {"negative", bytes_with([](BuiltIrradianceMap& m) { m.irradiance[7].rgb[0] = -1.0f; })},
        {"source out of range",
         bytes_with([&](BuiltIrradianceMap& m) { m.global_slot[3] = global.info.photon_count; })},
        {"source twice", bytes_with([](BuiltIrradianceMap& m) { m.global_slot[3] = m.global_slot[4]; })},
        {"source elsewhere", bytes_with([](BuiltIrradianceMap& m) { std::swap(m.global_slot[3], m.global_slot[9]); })},
    };
    for (const auto& [what, bytes] : cases) {
        INFO(what);
        CHECK_THROWS_AS(validate_bytes(bytes), FormatError);
        CHECK_THROWS_AS(PhotonMapFile::from_bytes(bytes, "bad.kdp"), FormatError);
    }
}

TEST_CASE("a format 1.0 .kdp without the irradiance map still loads", "[photons][irradiance][version]") {
    const PhotonHitSet set = test::synthetic_photons(1000, 23);
    PhotonMapBuild built = build_photon_map_file(set, PhotonTreeOptions{}, Metadata{});
    built.writer.set_version(1, 0);
    const auto bytes = built.writer.bytes();
    CHECK_NOTHROW(validate_bytes(bytes));
    const PhotonMapFile file = PhotonMapFile::from_bytes(bytes, "old.kdp");
    CHECK(file.container().header().version_minor == 0);
    CHECK_FALSE(file.has_map(PhotonMapKind::irradiance));
    CHECK_FALSE(file.irradiance_map().present());
    CHECK(file.view(PhotonMapKind::global).photon_count == 1000);
}

TEST_CASE("kdpm-build-photons stores the irradiance map by default, kdpm-inspect lists it",
          "[photons][irradiance][tools]") {
    test::TempDir dir;
    const auto hits = dir / "p.kdph", with = dir / "with.kdp", without = dir / "without.kdp";
    test::write_photon_hits_file(test::synthetic_photons(4000, 24), hits);
    auto r = test::run_tool("kdpm-build-photons " + hits.string() + " -o " + with.string() + " --irradiance-every 8");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.output, Catch::Contains("500 with irradiance"));
    const PhotonMapFile file = PhotonMapFile::open(with);
    CHECK(file.irradiance_map().photons.photon_count == 500);
    CHECK(file.metadata().parameters.at("irradiance_every") == "8");
    auto inspect = test::run_tool("kdpm-inspect " + with.string());
    CHECK_THAT(inspect.output,
               Catch::Contains("irradiance_tree.irradiance") && Catch::Contains("irradiance_tree.source"));
    CHECK(test::run_tool("kdpm-validate " + with.string()).exit_code == 0);

    REQUIRE(test::run_tool("kdpm-build-photons " + hits.string() + " -o " + without.string() +
                           " --irradiance-every 0 --quiet").exit_code == 0);
    CHECK_FALSE(PhotonMapFile::open(without).has_map(PhotonMapKind::irradiance));
    const std::string bad_k = "kdpm-build-photons " + hits.string() + " -o " + without.string() + " --irradiance-k 0";
    CHECK(test::run_tool(bad_k).exit_code == 2);
}

TEST_CASE("a gather hit reads the irradiance of the nearest chosen photon on its surface",
          "[photons][irradiance]") {
    const PhotonHitSet set = test::synthetic_photons(4000, 25);
    const auto bytes = map_file_bytes(set, 4);
    const PhotonMapFile file = PhotonMapFile::from_bytes(bytes, "m.kdp");
    const IrradianceMapView irr = file.irradiance_map();
    REQUIRE(irr.present());
    const PhotonMapView& map = irr.photons;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const glm::vec3 normals[] = {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, -1, 0}};
    const float radius = 0.08f, min_cos = 0.7f;
    KnnHeap heap{};
    std::uint32_t found = 0, missed = 0;
    for (int q = 0; q < 400; ++q) {
        const glm::vec3 p(u(rng), u(rng) * 0.2f, u(rng));
        const glm::vec3 n = normals[q % 4];
        // The nearest photon whose surface agrees, by looking at every one.
        const SurfacePhotonFilter accept(map, n, min_cos, 0, 0);
        float best = radius * radius;
        std::int64_t nearest = -1;
        for (std::uint32_t j = 0; j < map.photon_count; ++j) {
            const glm::vec3 d = glm::vec3(map.x[j], map.y[j], map.z[j]) - p;
            const float d2 = glm::dot(d, d);
            if (d2 < best && accept(j)) best = d2, nearest = j;
        }
        glm::vec3 e(-1.0f);
        const bool hit = lookup_irradiance(irr, p, n, radius, min_cos, 0.0f, heap, e);
        INFO("query " << q);
        REQUIRE(hit == (nearest >= 0));
        if (!hit) {
            ++missed;
            continue;
        }
        ++found;
        // Ties at equal distance may pick either photon: compare distances, then the value.
        const glm::vec3 d = glm::vec3(map.x[heap.index[0]], map.y[heap.index[0]], map.z[heap.index[0]]) - p;
        CHECK(glm::dot(d, d) == best);
        if (heap.index[0] == nearest)
            for (int c = 0; c < 3; ++c) CHECK(e[c] == irr.irradiance[nearest].rgb[c]);
    }
    CHECK(found > 50);
    CHECK(missed > 50);  // among them the (0, -1, 0) queries: no photon faces down
}

TEST_CASE("a large file with faults in several maps names the first, whichever thread checks it",
          "[photons][irradiance][corrupt]") {
    // Over a megabyte: a second thread checksums and takes the irradiance map's passes from the
    // back while the global map is checked (tree_validation.cpp); the message must be the one a
    // check of the maps in file order gives.
    const PhotonHitSet set = test::synthetic_photons(60000, 25);
    const BuiltPhotonTree global =
        build_photon_tree(set.hits, PhotonTreeOptions{}, set.info.emitted_count, set.info.max_bounces);
    const BuiltIrradianceMap irradiance =
        build_irradiance_map(global, set.hits, every_nth(4)(global), PhotonTreeOptions{});
    auto bytes_with = [&](auto edit_global, auto edit_irradiance) {
        BuiltPhotonTree g = global;
        BuiltIrradianceMap m = irradiance;
        edit_global(g);
        edit_irradiance(m);
        return photon_file_bytes(g, m);
    };
    auto message = [](const std::vector<std::uint8_t>& bytes) { return test::error_text([&] { validate_bytes(bytes); }); };
    auto keep_global = [](BuiltPhotonTree&) {};
    auto keep_irradiance = [](BuiltIrradianceMap&) {};
    auto negative = [](BuiltIrradianceMap& m) { m.irradiance[m.irradiance.size() / 2].rgb[0] = -1.0f; };
    auto moved = [](BuiltPhotonTree& t) { t.x[t.x.size() / 3] = t.info.bounds_min[0] - 1.0f; };
    auto short_x = [](BuiltPhotonTree& t) { t.x.pop_back(); };

    const auto good = bytes_with(keep_global, keep_irradiance);
    REQUIRE(good.size() > (std::size_t{1} << 20));
    CHECK(message(good) == "accepted");
    for (int run = 0; run < 4; ++run) {
        const std::string only_irradiance = message(bytes_with(keep_global, negative));
        INFO(only_irradiance);
        CHECK_THAT(only_irradiance, Catch::Contains("irradiance tree: photon") && Catch::Contains("negative irradiance"));
        const std::string both = message(bytes_with(moved, negative));
        INFO(both);
        CHECK_THAT(both, Catch::StartsWith("x.kdp: photon tree: photon") && Catch::Contains("lies outside the cell"));
        // The irradiance check reads the global map's positions: it must refuse a short array
        // itself (the global map's pass may not have run yet), and the global map's fault is named.
        const std::string short_positions = message(bytes_with(short_x, keep_irradiance));
        INFO(short_positions);
        CHECK_THAT(short_positions, Catch::Contains("photon tree: photon arrays do not all hold"));
        CHECK_THROWS_AS(PhotonMapFile::from_bytes(bytes_with(short_x, keep_irradiance), "short.kdp"), FormatError);
    }
}
