// Diffuse textures through the geometry file: an OBJ whose MTL names a PNG (written here with
// kdpm's own encoder) imports with its texture coordinates, its texture decoded from sRGB to
// linear and mip-mapped; the .kdg round-trips them; corrupt texture sections are refused; a
// missing or unreadable texture is a one-line warning and the material keeps Kd; files written
// before textures existed (format 1.0) still load.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <functional>

#include "builders/geometry/geometry_file_builder.h"
#include "builders/geometry/import/texture_import.h"
#include "builders/geometry/import/texture_ppm.h"
#include "builders/geometry/sah/sah_kd_builder.h"
#include "builders/geometry/scene_card.h"
#include "formats/format_error.h"
#include "formats/section_ids.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/render/image/image_encoder.h"
#include "runtime/shading/surface_point.h"
#include "tests/support/file_contents.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

namespace {

void write_text(const std::filesystem::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary);
    out << text;
}

// A 4 x 2 PNG whose byte at (x, y, c) (row 0 on top) is 30 x + 70 y + 5 c + 1.
constexpr std::uint32_t kW = 4, kH = 2;
std::uint8_t png_byte(std::uint32_t x, std::uint32_t y, int c) { return static_cast<std::uint8_t>(30 * x + 70 * y + 5 * c + 1); }

void write_png(const std::filesystem::path& p) {
    std::vector<float> pixels;
    for (std::uint32_t y = 0; y < kH; ++y)
        for (std::uint32_t x = 0; x < kW; ++x)
            for (int c = 0; c < 3; ++c) pixels.push_back(png_byte(x, y, c) / 255.0f);
    std::vector<std::uint8_t> bytes;
    REQUIRE(encode_builtin_image(bytes, p, kW, kH, {"R", "G", "B"}, pixels, true).empty());
    write_text(p, std::string(bytes.begin(), bytes.end()));
}

// A unit quad in z = 0 with uv = position, material "tex" with Kd 0.25 0.5 0.75 and map_Kd `texture`.
void write_quad(const test::TempDir& dir, const std::string& texture) {
    write_text(dir / "quad.mtl", "newmtl tex\nKd 0.25 0.5 0.75\nmap_Kd " + texture + "\n");
    write_text(dir / "quad.obj",
               "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
               "usemtl tex\nf 1/1 2/2 3/3 4/4\n");
}

std::vector<std::uint8_t> file_bytes(const Scene& scene, std::uint16_t minor = 1) {
    KdBuildParams params;
    ContainerWriter w = assemble_geometry_file(scene, build_sah_kd_tree(scene.triangles, params), params);
    w.set_version(1, minor);
    return w.bytes();
}

}  // namespace

TEST_CASE("a textured OBJ imports with uvs and a linear, mip-mapped texture that the .kdg round-trips", "[texture][geometry]") {
    test::TempDir dir;
    write_png(dir / "checker.png");
    write_quad(dir, "checker.png");
    const Scene scene = load_scene_input(dir / "quad.obj");
    CHECK(scene.warnings.empty());
    REQUIRE(scene.textures.size() == 1);
    REQUIRE(scene.uvs.size() == scene.triangles.size());
    const TextureRecord& t = scene.textures[0];
    CHECK(t.width == kW);
    CHECK(t.height == kH);
    CHECK(t.levels == 3);  // 4x2, 2x1, 1x1
    REQUIRE(scene.texels.size() == 8u + 2 + 1);
    const MaterialRecord& quad = scene.materials.at(scene.triangles[0].material);
    CHECK(quad.diffuse_texture == 1);
    CHECK(quad.diffuse[1] == 0.5f);  // Kd kept for readers that ignore textures
    // Row 0 of the stored texture is the image's bottom row (v = 0).
    for (std::uint32_t y = 0; y < kH; ++y)
        for (std::uint32_t x = 0; x < kW; ++x)
            for (int c = 0; c < 3; ++c)
                CHECK(scene.texels[(kH - 1 - y) * kW + x].rgb[c] == Approx(srgb_to_linear(png_byte(x, y, c) / 255.0f)));

    const std::vector<std::uint8_t> bytes = file_bytes(scene);
    const GeometryFile file = GeometryFile::from_bytes(bytes, "textured.kdg");
    const GeometryView& g = file.view();
    REQUIRE(g.texture_count == 1);
    REQUIRE(g.uvs != nullptr);
    REQUIRE(g.texel_count == scene.texels.size());
    for (std::size_t i = 0; i < scene.texels.size(); ++i)
        for (int c = 0; c < 3; ++c) CHECK(g.texels[i].rgb[c] == scene.texels[i].rgb[c]);
    // The albedo at a hit on the centre of texel (1, 0) of the bottom row, through material_of:
    // the quad's first triangle (0,0)-(1,0)-(1,1) has uv = (u + v, v) at barycentrics (u, v).
    const float tu = 1.5f / kW, tv = 0.5f / kH;
    const Hit hit{1.0f, 0, tu - tv, tv};
    const MaterialRecord m = material_of(g, hit);
    for (int c = 0; c < 3; ++c) CHECK(m.diffuse[c] == Approx(scene.texels[1].rgb[c]).epsilon(1e-5));
}

TEST_CASE("corrupt texture sections are refused", "[texture][geometry]") {
    test::TempDir dir;
    write_png(dir / "checker.png");
    write_quad(dir, "checker.png");
    const Scene good = load_scene_input(dir / "quad.obj");
    REQUIRE(good.textures.size() == 1);
    CHECK_NOTHROW(GeometryFile::from_bytes(file_bytes(good), "good.kdg"));

    const std::pair<const char*, std::function<void(Scene&)>> cases[] = {
        {"is negative or not finite", [](Scene& s) { s.texels[3].rgb[1] = std::nanf(""); }},
        {"is negative or not finite", [](Scene& s) { s.texels.back().rgb[0] = -1.0f; }},
        {"names a texture out of range", [](Scene& s) { s.materials.back().diffuse_texture = 2; }},
        {"texture coordinate that is not finite", [](Scene& s) { s.uvs[1].uv[2][0] = INFINITY; }},
        {"one record per triangle", [](Scene& s) { s.uvs.pop_back(); }},
        {"full mip chain", [](Scene& s) { s.textures[0].levels = 2; }},
        {"side outside", [](Scene& s) { s.textures[0].width = 0; }},
        {"does not match its levels", [](Scene& s) { s.textures[0].texel_count -= 1; }},
        {"exactly the textures' texels", [](Scene& s) { s.texels.push_back(Texel{{1, 1, 1}}); }},
        {"does not start where", [](Scene& s) { s.textures[0].first_texel = 1; }},
    };
    for (const auto& [why, corrupt] : cases) {
        Scene bad = good;
        corrupt(bad);
        INFO(why);
        CHECK_THROWS_WITH(GeometryFile::from_bytes(file_bytes(bad), "bad.kdg"), Catch::Contains(why));
    }
    // The same through kdpm-validate: one line, exit 1.
    Scene bad = good;
    bad.texels[0].rgb[0] = -2.0f;
    const auto bytes = file_bytes(bad);
    write_text(dir / "bad.kdg", std::string(bytes.begin(), bytes.end()));
    const auto r = test::run_tool("kdpm-validate " + (dir / "bad.kdg").string());
    INFO(r.output);
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.output, Catch::Contains("texel 0 is negative"));
}

TEST_CASE("a missing or unreadable texture is one warning and the material keeps Kd", "[texture][geometry][tools]") {
    test::TempDir dir;
    write_text(dir / "garbage.png", "this is no image");
    for (const std::string texture : {"missing.png", "garbage.png"}) {
        write_quad(dir, texture);
        const auto kdg = dir / "quad.kdg";
        auto r = test::run_tool("kdpm-build-geometry " + (dir / "quad.obj").string() + " -o " + kdg.string());
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        const auto warning = r.output.find("kdpm-build-geometry: warning: texture ");
        REQUIRE(warning != std::string::npos);
        const std::string line = r.output.substr(warning, r.output.find('\n', warning) - warning);
        CHECK_THAT(line, Catch::Contains(texture) && Catch::Contains("using the material's diffuse colour"));
        CHECK(r.output.find("warning", warning + line.size()) == std::string::npos);  // one line only
        const GeometryFile file = GeometryFile::open(kdg);
        CHECK(file.view().texture_count == 0);
        for (const MaterialRecord& m : file.materials()) CHECK(m.diffuse_texture == 0);
        const MaterialRecord m = material_of(file.view(), Hit{1.0f, 0, 0.25f, 0.25f});
        CHECK(m.diffuse[0] == 0.25f);
        CHECK(m.diffuse[2] == 0.75f);
        auto quiet = test::run_tool("kdpm-build-geometry " + (dir / "quad.obj").string() + " -o " + kdg.string() + " --quiet");
        CHECK(quiet.exit_code == 0);
        CHECK(quiet.output.empty());
    }
}

TEST_CASE("many unusable textures are one warning line for them all", "[texture][geometry]") {
    test::TempDir dir;
    std::string mtl, obj = "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n";
    for (int i = 0; i < 5; ++i) {
        mtl += "newmtl m" + std::to_string(i) + "\nKd 0.5 0.5 0.5\nmap_Kd gone" + std::to_string(i) + ".png\n";
        obj += "usemtl m" + std::to_string(i) + "\nf 1/1 2/2 3/3\n";
    }
    write_text(dir / "quad.mtl", mtl);
    write_text(dir / "quad.obj", obj);
    const Scene scene = load_scene_input(dir / "quad.obj");
    REQUIRE(scene.warnings.size() == 1);
    CHECK_THAT(scene.warnings[0], Catch::StartsWith("5 textures cannot be used (the first: ") && Catch::Contains("gone0.png"));
    for (const MaterialRecord& m : scene.materials) CHECK(m.diffuse_texture == 0);
    CHECK(scene.textures.empty());
}

TEST_CASE("geometry files of format 1.0, without texture sections, still load", "[texture][geometry]") {
    test::TempDir dir;
    write_text(dir / "quad.mtl", "newmtl plain\nKd 0.25 0.5 0.75\n");
    write_text(dir / "quad.obj", "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl plain\nf 1 2 3\n");
    const Scene scene = load_scene_input(dir / "quad.obj");
    CHECK(scene.textures.empty());
    const std::vector<std::uint8_t> bytes = file_bytes(scene, 0);
    const GeometryFile file = GeometryFile::from_bytes(bytes, "old.kdg");
    CHECK(file.reader().header().version_minor == 0);
    CHECK(file.reader().find(section::geo_textures) == nullptr);
    CHECK(file.view().uvs == nullptr);
    CHECK(file.view().texture_count == 0);
    const MaterialRecord m = material_of(file.view(), Hit{1.0f, 0, 0.2f, 0.2f});
    CHECK(m.diffuse[1] == 0.5f);
}

TEST_CASE("kdpm's PPM reader (builds without OpenImageIO) reads the shipped checker as OpenImageIO does", "[texture][geometry]") {
    const std::filesystem::path checker = test::source_path("scenes/textured-quad/checker.ppm");
    std::string why;
    const auto ours = read_ppm_texture(checker, why);
    const auto oiio = read_texture_image(checker, why);
    REQUIRE(ours);
    REQUIRE(oiio);
    REQUIRE(ours->width == 16);
    REQUIRE(ours->height == 16);
    REQUIRE(oiio->texels.size() == ours->texels.size());
    for (std::size_t i = 0; i < ours->texels.size(); ++i)
        for (int c = 0; c < 3; ++c) CHECK(ours->texels[i].rgb[c] == Approx(oiio->texels[i].rgb[c]));
    // Bottom-left stored texel = the file's bottom-left pixel (x 0, row 15 from the top: square (0, 3), green).
    CHECK(ours->texels[0].rgb[1] == 1.0f);
    CHECK(ours->texels[0].rgb[0] == 0.0f);

    // A binary P6 with 16-bit samples, and broken files.
    test::TempDir dir;
    std::string p6 = "P6\n# two pixels\n2 1\n65535\n";
    for (const int v : {65535, 0, 0, 0, 32768, 65535}) p6 += static_cast<char>(v >> 8), p6 += static_cast<char>(v & 255);
    write_text(dir / "two.ppm", p6);
    const auto two = read_ppm_texture(dir / "two.ppm", why);
    REQUIRE(two);
    CHECK(two->texels[0].rgb[0] == 1.0f);
    CHECK(two->texels[1].rgb[1] == Approx(srgb_to_linear(32768.0f / 65535.0f)));
    CHECK(two->texels[1].rgb[2] == 1.0f);
    for (const std::string bad : {"P6\n2 1\n255\nab", "P3\n2 1\n255\n1 2 3 4 5", "P3\n2 1\n255\n1 2 3 4 5 300", "P5\n1 1\n255\na",
                                  "P3\n0 1\n255\n", "P3\n99999 1\n255\n"}) {
        write_text(dir / "bad.ppm", bad);
        INFO(bad);
        CHECK_FALSE(read_ppm_texture(dir / "bad.ppm", why));
        CHECK(why.find('\n') == std::string::npos);
    }
}

TEST_CASE("a glTF base colour texture imports with its uvs the same way up", "[texture][geometry]") {
    // A unit quad in z = 0; glTF puts uv (0, 0) at the image's top-left corner, so the quad's
    // top-left vertex (0, 1, 0) has uv (0, 0).
    test::TempDir dir;
    write_png(dir / "checker.png");
    const float positions[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const float uvs[4][2] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    const std::uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
    std::string bin(reinterpret_cast<const char*>(positions), sizeof positions);
    bin.append(reinterpret_cast<const char*>(uvs), sizeof uvs);
    bin.append(reinterpret_cast<const char*>(indices), sizeof indices);
    write_text(dir / "quad.bin", bin);
    write_text(dir / "quad.gltf", R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"indices":2,"material":0}]}],
"materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],
"textures":[{"source":0}],"images":[{"uri":"checker.png"}],
"buffers":[{"uri":"quad.bin","byteLength":92}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":32},
{"buffer":0,"byteOffset":80,"byteLength":12}],
"accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
{"bufferView":1,"componentType":5126,"count":4,"type":"VEC2"},{"bufferView":2,"componentType":5123,"count":6,"type":"SCALAR"}]})");
    const Scene scene = load_scene_input(dir / "quad.gltf");
    INFO((scene.warnings.empty() ? "" : scene.warnings[0]));
    REQUIRE(scene.textures.size() == 1);
    REQUIRE(scene.triangles.size() == 2);
    const std::vector<std::uint8_t> bytes = file_bytes(scene);
    const GeometryFile file = GeometryFile::from_bytes(bytes, "gltf.kdg");
    // Quad point (0.375, 0.75), on the second triangle (0,0,0)-(1,1,0)-(0,1,0) at barycentrics
    // (0.375, 0.375): the centre of texel (1, 0) of the image's top row.
    const MaterialRecord m = material_of(file.view(), Hit{1.0f, 1, 0.375f, 0.375f});
    for (int c = 0; c < 3; ++c)
        CHECK(m.diffuse[c] == Approx(srgb_to_linear(png_byte(1, 0, c) / 255.0f)).epsilon(1e-5));
}
