// Scene import (Assimp) and scene cards: triangles in source order, materials, lights, cameras.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>

#include "builders/geometry/import/scene_import.h"
#include "builders/geometry/scene_card.h"
#include "formats/format_error.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

namespace {

void write_text(const std::filesystem::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary);
    out << text;
}

const MaterialRecord& material_of(const Scene& s, std::size_t tri) { return s.materials.at(s.triangles.at(tri).material); }

}  // namespace

TEST_CASE("the shipped Cornell box card imports with its light and camera", "[geometry][import]") {
    const Scene s = load_scene_input(test::source_path("scenes/cornell-box/cornell-box.json"));
    CHECK(s.triangles.size() == 32);
    for (std::uint32_t i = 0; i < s.triangles.size(); ++i) CHECK(s.triangles[i].source_index == i);
    REQUIRE(s.lights.size() == 2);
    for (const AreaLightRecord& l : s.lights) {
        CHECK(l.shape == static_cast<std::uint32_t>(LightShape::triangle));
        CHECK(l.radiance[0] == 17.0f);
        CHECK(l.radiance[1] == 12.0f);
        CHECK(l.radiance[2] == 4.0f);
        CHECK(l.area == Approx(0.1f));
        // Faces down into the room.
        const float ny = l.e1[2] * l.e2[0] - l.e1[0] * l.e2[2];
        CHECK(ny < 0.0f);
    }
    CHECK(s.has_camera);
    CHECK(s.camera.eye[2] == 3.9f);
    CHECK(s.camera.vfov_degrees == 40.0f);
    CHECK(s.camera.width == 512);
    CHECK(s.up_axis == 1);
    CHECK(s.photons == 262144);
    // Red left wall, green right wall.
    bool red = false, green = false;
    for (const MaterialRecord& m : s.materials) {
        red = red || (m.diffuse[0] > 0.6f && m.diffuse[1] < 0.1f);
        green = green || (m.diffuse[1] > 0.4f && m.diffuse[0] < 0.2f);
    }
    CHECK(red);
    CHECK(green);
}

TEST_CASE("OBJ quirks: CRLF tabs negative indices and mirror glass emissive materials", "[geometry][import]") {
    test::TempDir dir;
    write_text(dir / "q.mtl",
               "newmtl matte\r\nKd 0.5 0.25 0.125\r\nillum 1\r\n"
               "newmtl chrome\r\nKd 0 0 0\r\nKs 0.9 0.9 0.9\r\nillum 3\r\n"
               "newmtl glass\r\nKs 0.1 0.1 0.1\r\nTf 0.9 0.8 0.7\r\nNi 1.45\r\nillum 7\r\n"
               "newmtl lamp\r\nKd 1 1 1\r\nKe 2 3 4\r\nillum 1\r\n"
               "newmtl textured\r\nKd 0.3 0.3 0.3\r\nmap_Kd missing.png\r\n");
    write_text(dir / "q.obj",
               "mtllib q.mtl\r\n"
               "v\t0 0 0\r\nv 1\t0 0\r\nv 1 1 0\r\nv 0 1 0\r\n"
               "usemtl matte\r\nf -4 -3 -2 -1\r\n"
               "usemtl chrome\r\nf 1 2 3\r\n"
               "usemtl glass\r\nf 1 3 4\r\n"
               "usemtl lamp\r\nf 1 2 4\r\n"
               "usemtl textured\r\nf 2 3 4\r\n"
               "f 1 1 1\r\n");
    const Scene s = import_mesh(dir / "q.obj");
    REQUIRE(s.triangles.size() == 7);  // the quad gives two, the point triangle is kept as a record
    const MaterialRecord& matte = material_of(s, 0);
    CHECK(matte.kind == static_cast<std::uint32_t>(MaterialKind::diffuse));
    CHECK(matte.diffuse[1] == 0.25f);
    const MaterialRecord& chrome = material_of(s, 2);
    CHECK(chrome.kind == static_cast<std::uint32_t>(MaterialKind::mirror));
    CHECK(chrome.specular[0] == Approx(0.9f));
    const MaterialRecord& glass = material_of(s, 3);
    CHECK(glass.kind == static_cast<std::uint32_t>(MaterialKind::glass));
    CHECK(glass.ior == Approx(1.45f));
    CHECK(glass.transmission[2] == Approx(0.7f));
    const MaterialRecord& lamp = material_of(s, 4);
    CHECK(lamp.emission[2] == 4.0f);
    CHECK(material_of(s, 5).diffuse[0] == Approx(0.3f));  // missing texture: Kd
    REQUIRE(s.lights.size() == 1);
    CHECK(s.lights[0].triangle == 4);
    CHECK(s.lights[0].area == Approx(0.5f));
    // Source order: the quad (fanned), then one triangle per usemtl.
    CHECK(s.triangles[2].v0[0] == 0.0f);
    CHECK(s.triangles[2].e1[0] == 1.0f);
    CHECK(s.triangles[2].e2[1] == 1.0f);
}

TEST_CASE("the shared original Cornell box imports despite its quirks", "[geometry][import]") {
    const std::string dir = test::shared_scenes_dir();
    if (dir.empty()) {
        WARN("../shared/scenes not found (set KDPM_SCENES): skipped");
        return;
    }
    const Scene s = import_mesh(std::filesystem::path(dir) / "cornell-box" / "CornellBox-Original.obj");
    CHECK(s.triangles.size() == 36);
    REQUIRE(s.lights.size() == 2);
    CHECK(s.lights[0].radiance[0] == 17.0f);
}

TEST_CASE("a bare mesh gets a camera that looks at it", "[geometry][import]") {
    const Scene s = load_scene_input(test::source_path("scenes/cornell-box/cornell-box.obj"));
    CHECK(s.has_camera);
    CHECK(s.camera.lookat[1] == Approx(1.0f));
    CHECK(s.camera.eye[2] > 2.0f);
    CHECK(s.camera.width > 0);
}

TEST_CASE("scene cards with mistakes are refused with a reason", "[geometry][import]") {
    test::TempDir dir;
    write_text(dir / "a.json", "{ \"mesh\": \"missing.obj\" }");
    CHECK_THROWS_AS(load_scene_input(dir / "a.json"), FormatError);
    write_text(dir / "b.json", "{ \"mesh\": 3 }");
    CHECK_THROWS_WITH(load_scene_input(dir / "b.json"), Catch::Contains("mesh"));
    write_text(dir / "c.json", "{ \"mesh\": \"x.obj\", \"camra\": {} }");
    CHECK_THROWS_WITH(load_scene_input(dir / "c.json"), Catch::Contains("camra"));
    write_text(dir / "d.json", "{ \"mesh\": ");
    CHECK_THROWS_WITH(load_scene_input(dir / "d.json"), Catch::Contains("JSON"));
    CHECK_THROWS_AS(load_scene_input(dir / "none.json"), FormatError);
    write_text(dir / "e.json", "{ \"mesh\": \"e.obj\", \"camera\": { \"eye\": [0,0], \"lookat\": [0,0,0], \"up\": [0,1,0], \"vfov\": 40 } }");
    write_text(dir / "e.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    CHECK_THROWS_WITH(load_scene_input(dir / "e.json"), Catch::Contains("eye"));
}

TEST_CASE("a card adds parallelogram lights and defaults", "[geometry][import]") {
    test::TempDir dir;
    write_text(dir / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 3 2\n");
    write_text(dir / "m.json",
               "{ \"mesh\": \"m.obj\", \"up\": \"z\", \"photons\": 1000, \"bounces\": 2, \"k\": 8,"
               "  \"lights\": [ { \"p0\": [0, 2, 0], \"e1\": [0, 0, 1], \"e2\": [1, 0, 0], \"radiance\": [1, 2, 3] } ] }");
    const Scene s = load_scene_input(dir / "m.json");
    CHECK(s.up_axis == 2);
    CHECK(s.photons == 1000);
    CHECK(s.bounces == 2);
    CHECK(s.k == 8);
    REQUIRE(s.lights.size() == 1);
    CHECK(s.lights[0].shape == static_cast<std::uint32_t>(LightShape::parallelogram));
    CHECK(s.lights[0].triangle == 0xffffffffu);
    CHECK(s.lights[0].area == Approx(1.0f));
    CHECK(s.lights[0].power == Approx(3.14159265f * 2.0f));
    CHECK(s.camera.up[2] == 1.0f);
}

TEST_CASE("glTF import applies node transforms and reads base colour and emission", "[geometry][import]") {
    test::TempDir dir;
    write_text(dir / "tri.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"scene\": 0, \"scenes\": [{\"nodes\": [0]}], \"nodes\": [{\"mesh\": 0, \"translation\": [0, 0, 2]}], \"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 0}, \"indices\": 1, \"material\": 0}]}], \"materials\": [{\"pbrMetallicRoughness\": {\"baseColorFactor\": [0.2, 0.4, 0.6, 1]}, \"emissiveFactor\": [1, 0.5, 0.25]}], \"buffers\": [{\"byteLength\": 44, \"uri\": \"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA=\"}], \"bufferViews\": [{\"buffer\": 0, \"byteOffset\": 0, \"byteLength\": 36}, {\"buffer\": 0, \"byteOffset\": 36, \"byteLength\": 6}], \"accessors\": [{\"bufferView\": 0, \"componentType\": 5126, \"count\": 3, \"type\": \"VEC3\", \"min\": [0, 0, 0], \"max\": [1, 1, 0]}, {\"bufferView\": 1, \"componentType\": 5123, \"count\": 3, \"type\": \"SCALAR\"}]}");
    const Scene s = import_mesh(dir / "tri.gltf");
    REQUIRE(s.triangles.size() == 1);
    CHECK(s.triangles[0].v0[2] == 2.0f);  // node translation (0, 0, 2)
    CHECK(s.triangles[0].e1[0] == 1.0f);
    const MaterialRecord& m = material_of(s, 0);
    CHECK(m.diffuse[1] == Approx(0.4f));
    CHECK(m.emission[1] == Approx(0.5f));
    REQUIRE(s.lights.size() == 1);
    CHECK(s.lights[0].radiance[2] == Approx(0.25f));
}
