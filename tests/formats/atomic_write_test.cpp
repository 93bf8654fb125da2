#include <catch2/catch.hpp>

#include <fstream>
#include <stdexcept>

#include "formats/atomic_file.h"
#include "formats/container_reader.h"
#include "tests/support/file_contents.h"
#include "tests/formats/sample_container.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;
namespace fs = std::filesystem;

namespace {

std::size_t entries(const fs::path& dir) {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

}  // namespace

TEST_CASE("a write that fails midway leaves the old file and no temporary", "[formats]") {
    test::TempDir dir;
    auto dest = dir / "tree.kdt";
    { std::ofstream(dest) << "old contents"; }
    CHECK_THROWS_AS(write_file_atomically(dest,
                                          [](const ByteSink& sink) {
                                              sink("partial", 7);
                                              throw std::runtime_error("interrupted");
                                          }),
                    std::runtime_error);
    CHECK(test::file_contents(dest) == "old contents");
    CHECK(entries(dir.path()) == 1);
}

TEST_CASE("a write whose rename fails leaves the destination and no temporary", "[formats]") {
    test::TempDir dir;
    auto dest = dir / "occupied";
    fs::create_directory(dest);
    { std::ofstream(dest / "keep") << "x"; }
    CHECK_THROWS_AS(test::sample_writer().write(dest), FormatError);
    CHECK(fs::is_directory(dest));
    CHECK(entries(dir.path()) == 1);
}

TEST_CASE("a write into a missing folder fails cleanly", "[formats]") {
    test::TempDir dir;
    CHECK_THROWS_WITH(test::sample_writer().write(dir / "no" / "such" / "x.kdt"), Catch::Contains("cannot write"));
}

TEST_CASE("a successful write replaces the destination whole", "[formats]") {
    test::TempDir dir;
    auto dest = dir / "tree.kdt";
    { std::ofstream(dest) << "old contents"; }
    test::sample_writer().write(dest);
    CHECK(entries(dir.path()) == 1);
    CHECK_NOTHROW(ContainerReader::open(dest).verify());
}
