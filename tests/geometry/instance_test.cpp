// Scenes of instances (format 1.3): object files placed by affine maps, opened by GeometryFile,
// walked through the instance BVH. References: brute force over every instance's triangles, and
// the same scene flattened (every triangle mapped into the world, one tree).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "builders/geometry/geometry_file_builder.h"
#include "formats/container_writer.h"
#include "formats/instance_layout.h"
#include "formats/section_ids.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/geometry/instance_hit.h"
#include "runtime/geometry/kd_packet_traversal.h"
#include "runtime/geometry/packet_box_test.h"
#include "runtime/geometry/scene_traversal.h"
#include "tests/geometry/random_scenes.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

namespace {

struct Placement {
    Affine map;
    std::uint32_t object;
};

// Rotation about a unit-ish axis by `degrees`, scaled, then moved.
Affine placement(float axis_x, float axis_y, float axis_z, float degrees, float sx, float sy, float sz, float tx,
                 float ty, float tz) {
    const float len = std::sqrt(axis_x * axis_x + axis_y * axis_y + axis_z * axis_z);
    const float x = axis_x / len, y = axis_y / len, z = axis_z / len;
    const float a = degrees * 3.14159265f / 180.0f, c = std::cos(a), s = std::sin(a), k = 1.0f - c;
    const float r[3][3] = {{c + x * x * k, x * y * k - z * s, x * z * k + y * s},
                           {y * x * k + z * s, c + y * y * k, y * z * k - x * s},
                           {z * x * k - y * s, z * y * k + x * s, c + z * z * k}};
    const float scale[3] = {sx, sy, sz}, t[3] = {tx, ty, tz};
    Affine m{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m.m[i][j] = r[i][j] * scale[j];
        m.m[i][3] = t[i];
    }
    return m;
}

Scene object_scene(std::uint32_t triangles, std::uint32_t seed, bool with_light) {
    Scene s = scene_from_triangles(test::random_soup(triangles, seed, 0.2f));
    if (with_light) {
        const float p0[3] = {0.2f, 1.1f, 0.2f}, e1[3] = {0.3f, 0.0f, 0.0f}, e2[3] = {0.0f, 0.0f, 0.3f},
                    radiance[3] = {1.0f, 2.0f, 3.0f};
        s.lights.push_back(make_parallelogram_light(p0, e1, e2, radiance));
    }
    return s;
}

// A scene file placing the object files `names` (in `folder`) as `placements`.
ContainerWriter scene_of_instances(const std::filesystem::path& folder, const std::vector<std::string>& names,
                                   const std::vector<Placement>& placements) {
    ContainerWriter w(FileKind::geometry);
    GeometryInfo info{};
    for (int a = 0; a < 3; ++a) info.bounds_min[a] = -10.0f, info.bounds_max[a] = 10.0f;
    info.default_photons = 1000, info.default_bounces = 2, info.default_k = 16, info.up_axis = 1;
    w.add_record(section::geo_info, info);
    w.add_record(section::geo_camera, GeometryFile::open(folder / names[0]).camera());
    w.add(section::geo_lights, ElementType::record, std::vector<AreaLightRecord>{});
    std::vector<ObjectReference> objects;
    for (const std::string& n : names) {
        ObjectReference o{};
        std::strncpy(o.path, n.c_str(), kObjectPathBytes - 1);
        const GeometryFile f = GeometryFile::open(folder / n);
        o.content_hash = f.content_hash();
        o.triangle_count = f.info().triangle_count;
        objects.push_back(o);
    }
    w.add(section::geo_objects, ElementType::record, objects);
    std::vector<InstanceRecord> records;
    for (const Placement& p : placements) {
        InstanceRecord r{};
        std::memcpy(r.world_from_object, p.map.m, sizeof r.world_from_object);
        r.object = p.object;
        records.push_back(r);
    }
    w.add(section::geo_instances, ElementType::record, records);
    return w;
}

// Every instance's triangles mapped into the world the way world_triangle maps them.
std::vector<TriangleRecord> flattened(const GeometryView& g) {
    std::vector<TriangleRecord> out;
    for (std::uint32_t i = 0; i < g.instance_count; ++i) {
        const GeometryView& o = g.objects[g.instances[i].object];
        for (std::uint32_t t = 0; t < o.triangle_count; ++t) out.push_back(world_triangle(g, Hit{1.0f, t, 0, 0, i}));
    }
    return out;
}

std::vector<Placement> test_placements() {
    std::vector<Placement> p;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (std::uint32_t i = 0; i < 40; ++i) {
        const float sx = 0.5f + 0.5f * std::fabs(u(rng));
        // One in five mirrored (negative determinant), some stretched unevenly.
        const float sy = (i % 5 == 3 ? -1.0f : 1.0f) * (i % 3 == 0 ? 2.0f * sx : sx);
        p.push_back({placement(u(rng), u(rng), u(rng) + 0.1f, 180.0f * u(rng), sx, sy, sx, 4.0f * u(rng),
                               4.0f * u(rng), 4.0f * u(rng)),
                     i % 2});
    }
    return p;
}

struct Fixture {
    test::TempDir dir;
    std::vector<Placement> placements = test_placements();
    Fixture() {
        build_geometry_file(object_scene(300, 11, false), KdBuildParams{}).writer.write(dir / "a.kdg");
        build_geometry_file(object_scene(200, 12, true), KdBuildParams{}).writer.write(dir / "b.kdg");
        scene_of_instances(dir.path(), {"a.kdg", "b.kdg"}, placements).write(dir / "scene.kdg");
    }
};

std::vector<Ray> world_rays(std::uint32_t n, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-6.0f, 6.0f);
    std::vector<Ray> rays;
    for (std::uint32_t i = 0; i < n; ++i) {
        const glm::vec3 o(u(rng), u(rng), u(rng)), target(u(rng) * 0.7f, u(rng) * 0.7f, u(rng) * 0.7f);
        rays.push_back(Ray{o, 0.0f, target - o, 1e30f});
    }
    return rays;
}

}  // namespace

TEST_CASE("a scene of instances finds the hits brute force finds over every placed triangle", "[instances]") {
    Fixture f;
    const GeometryFile scene = GeometryFile::open(f.dir / "scene.kdg");
    const GeometryView& g = scene.view();
    REQUIRE(g.instance_count == 40);
    REQUIRE(g.object_count == 2);
    std::uint32_t found = 0, differ = 0, occlusion_differs = 0;
    for (const Ray& r : world_rays(20000, 3)) {
        const Hit h = closest_hit(g, r), b = closest_hit_brute_force(g, r);
        found += b.found();
        const bool same = h.found() == b.found() &&
                          (!b.found() || (h.instance == b.instance && h.triangle == b.triangle) || h.t == b.t);
        differ += !same;
        occlusion_differs += occluded(g, r) != b.found();
    }
    CHECK(found > 4000);  // the rays do meet the instances
    CHECK(differ <= 2);
    CHECK(occlusion_differs <= 2);
}

TEST_CASE("a scene of instances hits what the same scene flattened into one tree hits", "[instances]") {
    Fixture f;
    const GeometryFile scene = GeometryFile::open(f.dir / "scene.kdg");
    const GeometryView& g = scene.view();
    const auto flat_build = build_geometry_file(scene_from_triangles(flattened(g)), KdBuildParams{});
    const auto bytes = flat_build.writer.bytes();
    const GeometryFile flat = GeometryFile::from_bytes(bytes, "flattened");
    std::uint32_t found = 0, differ = 0, surface_differs = 0;
    for (const Ray& r : world_rays(20000, 4)) {
        const Hit h = closest_hit(g, r), q = closest_hit(flat.view(), r);
        found += q.found();
        if (h.found() != q.found() || (q.found() && std::fabs(h.t - q.t) > 1e-4f * q.t)) {
            ++differ;
            continue;
        }
        if (!q.found()) continue;
        // The same world point and the same facing of the geometric normal.
        const glm::vec3 ph = surface_point(world_triangle(g, h), h.u, h.v);
        const glm::vec3 pq = surface_point(flat.view().triangles[q.triangle], q.u, q.v);
        const glm::vec3 nh = geometric_normal(world_triangle(g, h)), nq = geometric_normal(flat.view().triangles[q.triangle]);
        surface_differs += glm::length(ph - pq) > 1e-4f || glm::dot(nh, nq) < 0.999f;
    }
    CHECK(found > 4000);
    CHECK(differ <= 20);  // grazing rays at shared edges (0.1 %)
    CHECK(surface_differs <= 20);
}

TEST_CASE("a packet's box test answers each lane as the single ray's box test does", "[instances][packets]") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-4.0f, 4.0f);
    std::uint32_t entered = 0, differ = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        RayPacket p;
        p.count = 1 + trial % kPacketRays;
        const glm::vec3 o(u(rng), u(rng), u(rng));
        for (std::uint32_t i = 0; i < p.count; ++i) {
            glm::vec3 d(u(rng), u(rng), u(rng));
            if (i % 5 == 4) d[i % 3] = 0.0f;  // axis-parallel rays: 1/d is infinite
            p.set(i, Ray{o, 0.1f * std::fabs(u(rng)), d, trial % 2 ? 1e30f : std::fabs(u(rng))});
        }
        InstanceNode box{};
        for (int a = 0; a < 3; ++a) {
            const float x = u(rng), y = u(rng);
            box.lo[a] = std::min(x, y), box.hi[a] = std::max(x, y);
        }
        const PacketBoxTest test(p.origin, p.direction, p.tmin, p.tmax, p.count);
        const std::uint32_t lanes = test.entering(box.lo, box.hi);
        for (std::uint32_t i = 0; i < p.count; ++i) {
            const Ray r = p.ray(i);
            const glm::vec3 inv(1.0f / r.direction.x, 1.0f / r.direction.y, 1.0f / r.direction.z);
            float t;
            const bool one = instance_detail::enter_box(box, r.origin, inv, r.tmin, r.tmax, t);
            entered += one;
            differ += one != bool(lanes >> i & 1u);
        }
    }
    CHECK(entered > 1000);  // about one lane in six enters
    CHECK(differ == 0);
}

TEST_CASE("packets in a scene of instances hit what their rays hit one by one", "[instances][packets]") {
    Fixture f;
    const GeometryFile scene = GeometryFile::open(f.dir / "scene.kdg");
    const GeometryView& g = scene.view();
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::uint32_t found = 0, differ = 0, occlusion_differs = 0, packets = 0;
    for (PacketIsa isa : {PacketIsa::sse2, PacketIsa::best}) {
        for (int trial = 0; trial < 600; ++trial) {
            // A camera-like bundle from one origin (a shared origin stays shared in every object's
            // frame), some of them cut short as shadow rays are; the last packets partly full.
            RayPacket p;
            const glm::vec3 o(6.0f * u(rng), 6.0f * u(rng), 6.0f * u(rng));
            const glm::vec3 aim = glm::vec3(2.0f * u(rng), 2.0f * u(rng), 2.0f * u(rng)) - o;
            p.count = trial % 7 == 0 ? 1 + trial % kPacketRays : kPacketRays;
            for (std::uint32_t i = 0; i < p.count; ++i) {
                const glm::vec3 d = aim + 0.15f * glm::length(aim) * glm::vec3(u(rng), u(rng), u(rng));
                p.set(i, Ray{o, 0.0f, d, trial % 3 == 0 ? 0.5f + 0.5f * u(rng) : 1e30f});
            }
            Hit hits[kPacketRays];
            bool blocked[kPacketRays];
            closest_hits(g, p, hits, isa);
            occluded_rays(g, p, blocked, isa);
            ++packets;
            for (std::uint32_t i = 0; i < p.count; ++i) {
                const Hit one = closest_hit(g, p.ray(i));
                found += one.found();
                // The same distance (a different triangle only at a tie, where two meet).
                differ += hits[i].found() != one.found() || (one.found() && hits[i].t != one.t);
                occlusion_differs += blocked[i] != occluded(g, p.ray(i));
            }
        }
    }
    CHECK(packets == 1200);
    CHECK(found > 3000);
    CHECK(differ <= 2);  // grazing rays the binary and the wide walk tell apart
    CHECK(occlusion_differs <= 2);
}

TEST_CASE("a scene of instances places its objects' lights in the world", "[instances]") {
    Fixture f;
    const GeometryFile scene = GeometryFile::open(f.dir / "scene.kdg");
    const GeometryView& g = scene.view();
    REQUIRE(g.light_count == 20);  // object b (one light) is placed by every second instance
    const GeometryView& b = g.objects[1];
    std::uint32_t light = 0;
    for (std::uint32_t i = 1; i < g.instance_count; i += 2, ++light) {
        const Affine& m = f.placements[i].map;
        const AreaLightRecord& l = g.lights[light];
        const glm::vec3 p0 = apply_point(m, to_vec3(b.lights[0].p0));
        CHECK(glm::length(to_vec3(l.p0) - p0) < 1e-5f);
        const float area = glm::length(glm::cross(apply_vector(m, to_vec3(b.lights[0].e1)), apply_vector(m, to_vec3(b.lights[0].e2))));
        CHECK(l.area == Approx(area).epsilon(1e-5));
        CHECK(l.power == Approx(3.14159265f * area * 2.0f).epsilon(1e-5));
    }
}

TEST_CASE("a scene of instances whose object was rebuilt is refused with one line", "[instances]") {
    Fixture f;
    build_geometry_file(object_scene(300, 99, false), KdBuildParams{}).writer.write(f.dir / "a.kdg");
    try {
        GeometryFile::open(f.dir / "scene.kdg");
        FAIL("a stale object reference was read");
    } catch (const FormatError& e) {
        const std::string what = e.what();
        CHECK(what.find("a.kdg has changed since the scene was built") != std::string::npos);
        CHECK(what.find('\n') == std::string::npos);
    }
    // Built again from the same triangles, it is the same file (builds are deterministic).
    build_geometry_file(object_scene(300, 11, false), KdBuildParams{}).writer.write(f.dir / "a.kdg");
    CHECK(GeometryFile::open(f.dir / "scene.kdg").view().instance_count == 40);
    std::filesystem::remove(f.dir / "b.kdg");
    CHECK_THROWS_WITH(GeometryFile::open(f.dir / "scene.kdg"), Catch::Contains("object b.kdg"));
}

TEST_CASE("a scene of instances with a bad record is refused, its fault named", "[instances]") {
    Fixture f;
    auto refused = [&](std::vector<Placement> placements, const std::string& why) {
        const auto bytes = scene_of_instances(f.dir.path(), {"a.kdg", "b.kdg"}, placements).bytes();
        CHECK_THROWS_WITH(GeometryFile::from_bytes(bytes, "bad.kdg", f.dir.path()), Catch::Contains(why));
    };
    Affine singular = identity_affine();
    singular.m[2][0] = 0.0f, singular.m[2][1] = 0.0f, singular.m[2][2] = 0.0f;
    refused({{singular, 0}}, "instance 0 has a transform that is not finite or not invertible");
    Affine infinite = identity_affine();
    infinite.m[0][3] = INFINITY;
    refused({{identity_affine(), 0}, {infinite, 1}}, "instance 1 has a transform that is not finite");
    refused({{identity_affine(), 2}}, "instance 0 names an object out of range");
    refused({}, "it has no instances");

    // Its own triangles beside instances: an old reader would draw them alone.
    ContainerWriter w = scene_of_instances(f.dir.path(), {"a.kdg"}, {{identity_affine(), 0}});
    w.add(section::geo_triangles, ElementType::record, test::random_soup(3, 1));
    const auto bytes = w.bytes();
    CHECK_THROWS_WITH(GeometryFile::from_bytes(bytes, "own.kdg", f.dir.path()), Catch::Contains("no triangles of its own"));

    // An object that places instances itself.
    scene_of_instances(f.dir.path(), {"a.kdg"}, {{identity_affine(), 0}}).write(f.dir / "nested.kdg");
    const auto nested = scene_of_instances(f.dir.path(), {"nested.kdg"}, {{identity_affine(), 0}}).bytes();
    CHECK_THROWS_WITH(GeometryFile::from_bytes(nested, "outer.kdg", f.dir.path()), Catch::Contains("one level deep"));
}

TEST_CASE("a scene of one mesh keeps its own tree: no instance walk", "[instances]") {
    const auto bytes = build_geometry_file(object_scene(100, 5, false), KdBuildParams{}).writer.bytes();
    const GeometryFile file = GeometryFile::from_bytes(bytes, "one.kdg");
    CHECK(file.view().instance_count == 0);
    for (const Ray& r : test::random_rays(500, 9)) {
        const Hit h = closest_hit(file.view(), r), flat = closest_hit_flat(file.view(), r);
        CHECK(h.triangle == flat.triangle);
        CHECK(h.instance == kNoInstance);
        if (flat.found()) CHECK(h.t == flat.t);
    }
}

TEST_CASE("a scene of one object placed as it is walks the object's own tree", "[instances]") {
    Fixture f;
    scene_of_instances(f.dir.path(), {"a.kdg", "b.kdg"}, {{identity_affine(), 1}}).write(f.dir / "as_is.kdg");
    scene_of_instances(f.dir.path(), {"b.kdg"}, {{placement(0, 1, 0, 0, 1, 1, 1, 0, 0, 1e-3f), 0}}).write(f.dir / "moved.kdg");
    const GeometryFile as_is = GeometryFile::open(f.dir / "as_is.kdg"), moved = GeometryFile::open(f.dir / "moved.kdg");
    const GeometryFile object = GeometryFile::open(f.dir / "b.kdg");
    CHECK(as_is.has_instances());
    CHECK(as_is.view().instance_count == 0);
    REQUIRE(as_is.view().triangle_count == object.view().triangle_count);  // the object's own tree
    CHECK(as_is.view().node_count == object.view().node_count);
    CHECK(as_is.view().light_count == object.view().light_count);
    CHECK(as_is.view().info.default_k == 16);                   // the scene's defaults, not the object's
    CHECK(moved.view().instance_count == 1);                    // moved at all: an instance
    for (const Ray& r : test::random_rays(500, 9)) {
        const Hit h = closest_hit(as_is.view(), r), o = closest_hit(object.view(), r);
        CHECK(h.triangle == o.triangle);
        CHECK(h.instance == kNoInstance);
        if (o.found()) CHECK(h.t == o.t);
    }
}

TEST_CASE("kdpm-inspect lists a scene's objects and says which changed", "[instances][tools]") {
    Fixture f;
    const std::string scene = (f.dir / "scene.kdg").string();
    auto text = test::run_tool("kdpm-inspect " + scene);
    CHECK(text.exit_code == 0);
    CHECK_THAT(text.output, Catch::Contains("a.kdg: 300 triangles") && Catch::Contains("b.kdg: 200 triangles") &&
                                Catch::Contains("current"));

    build_geometry_file(object_scene(300, 99, false), KdBuildParams{}).writer.write(f.dir / "a.kdg");
    text = test::run_tool("kdpm-inspect --json " + scene);
    CHECK(text.exit_code == 0);
    CHECK_THAT(text.output, Catch::Contains("\"path\": \"a.kdg\"") && Catch::Contains("changed since the scene was built"));
}

TEST_CASE("kdpm-validate checks a scene's objects: a changed one fails in one line", "[instances][tools]") {
    Fixture f;
    const std::string scene = (f.dir / "scene.kdg").string();
    CHECK(test::run_tool("kdpm-validate " + scene).exit_code == 0);
    build_geometry_file(object_scene(300, 99, false), KdBuildParams{}).writer.write(f.dir / "a.kdg");
    const auto run = test::run_tool("kdpm-validate " + scene);
    CHECK(run.exit_code != 0);
    CHECK_THAT(run.output, Catch::Contains("has changed since the scene was built"));
}

TEST_CASE("kdpm-build-geometry makes a scene of instances from a card, grids included", "[instances][tools]") {
    Fixture f;
    {
        std::ofstream card(f.dir / "grid.json");
        card << R"({ "instances": [
            { "object": "a.kdg", "rotate": {"axis": [0, 1, 0], "degrees": 90}, "scale": 2 },
            { "object": "b.kdg", "translate": [5, 0, 0], "repeat": {"count": [3, 1, 4], "step": [1.5, 0, 2]} } ] })";
    }
    std::filesystem::create_directories(f.dir / "scenes");
    const std::string out = (f.dir / "scenes" / "grid.kdg").string();
    const auto run = test::run_tool("kdpm-build-geometry " + (f.dir / "grid.json").string() + " -o " + out);
    REQUIRE(run.exit_code == 0);
    CHECK_THAT(run.output, Catch::Contains("13 instances of 2 objects"));
    const GeometryFile scene = GeometryFile::open(out);  // object paths stored relative to scenes/
    const GeometryView& g = scene.view();
    REQUIRE(g.instance_count == 13);
    // The first: rotated a quarter turn about y and doubled: x -> -z.
    const Affine& m = g.instances[0].world_from_object;
    CHECK(m.m[0][0] == Approx(0.0f).margin(1e-6));
    CHECK(m.m[2][0] == Approx(-2.0f));
    // The grid's last copy: moved by step * (2, 0, 3).
    CHECK(g.instances[12].world_from_object.m[0][3] == Approx(8.0f));
    CHECK(g.instances[12].world_from_object.m[2][3] == Approx(6.0f));
    CHECK(g.light_count == 12);
    std::uint32_t found = 0, differ = 0;
    for (const Ray& r : world_rays(5000, 8)) {
        const Hit h = closest_hit(g, r), b = closest_hit_brute_force(g, r);
        found += b.found();
        differ += h.found() != b.found() || (b.found() && h.t != b.t && (h.instance != b.instance || h.triangle != b.triangle));
    }
    CHECK(found > 200);
    CHECK(differ <= 1);

    for (const char* bad : {R"({"instances": [{"object": "a.kdg", "scale": 0}]})",
                            R"({"mesh": "x.obj", "instances": [{"object": "a.kdg"}]})",
                            R"({"instances": [{"object": "missing.kdg"}]})",
                            R"({"instances": [{"object": "a.kdg", "repeat": {"count": [0, 1, 1], "step": [1, 0, 0]}}]})"}) {
        std::ofstream(f.dir / "bad.json") << bad;
        const auto refused = test::run_tool("kdpm-build-geometry " + (f.dir / "bad.json").string() + " -o " +
                                            (f.dir / "bad.kdg").string());
        CHECK(refused.exit_code != 0);
        CHECK(std::count(refused.output.begin(), refused.output.end(), '\n') == 1);
        CHECK_FALSE(std::filesystem::exists(f.dir / "bad.kdg"));
    }
}
