#include <catch2/catch.hpp>

#include <fstream>

#include "tests/formats/sample_container.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

TEST_CASE("kdpm-inspect prints sections and metadata as text and JSON", "[tools]") {
    test::TempDir dir;
    auto path = (dir / "sample.kdt").string();
    test::sample_writer().write(path);

    auto text = test::run_tool("kdpm-inspect " + path);
    CHECK(text.exit_code == 0);
    CHECK_THAT(text.output, Catch::Contains("test container") && Catch::Contains("metadata") &&
                                Catch::Contains("kdpm-test") && Catch::Contains("max_depth = 40"));

    auto json = test::run_tool("kdpm-inspect --json " + path);
    CHECK(json.exit_code == 0);
    CHECK_THAT(json.output, Catch::Contains("\"sections\": [") && Catch::Contains("\"sah_cost\": 12.5"));
}

TEST_CASE("kdpm-validate accepts a sound file and rejects a damaged one in one line", "[tools]") {
    test::TempDir dir;
    auto path = (dir / "sample.kdt").string();
    auto bytes = test::sample_writer().bytes();
    { std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), bytes.size()); }
    CHECK(test::run_tool("kdpm-validate " + path).exit_code == 0);

    // Flip one bit in each region: header, a section, padding, section table.
    for (std::size_t at : {std::size_t{9}, std::size_t{130}, bytes.size() / 2, bytes.size() - 5}) {
        auto damaged = bytes;
        damaged[at] ^= 0x10;
        auto bad = (dir / "bad.kdt").string();
        { std::ofstream(bad, std::ios::binary).write(reinterpret_cast<const char*>(damaged.data()), damaged.size()); }
        auto r = test::run_tool("kdpm-validate " + bad);
        INFO("byte " << at << ": " << r.output);
        CHECK(r.exit_code == 1);
        CHECK_THAT(r.output, Catch::StartsWith("kdpm-validate: error: "));
        CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
    }
}

TEST_CASE("the tools reject a missing file and bad arguments", "[tools]") {
    auto missing = test::run_tool("kdpm-validate /nonexistent/file.kdg");
    CHECK(missing.exit_code == 1);
    CHECK_THAT(missing.output, Catch::Contains("cannot open"));
    CHECK(test::run_tool("kdpm-inspect --frobnicate x").exit_code == 2);
    CHECK(test::run_tool("kdpm-inspect").exit_code == 2);
}
