// kdpm-bench-quality on the Cornell box at a tiny size: its error-against-time table is sane
// (the path tracer's relMSE against the reference falls as its samples double), and the
// reference is cached: reused untouched by a second run, rendered anew when its key changes.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;
namespace fs = std::filesystem;

namespace {

// relMSE of every `path` rung of the error-against-time table, in order (mode, N, "spp", time,
// relMSE, ...), up to the equal-time table.
std::vector<double> path_relmse(const std::string& output) {
    std::vector<double> out;
    std::istringstream lines(output);
    std::string line;
    while (std::getline(lines, line) && line.rfind("equal time", 0) != 0) {
        std::istringstream words(line);
        std::string mode, n, unit, time;
        double relmse = 0;
        if (words >> mode >> n >> unit >> time >> relmse && mode == "path" && unit == "spp") out.push_back(relmse);
    }
    return out;
}

std::vector<fs::path> references(const fs::path& dir) {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".pfm") out.push_back(e.path());
    return out;
}

struct FileStamp {
    ino_t inode;
    timespec mtime;
};

FileStamp stamp(const fs::path& p) {
    struct stat st {};
    REQUIRE(::stat(p.c_str(), &st) == 0);
    return {st.st_ino, st.st_mtim};
}

}  // namespace

TEST_CASE("kdpm-bench-quality measures error against time and caches its reference", "[tools][bench]") {
    test::TempDir dir;
    // A scenes/ folder with the Cornell box and a card whose mesh is absent (as the shared scenes
    // are on a machine without them).
    fs::create_directories(dir / "repo" / "scenes" / "cornell-box");
    fs::copy(test::source_path("scenes/cornell-box"), dir / "repo" / "scenes" / "cornell-box");
    fs::create_directories(dir / "repo" / "scenes" / "absent");
    std::ofstream(dir / "repo" / "scenes" / "absent" / "absent.json") << R"({"mesh": "nowhere.obj"})";
    const std::string work = (dir / "work").string();
    const std::string base = "kdpm-bench-quality --repo " + (dir / "repo").string() + " --work " + work +
                             " --size 32 --photons 20000 --max-rungs 5 --seconds 1000 --sppm-seconds 0 --quiet";

    const auto first = test::run_tool(base + " --scenes cornell-box,absent --reference-spp 256");
    INFO(first.output);
    REQUIRE(first.exit_code == 0);
    CHECK_THAT(first.output, Catch::Contains("skipping absent") && Catch::Contains("rendered in"));
    const std::vector<double> relmse = path_relmse(first.output);
    REQUIRE(relmse.size() == 5);  // 1, 2, 4, 8, 16 spp
    for (std::size_t i = 1; i < relmse.size(); ++i) CHECK(relmse[i] < relmse[i - 1]);
    CHECK(relmse.back() < 0.5 * relmse.front());
    for (const char* mode : {"photons", "direct+photons", "final-gather + cache", "final-gather, no cache", "sppm"})
        CHECK_THAT(first.output, Catch::Contains(std::string("\n") + mode + " "));
    CHECK_THAT(first.output, Catch::Contains("equal time (<= 1000 s)") && Catch::Contains("sppm curve (relMSE): 1 pass"));
    CHECK_THAT(first.output, Catch::Contains("relMSE at equal time") && Catch::Contains("where the error is"));
    // Each mode's picture: test | reference | error, three images wide.
    for (const char* picture : {"cornell-box-path.png", "cornell-box-final-gather-cache.png", "cornell-box-sppm.png"}) {
        INFO(picture);
        const fs::path file = dir / "work" / "pictures" / picture;
        REQUIRE(fs::exists(file));
        // The PNG's IHDR: width and height, big-endian, at bytes 16 and 20.
        std::ifstream png(file, std::ios::binary);
        unsigned char header[24] = {};
        png.read(reinterpret_cast<char*>(header), sizeof header);
        auto be32 = [&](int at) {
            return (std::uint32_t(header[at]) << 24) | (std::uint32_t(header[at + 1]) << 16) |
                   (std::uint32_t(header[at + 2]) << 8) | std::uint32_t(header[at + 3]);
        };
        CHECK(be32(16) == 96u);
        CHECK(be32(20) == 32u);
    }
    const std::vector<fs::path> cached = references(dir / "work");
    REQUIRE(cached.size() == 1);
    const FileStamp before = stamp(cached.front());

    // The same key: the reference is read back, not rendered or rewritten, and measures the same.
    const auto second = test::run_tool(base + " --scenes cornell-box --reference-spp 256");
    INFO(second.output);
    REQUIRE(second.exit_code == 0);
    CHECK_THAT(second.output, Catch::Contains("reused from " + cached.front().string()));
    const FileStamp after = stamp(cached.front());
    CHECK(after.inode == before.inode);
    CHECK((after.mtime.tv_sec == before.mtime.tv_sec && after.mtime.tv_nsec == before.mtime.tv_nsec));
    CHECK(path_relmse(second.output) == relmse);

    // Another key (fewer reference samples): another reference, rendered; the first stays.
    // Its photon map with the report's 4 bounces (the first had the card's, unlimited in practice).
    CHECK_THAT(first.output, Catch::Contains("photons of up to 63 bounces"));
    const auto third = test::run_tool(base + " --scenes cornell-box --reference-spp 128 --photon-bounces 4");
    INFO(third.output);
    REQUIRE(third.exit_code == 0);
    CHECK_THAT(third.output, Catch::Contains("rendered in") && Catch::Contains("photons of up to 4 bounces"));
    CHECK(references(dir / "work").size() == 2);

    // A damaged cache file is refused in one line, and left as it is.
    fs::resize_file(cached.front(), 100);
    const auto damaged = test::run_tool(base + " --scenes cornell-box --reference-spp 256");
    INFO(damaged.output);
    CHECK(damaged.exit_code == 1);
    CHECK_THAT(damaged.output, Catch::Contains("remove it to render the reference anew"));
    CHECK(fs::file_size(cached.front()) == 100);
}

TEST_CASE("kdpm-bench-quality refuses bad options in one line", "[tools][bench]") {
    test::TempDir dir;
    // Cheap settings first, so that an option wrongly accepted costs no long run; the bad one last
    // (an option given twice takes its last value).
    const std::string base = "kdpm-bench-quality --scenes cornell-box --repo " + test::source_path("") + " --work " +
                             (dir / "work").string() + " --size 8 --reference-spp 1 --max-rungs 1 --photons 100 --quiet ";
    for (const char* bad : {"--size 0", "--seconds -1", "--threads 0", "--reference-spp x", "--reference-backend gpu",
                            "--photon-bounces 256", "--budgets 0", "--budgets 1,x", "--budgets ,", "--no-such-option"}) {
        const auto r = test::run_tool(base + bad);
        INFO(bad << ": " << r.output);
        CHECK(r.exit_code == 2);
        CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
    }
}
