// Hostile meshes: an index past the vertex array, files nested deep enough to overflow Assimp's
// recursion, and mesh paths that are not regular files all end in a one-line error, not a crash.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <functional>

#include <string>

#include "builders/geometry/import/isolated_import.h"
#include "builders/geometry/import/mesh_nesting.h"
#include "formats/format_error.h"
#include "tests/hostile/hostile_files.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

namespace {

std::string gltf_chain(int depth) {
    std::string nodes;
    for (int i = 0; i < depth; ++i) {
        if (i) nodes += ",";
        nodes += i + 1 < depth ? "{\"children\":[" + std::to_string(i + 1) + "]}" : "{}";
    }
    return "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[" + nodes + "]}";
}

test::CommandResult build(const std::filesystem::path& input, const test::TempDir& dir) {
    return test::run_tool("kdpm-build-geometry '" + input.string() + "' -o '" + (dir / "out.kdg").string() + "' --quiet");
}

}  // namespace

TEST_CASE("a PLY face index past the vertex array is an error, not a crash", "[hostile][mesh]") {
    test::TempDir dir;
    test::write_file(dir / "bad.ply", test::ply_triangle(100000000));
    const auto r = build(dir / "bad.ply", dir);
    CHECK(test::is_clean_error(r));
    CHECK_THAT(r.output, Catch::Contains("out of range") || Catch::Contains("names vertex 100000000 of 3"));
    test::write_file(dir / "good.ply", test::ply_triangle(2));
    CHECK(build(dir / "good.ply", dir).exit_code == 0);
}

TEST_CASE("deeply nested glTF and COLLADA files are refused before Assimp recurses", "[hostile][mesh]") {
    test::TempDir dir;
    test::write_file(dir / "chain.gltf", gltf_chain(20000));
    test::write_file(dir / "arrays.gltf",
                     "{\"asset\":{\"version\":\"2.0\"},\"x\":" + std::string(1000000, '[') + std::string(1000000, ']') + "}");
    std::string dae = "<?xml version=\"1.0\"?><COLLADA version=\"1.4.1\"><library_visual_scenes><visual_scene id=\"s\">";
    for (int i = 0; i < 200000; ++i) dae += "<node>";
    for (int i = 0; i < 200000; ++i) dae += "</node>";
    dae += "</visual_scene></library_visual_scenes></COLLADA>";
    test::write_file(dir / "nodes.dae", dae);
    for (const char* name : {"chain.gltf", "arrays.gltf", "nodes.dae"}) {
        INFO(name);
        const auto r = build(dir / name, dir);
        CHECK(test::is_clean_error(r));
        CHECK_THAT(r.output, Catch::Contains("levels deep"));
    }
}

TEST_CASE("nesting depths are measured as the parsers see them", "[hostile][mesh]") {
    CHECK(json_nesting_depth(R"({"a": [1, {"b": "[[[[{{"}], "c": "\"["})") == 3);
    CHECK(xml_nesting_depth("<?xml?><!-- <a><a> --><a x='>' y=\"/>\"><b/><c><![CDATA[<d>]]></c></a>") == 2);
    CHECK(gltf_node_depth(gltf_chain(50)) == 50);
    CHECK(gltf_node_depth(R"({"nodes": [{"children": [1]}, {"children": [0]}]})") == static_cast<std::size_t>(-1));
    CHECK(gltf_node_depth(R"({"nodes": [{"children": [1, 2]}, {}, {"children": [1]}]})") == 3);
}

TEST_CASE("a mesh path that is a device, a FIFO, a folder or empty gets an accurate message", "[hostile][mesh]") {
    test::TempDir dir;
    REQUIRE(::mkfifo((dir / "pipe.obj").c_str(), 0600) == 0);
    test::write_file(dir / "empty.obj", "");
    struct Case {
        std::string mesh, expected;
    };
    const Case cases[] = {{"/dev/zero", "not a regular file"},
                          {(dir / "pipe.obj").string(), "not a regular file"},
                          {dir.path().string(), "is a folder"},
                          {(dir / "empty.obj").string(), "is empty"},
                          {(dir / "missing.obj").string(), "no such mesh file"}};
    for (const Case& c : cases) {
        INFO(c.mesh);
        const auto r = build(c.mesh, dir);
        CHECK(test::is_clean_error(r));
        CHECK_THAT(r.output, Catch::Contains(c.expected));
    }
    test::write_file(dir / "card.json", test::card_json(""));
    const auto r = build(dir / "card.json", dir);
    CHECK(test::is_clean_error(r));
    CHECK_THAT(r.output, Catch::Contains("mesh path is empty"));
}

TEST_CASE("a mesh on which Assimp aborts is an error of the tool, not its end", "[hostile][mesh]") {
    test::TempDir dir;
    // Found by fuzz_mesh_import: Assimp's triangulation asserts (and aborts) on this OFF file.
    const std::string off("OFF\n3 1 0\n\n0  00 00  \0v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n1 2\n", 74);
    test::write_file(dir / "abort.off", off);
    const auto r = build(dir / "abort.off", dir);
    CHECK(test::is_clean_error(r));
    CHECK_THAT(r.output, Catch::Contains("cannot read mesh"));
}

TEST_CASE("the isolated importer turns a child's crash, hang or error into one line", "[hostile][mesh]") {
    auto message = [](const std::function<Scene()>& import) {
        try {
            (void)run_isolated(import, "m.obj", 1);
        } catch (const FormatError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    CHECK(message([]() -> Scene { std::raise(SIGSEGV); return {}; }) == "m.obj: cannot read mesh: the importer crashed (Segmentation fault)");
    CHECK(message([]() -> Scene { for (;;) ::pause(); }) == "m.obj: cannot read mesh: the importer took longer than 1 s");
    CHECK(message([]() -> Scene { throw FormatError("m.obj: no faces"); }) == "m.obj: no faces");
    Scene one;
    one.source_name = "m.obj";
    one.triangles.resize(3);
    one.triangles[1].v0[0] = 7.0f;
    const Scene back = run_isolated([&] { return one; }, "m.obj", 1);
    REQUIRE(back.triangles.size() == 3);
    CHECK(back.triangles[1].v0[0] == 7.0f);
    CHECK(back.source_name == "m.obj");
}

TEST_CASE("a mesh in memory on which Assimp aborts is an error, the caller lives on", "[hostile][mesh]") {
    const std::string off("OFF\n3 1 0\n\n0  00 00  \0v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n1 2\n", 74);
    CHECK_THROWS_WITH(import_mesh_from_memory_isolated(off, "off", "abort.off", 10), Catch::Contains("abort.off: cannot read mesh"));
    CHECK_THROWS_WITH(import_mesh_from_memory_isolated("", "off", "empty.off", 10), "empty.off: the mesh file is empty");
}
