// Packets of rays through the kd-tree (kd_packet_traversal.h) return the single-ray walk's
// closest hits bit for bit: coherent packets walked as one, packets that are not (mixed
// direction signs, several origins) walked ray by ray, and the edge cases of the walk.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "builders/geometry/scene_card.h"
#include "runtime/geometry/kd_packet_traversal.h"
#include "tests/geometry/geometry_check.h"
#include "tests/geometry/random_scenes.h"
#include "tests/support/run_command.h"

using namespace kdpm;

namespace {

bool same_bits(const Hit& a, const Hit& b) { return std::memcmp(&a, &b, sizeof(Hit)) == 0; }

// The packet walks this CPU runs: SSE2 always, AVX2 and AVX-512 where the CPU has them.
std::vector<PacketIsa> packet_isas() {
    std::vector<PacketIsa> isas{PacketIsa::sse2};
#if defined(KDPM_PACKET_SIMD)
    if (packet_detail::cpu_has_avx2()) isas.push_back(PacketIsa::avx2);
    if (packet_detail::cpu_has_avx512()) isas.push_back(PacketIsa::avx512);
#endif
    return isas;
}

const char* isa_name(PacketIsa isa) {
    return isa == PacketIsa::avx512 ? "AVX-512" : isa == PacketIsa::avx2 ? "AVX2" : "SSE2";
}

// Lanes whose packet result differs from the single ray's binary walk (the packets walk the same
// kd-tree), over every packet walk: closest hits in any bit, occlusion (the same rays as shadow
// rays) at all.
int packet_mismatches(const GeometryView& g, const RayPacket& p) {
    int bad = 0;
    for (PacketIsa isa : packet_isas()) {
        Hit out[kPacketRays];
        bool blocked[kPacketRays];
        closest_hits(g, p, out, isa);
        occluded_rays(g, p, blocked, isa);
        for (std::uint32_t i = 0; i < p.count; ++i) {
            const Hit single = closest_hit_kd(g, p.ray(i));
            if (!same_bits(out[i], single)) {
                ++bad;
                UNSCOPED_INFO(isa_name(isa)
                              << " lane " << i << ": packet t " << out[i].t << " triangle " << out[i].triangle
                              << ", single t " << single.t << " triangle " << single.triangle);
            }
            if (blocked[i] != occluded_kd(g, p.ray(i))) {
                ++bad;
                UNSCOPED_INFO(isa_name(isa) << " lane " << i << ": packet occluded " << blocked[i]);
            }
        }
    }
    return bad;
}

// A packet of `count` rays from one origin, directions spread by `spread` around `centre`.
RayPacket cone_packet(std::mt19937& rng, glm::vec3 origin, glm::vec3 centre, float spread, std::uint32_t count,
                      float tmin = 0.0f, float tmax = 1e30f) {
    std::normal_distribution<float> g(0.0f, 1.0f);
    RayPacket p;
    for (std::uint32_t i = 0; i < count; ++i)
        p.set(p.count++, Ray{origin, tmin, centre + spread * glm::vec3(g(rng), g(rng), g(rng)), tmax});
    return p;
}

struct Counts {
    int mismatches = 0, as_one = 0, packets = 0;
};

Counts check_packets(const GeometryView& g, int packets, std::uint32_t seed, float lo, float hi) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(lo, hi), count(1.0f, 16.99f);
    std::normal_distribution<float> n(0.0f, 1.0f);
    Counts c;
    for (int k = 0; k < packets; ++k) {
        const glm::vec3 origin(u(rng), u(rng), u(rng));
        const glm::vec3 centre(n(rng), n(rng), n(rng));
        // Mostly narrow cones, some wide (direction signs mixed: still one walk), every seventh
        // packet partly filled, every eleventh from several origins (ray by ray).
        const float spread = k % 5 == 0 ? 1.0f : 0.02f;
        const std::uint32_t lanes = k % 7 == 0 ? static_cast<std::uint32_t>(count(rng)) : kPacketRays;
        RayPacket p = cone_packet(rng, origin, centre, spread, lanes);
        if (k % 11 == 0 && p.count > 1) p.origin[1][p.count - 1] += 0.01f;
        c.as_one += packet_detail::shares_origin(p);
        c.mismatches += packet_mismatches(g, p);
        ++c.packets;
    }
    return c;
}

}  // namespace

TEST_CASE("packets of rays return the single-ray walk's hits bit for bit on random soups",
          "[geometry][traversal][packets]") {
    const KdBuildParams params = test::quality_params(GENERATE(KdBuildQuality::high, KdBuildQuality::fast));
    INFO("quality: " << quality_name(params.quality));
    const auto bytes = test::build_bytes(scene_from_triangles(test::random_soup(3000, 11, 0.08f)), params);
    const GeometryFile file = GeometryFile::from_bytes(bytes, "soup.kdg");
    const Counts inside = check_packets(file.view(), 3000, 21, 0.0f, 1.0f);
    const Counts outside = check_packets(file.view(), 1000, 22, -2.0f, 3.0f);
    CHECK(inside.mismatches == 0);
    CHECK(outside.mismatches == 0);
    // Both paths ran: most packets as one, those from several origins ray by ray.
    CHECK(inside.as_one > inside.packets / 2);
    CHECK(inside.as_one < inside.packets);
    if (packet_isas().size() < 3) WARN("this CPU lacks AVX2 or AVX-512: only " << packet_isas().size() << " of the 3 packet walks were compared");
}

TEST_CASE("packets agree with single rays at the walk's edge cases", "[geometry][traversal][packets]") {
    // The grid with twins: split planes at exact coordinates the rays start on, and exact ties.
    const auto bytes = test::build_bytes(scene_from_triangles(test::grid_scene(true)));
    const GeometryFile file = GeometryFile::from_bytes(bytes, "grid.kdg");
    const GeometryView& g = file.view();
    std::mt19937 rng(3);

    SECTION("origins on split planes, directions with zero components, exact ties") {
        const glm::vec3 origins[] = {{0.25f, 0.25f, 0.5f}, {0.5f, 0.25f, 0.25f}, {0.125f, 0.375f, 0.5f},
                                     {0.0f, 0.0f, 0.0f},   {0.25f, 0.25f, 0.0f}, {0.375f, 0.125f, 0.0f}};
        const glm::vec3 dirs[] = {{0, 0, 1}, {0, 0, -1}, {0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {0.3f, 0.0f, -1.0f}, {0.0f, 0.2f, 1.0f}};
        for (const glm::vec3& o : origins)
            for (const glm::vec3& d : dirs) {
                // Exactly axis-aligned lanes beside slightly tilted ones of the same sign class.
                RayPacket p;
                for (std::uint32_t i = 0; i < kPacketRays; ++i) {
                    glm::vec3 dir = d;
                    if (i % 2) dir += 0.001f * static_cast<float>(i) * glm::vec3(d.x >= 0 ? 1 : -1, d.y >= 0 ? 1 : -1, d.z >= 0 ? 1 : -1);
                    p.set(p.count++, Ray{o, 0.0f, dir, 1e30f});
                }
                INFO("origin " << o.x << "," << o.y << "," << o.z << " direction " << d.x << "," << d.y << "," << d.z);
                CHECK(packet_mismatches(g, p) == 0);
            }
    }
    SECTION("limited segments: tmin past the start, tmax short of the scene") {
        for (int k = 0; k < 400; ++k) {
            const float tmin = k % 2 ? 0.3f : 0.0f, tmax = k % 3 ? 0.6f : 1e30f;
            const RayPacket p = cone_packet(rng, glm::vec3(0.5f, 0.6f, 0.1f), glm::vec3(0.1f, -0.5f, 0.8f), 0.05f,
                                            kPacketRays, tmin, tmax);
            CHECK(packet_mismatches(g, p) == 0);
        }
    }
    SECTION("lanes that miss the scene's box beside lanes that enter it") {
        for (int k = 0; k < 200; ++k) {
            const RayPacket p = cone_packet(rng, glm::vec3(-1.0f, 0.5f, 0.5f), glm::vec3(1.0f, 0.0f, 0.0f), 0.6f, kPacketRays);
            CHECK(packet_mismatches(g, p) == 0);
        }
    }
    SECTION("several origins: ray by ray, same hits") {
        RayPacket p = cone_packet(rng, glm::vec3(0.5f, 0.5f, -0.5f), glm::vec3(0, 0, 1), 0.1f, kPacketRays);
        p.origin[0][3] += 0.01f;
        CHECK_FALSE(packet_detail::shares_origin(p));
        CHECK(packet_mismatches(g, p) == 0);
    }
    SECTION("origins on split planes with direction signs mixed on the plane's axis") {
        // The single-ray walk breaks an origin-on-plane tie by each ray's sign: such a packet is
        // given back to the single-ray walk, and the answers stay the single rays'.
        const glm::vec3 origins[] = {{0.25f, 0.25f, 0.5f}, {0.5f, 0.25f, 0.25f}, {0.125f, 0.375f, 0.5f},
                                     {0.25f, 0.25f, 0.0f}, {0.375f, 0.125f, 0.0f}};
        const glm::vec3 dirs[] = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {0.3f, 0.2f, -1.0f}};
        int given_back = 0, walked = 0;
        for (const glm::vec3& o : origins)
            for (const glm::vec3& d : dirs)
                for (int axis = 0; axis < 3; ++axis) {
                    RayPacket p;
                    for (std::uint32_t i = 0; i < kPacketRays; ++i) {
                        glm::vec3 dir = d;
                        dir[axis] += (i % 2 ? 0.01f : -0.01f) * static_cast<float>(i + 1);
                        p.set(p.count++, Ray{o, 0.0f, dir, 1e30f});
                    }
                    INFO("origin " << o.x << "," << o.y << "," << o.z << " axis " << axis);
                    CHECK(packet_mismatches(g, p) == 0);
                    Hit out[kPacketRays];
                    (packet_detail::sse2::walk_simd<false>(g, p, out, nullptr) ? walked : given_back)++;
                }
        // Both happen on this grid: ties met (given back) and planes never touched (walked).
        CHECK(given_back > 0);
        CHECK(walked > 0);
    }
}

TEST_CASE("camera packets through the shipped Cornell box find every single-ray hit", "[geometry][traversal][packets]") {
    const Scene scene = load_scene_input(test::source_path("scenes/cornell-box/cornell-box.json"));
    const auto bytes = test::build_bytes(scene);
    const GeometryFile file = GeometryFile::from_bytes(bytes, "cornell-box.kdg");
    const glm::vec3 eye(0.0f, 1.0f, 3.9f);
    std::mt19937 rng(9);
    int found = 0;
    for (int k = 0; k < 2000; ++k) {
        std::uniform_real_distribution<float> u(-0.25f, 0.25f);
        const RayPacket p = cone_packet(rng, eye, glm::vec3(u(rng), u(rng), -1.0f), 0.005f, kPacketRays);
        CHECK(packet_mismatches(file.view(), p) == 0);
        Hit out[kPacketRays];
        closest_hits(file.view(), p, out);
        for (const Hit& h : out) found += h.found();
    }
    // Every ray passes the open front (under 0.3 of a unit per unit off axis) into the closed room.
    CHECK(found == 2000 * static_cast<int>(kPacketRays));
}
