// Faults on the input side: an empty photon map round-trips, a mapped file truncated while in
// use is a one-line error (not SIGBUS), a FIFO as input does not hang, shooting verifies
// checksums, and an output that is an input is refused before any work.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include "formats/container_reader.h"
#include "formats/container_writer.h"
#include "formats/geometry_layout.h"
#include "formats/photon_layout.h"
#include "formats/section_ids.h"
#include "tests/hostile/fork_child.h"
#include "tests/hostile/hostile_files.h"
#include "tests/hostile/resealed_file.h"
#include "tests/support/file_contents.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;
namespace fs = std::filesystem;

namespace {

// Quoted for the shell; built by appends: GCC 12 warns falsely on "'" + string.
std::string q(const fs::path& p) {
    std::string s(1, '\'');
    s.append(p.string()).push_back('\'');
    return s;
}

// A triangle on y = 0 and a card light above it that faces up, away from everything.
fs::path build_scene(const test::TempDir& dir, bool light_faces_down) {
    test::write_file(dir / "tri.obj", "v -1 0 -1\nv 1 0 -1\nv 0 0 1\nf 1 3 2\n");
    const std::string e1 = light_faces_down ? "[1,0,0]" : "[0,0,1]", e2 = light_faces_down ? "[0,0,1]" : "[1,0,0]";
    test::write_file(dir / "card.json",
                     test::card_json("tri.obj", "\"lights\": [{\"p0\": [-0.1,1,-0.1], \"e1\": " + e1 + ", \"e2\": " + e2 +
                                                    ", \"radiance\": [5,5,5]}], \"camera\": {\"eye\": [0,2,3], "
                                                    "\"lookat\": [0,0,0], \"up\": [0,1,0], \"vfov\": 40, \"width\": 16, "
                                                    "\"height\": 16}"));
    const fs::path kdg = dir / "scene.kdg";
    REQUIRE(test::run_tool("kdpm-build-geometry " + q(dir / "card.json") + " -o " + q(kdg) + " --quiet").exit_code == 0);
    return kdg;
}

}  // namespace

TEST_CASE("an empty photon map is written and read back", "[hostile][inputs]") {
    test::TempDir dir;
    const fs::path kdg = build_scene(dir, /*light_faces_down=*/false);
    const auto shot = test::run_tool("kdpm-shoot-photons " + q(kdg) + " -n 1000 -o " + q(dir / "s.kdph") + " --quiet");
    REQUIRE(shot.exit_code == 0);
    const auto built = test::run_tool("kdpm-build-photons " + q(dir / "s.kdph") + " -o " + q(dir / "s.kdp") + " --quiet");
    INFO(built.output);
    REQUIRE(built.exit_code == 0);
    CHECK(test::run_tool("kdpm-validate " + q(dir / "s.kdph")).exit_code == 0);
    CHECK(test::run_tool("kdpm-validate " + q(dir / "s.kdp")).exit_code == 0);
}

TEST_CASE("empty sections at a shared offset are not an overlap", "[hostile][inputs]") {
    ContainerWriter w(FileKind::photon_tree);
    const std::vector<std::uint32_t> one{7};
    for (std::uint32_t id = 0x400; id < 0x411; ++id)  // 17 sections: std::sort is no longer an insertion sort
        w.add_raw(id, ElementType::u32, 4, id % 2 ? 1 : 0, one.data());
    const auto bytes = w.bytes();
    CHECK_NOTHROW(ContainerReader::from_bytes(bytes, "empty-sections.kdp"));
}

TEST_CASE("a mapped input truncated while in use is a one-line error, not SIGBUS", "[hostile][inputs]") {
    test::TempDir dir;
    ContainerWriter w(FileKind::photon_tree);
    const std::vector<std::uint32_t> values(1 << 16, 1);
    w.add(0x400, ElementType::u32, values);
    w.write(dir / "big.kdp");
    const fs::path log = dir / "stderr.txt";
    const auto end = test::run_in_child([&] {
        const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        ::dup2(fd, 2);
        const ContainerReader r = ContainerReader::open(dir / "big.kdp");
        REQUIRE(::truncate((dir / "big.kdp").c_str(), 0) == 0);
        std::uint64_t sum = 0;
        for (std::uint8_t b : r.file_bytes()) sum += b;  // reads the lost pages
        return sum == 0 ? 3 : 2;
    });
    CHECK(end.exited);
    CHECK(end.exit_code == 1);
    CHECK_THAT(test::file_contents(log), Catch::Contains("truncated or changed while in use"));
}

TEST_CASE("a FIFO as input is refused at once instead of blocking", "[hostile][inputs]") {
    test::TempDir dir;
    const fs::path fifos[] = {dir / "in.kdg", dir / "card.json"};
    for (const fs::path& f : fifos) REQUIRE(::mkfifo(f.c_str(), 0600) == 0);
    // A tool that blocks in open() is released after a grace period by opening the write end,
    // so a regression fails this test instead of hanging it.
    std::atomic<bool> done{false};
    std::thread releaser([&] {
        std::this_thread::sleep_for(std::chrono::seconds(3));
        while (!done) {
            for (const fs::path& f : fifos)
                if (const int fd = ::open(f.c_str(), O_WRONLY | O_NONBLOCK); fd >= 0) ::close(fd);
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
    });
    for (const std::string& cmd : {"kdpm-validate " + q(dir / "in.kdg"), "kdpm-inspect " + q(dir / "in.kdg"),
                                   "kdpm-render " + q(dir / "in.kdg") + " --mode direct --quiet -o " + q(dir / "o.png"),
                                   "kdpm-shoot-photons " + q(dir / "in.kdg") + " -o " + q(dir / "o.kdph"),
                                   "kdpm-build-geometry " + q(dir / "card.json") + " -o " + q(dir / "o.kdg")}) {
        INFO(cmd);
        const auto start = std::chrono::steady_clock::now();
        const auto r = test::run_tool(cmd);
        CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(3));
        CHECK(test::is_clean_error(r));
        CHECK_THAT(r.output, Catch::Contains("not a regular file"));
    }
    done = true;
    releaser.join();
}

TEST_CASE("kdpm-shoot-photons verifies the checksums of its input", "[hostile][inputs]") {
    test::TempDir dir;
    const fs::path kdg = build_scene(dir, /*light_faces_down=*/true);
    // Patch the light without fixing the section checksum.
    const ContainerReader r = ContainerReader::open(kdg);
    const SectionEntry* lights = r.find(section::geo_lights);
    REQUIRE(lights);
    std::string bytes = test::file_contents(kdg);
    bytes[lights->offset + offsetof(AreaLightRecord, radiance)] ^= 0x40;
    test::write_file(dir / "patched.kdg", bytes);
    const auto shot = test::run_tool("kdpm-shoot-photons " + q(dir / "patched.kdg") + " -n 1000 -o " + q(dir / "s.kdph"));
    CHECK(test::is_clean_error(shot));
    CHECK_THAT(shot.output, Catch::Contains("checksum"));
    CHECK_FALSE(fs::exists(dir / "s.kdph"));
}

TEST_CASE("an output that is an input is refused and the input survives", "[hostile][inputs]") {
    test::TempDir dir;
    const fs::path kdg = build_scene(dir, /*light_faces_down=*/true);
    const std::string card = test::file_contents(dir / "card.json"), scene = test::file_contents(kdg);
    for (const std::string& cmd : {"kdpm-build-geometry " + q(dir / "card.json") + " -o " + q(dir / "card.json"),
                                   "kdpm-build-geometry " + q(dir / "card.json") + " -o " + q(dir / "tri.obj"),
                                   "kdpm-shoot-photons " + q(kdg) + " -n 100 -o " + q(kdg),
                                   "kdpm-render " + q(kdg) + " --mode direct -o " + q(kdg)}) {
        INFO(cmd);
        const auto r = test::run_tool(cmd + " --quiet");
        CHECK(test::is_clean_error(r));
        CHECK_THAT(r.output, Catch::Contains("it is the input"));
    }
    CHECK(test::file_contents(dir / "card.json") == card);
    CHECK(test::file_contents(kdg) == scene);
}

TEST_CASE("every tool takes --threads 0 as all cores", "[hostile][inputs]") {
    test::TempDir dir;
    const fs::path kdg = build_scene(dir, /*light_faces_down=*/true);
    CHECK(test::run_tool("kdpm-render " + q(kdg) + " --mode direct --threads 0 -o " + q(dir / "o.png") + " --quiet")
              .exit_code == 0);
    CHECK(test::run_tool("kdpm-shoot-photons " + q(kdg) + " -n 100 --threads 0 -o " + q(dir / "o.kdph") + " --quiet")
              .exit_code == 0);
}

TEST_CASE("a photon search radius too small to find any photon is refused", "[hostile][inputs]") {
    test::TempDir dir;
    const fs::path kdg = build_scene(dir, /*light_faces_down=*/true);
    REQUIRE(test::run_tool("kdpm-shoot-photons " + q(kdg) + " -n 2000 -o " + q(dir / "s.kdph") + " --quiet").exit_code == 0);
    const auto tiny = test::run_tool("kdpm-build-photons " + q(dir / "s.kdph") + " --radius 1e-30 -o " + q(dir / "s.kdp") + " --quiet");
    CHECK(test::is_clean_error(tiny));
    CHECK_THAT(tiny.output, Catch::Contains("1e-30 is below"));
    REQUIRE(test::run_tool("kdpm-build-photons " + q(dir / "s.kdph") + " -o " + q(dir / "s.kdp") + " --quiet").exit_code == 0);
    const auto render = test::run_tool("kdpm-render " + q(kdg) + " " + q(dir / "s.kdp") + " --max-radius 1e-30 -o " +
                                       q(dir / "o.png") + " --quiet");
    CHECK(test::is_clean_error(render));
    // A file that stores such a radius (the renderer derives its search radius from it).
    test::reseal_record<PhotonTreeInfo>(dir / "s.kdp", dir / "tiny.kdp",
                                        photon_tree_section(PhotonMapKind::global, ptree_field_info),
                                        [](PhotonTreeInfo& i) { i.query_radius = 1e-30f; });
    CHECK(test::run_tool("kdpm-validate " + q(dir / "tiny.kdp")).exit_code != 0);
    CHECK(test::is_clean_error(test::run_tool("kdpm-render " + q(kdg) + " " + q(dir / "tiny.kdp") + " -o " +
                                              q(dir / "o.png") + " --quiet")));
}

TEST_CASE("kdpm-view refuses an unwritable screenshot before rendering or opening a window", "[hostile][inputs]") {
    test::TempDir dir;
    const fs::path kdg = build_scene(dir, /*light_faces_down=*/true);
    // No display: a viewer that got as far as its window would fail for another reason.
    const auto end = test::run_in_child([&] {
        ::unsetenv("DISPLAY");
        ::unsetenv("WAYLAND_DISPLAY");
        const auto r = test::run_tool("kdpm-view " + q(kdg) + " --frames 1 --screenshot " + q(dir / "no" / "shot.png") +
                                      " --quiet");
        return test::is_clean_error(r) && r.output.find("does not exist") != std::string::npos ? 0 : 1;
    });
    CHECK(end.exit_code == 0);
}
