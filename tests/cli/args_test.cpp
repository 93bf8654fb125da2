#include <catch2/catch.hpp>

#include <array>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "tests/support/temp_dir.h"
#include "tools/cli/args.h"

using namespace kdpm;

namespace {

// Parses a command line given as words (argv[0] first).
void parse(cli::Args& args, std::vector<std::string> words) {
    std::vector<char*> argv;
    for (auto& w : words) argv.push_back(w.data());
    args.parse(static_cast<int>(argv.size()), argv.data());
}

}  // namespace

TEST_CASE("options flags and positionals are parsed", "[cli]") {
    std::string input, output;
    int k = 0;
    double exposure = 0;
    bool quiet = false;
    cli::Args args("tool", "test");
    args.positional("INPUT", &input, "in")
        .option("output", &output, "FILE", "out")
        .option("k", &k, "N", "k", 1, 256)
        .option("exposure", &exposure, "STOPS", "e", -20, 20)
        .flag("quiet", &quiet, "q")
        .short_name('o', "output");
    parse(args, {"tool", "scene.kdg", "-o", "x.png", "--k=32", "--exposure", "-1.5", "--quiet"});
    CHECK(input == "scene.kdg");
    CHECK(output == "x.png");
    CHECK(k == 32);
    CHECK(exposure == -1.5);
    CHECK(quiet);
    CHECK_THAT(args.usage(), Catch::Contains("-o,--output FILE"));
}

TEST_CASE("a short name is only an alias of its long option", "[cli]") {
    std::string output;
    cli::Args args("tool", "test");
    args.option("output", &output, "FILE", "out").short_name('o', "output");
    parse(args, {"tool", "--output=a.kdg"});
    CHECK(output == "a.kdg");
    parse(args, {"tool", "-o", "b.kdg"});
    CHECK(output == "b.kdg");
}

TEST_CASE("a three-number option takes the next three words, negative numbers included", "[cli]") {
    std::optional<std::array<double, 3>> eye, up;
    std::string input;
    cli::Args args("tool", "test");
    args.positional("INPUT", &input, "in").option("eye", &eye, "eye").option("up", &up, "up");
    parse(args, {"tool", "--eye", "-1", "2.5", "-3e2", "scene.kdg"});
    REQUIRE(eye);
    CHECK(*eye == std::array<double, 3>{-1.0, 2.5, -300.0});
    CHECK_FALSE(up);
    CHECK(input == "scene.kdg");
    CHECK_THAT(args.usage(), Catch::Contains("--eye X Y Z") && Catch::Contains("--version"));
}

TEST_CASE("options come from a --config file (TOML or INI); the command line wins", "[cli]") {
    test::TempDir dir;
    std::ofstream(dir / "render.toml") << "# render settings kept by a pipeline\nk = 32\nexposure = -1.5\nquiet = true\n"
                                          "output = \"frame.png\"\neye = [1, 2, 3]\n";
    std::ofstream(dir / "render.ini") << "[default]\nk=8\n";
    std::string output;
    int k = 0;
    double exposure = 0;
    bool quiet = false;
    std::optional<std::array<double, 3>> eye;
    auto declare = [&](cli::Args& args) {
        args.option("output", &output, "FILE", "out")
            .option("k", &k, "N", "k", 1, 256)
            .option("exposure", &exposure, "STOPS", "e", -20, 20)
            .flag("quiet", &quiet, "q")
            .option("eye", &eye, "eye");
    };
    cli::Args a("tool", "test");
    declare(a);
    parse(a, {"tool", "--config", (dir / "render.toml").string(), "--k", "64"});
    CHECK(k == 64);
    CHECK(exposure == -1.5);
    CHECK(quiet);
    CHECK(output == "frame.png");
    REQUIRE(eye);
    CHECK(*eye == std::array<double, 3>{1.0, 2.0, 3.0});

    cli::Args b("tool", "test");
    declare(b);
    parse(b, {"tool", "--config", (dir / "render.ini").string()});
    CHECK(k == 8);
}

TEST_CASE("an option given twice takes its last value, so scripts can append overrides", "[cli]") {
    int k = 0;
    std::optional<std::array<double, 3>> eye;
    cli::Args args("tool", "test");
    args.option("k", &k, "N", "k", 1, 256).option("eye", &eye, "eye");
    parse(args, {"tool", "--k", "4", "--eye", "1", "1", "1", "--k=5", "--eye", "-2", "-3", "-4"});
    CHECK(k == 5);
    REQUIRE(eye);
    CHECK(*eye == std::array<double, 3>{-2.0, -3.0, -4.0});
}

TEST_CASE("a repeated positional collects every remaining argument in order", "[cli]") {
    std::string output;
    std::vector<std::string> inputs;
    cli::Args args("tool", "test");
    args.positionals("PART", &inputs, "parts").option("output", &output, "FILE", "out").short_name('o', "output");
    parse(args, {"tool", "b.kdph", "-o", "x.kdph", "a.kdph", "--", "-c.kdph"});
    CHECK(inputs == std::vector<std::string>{"b.kdph", "a.kdph", "-c.kdph"});
    CHECK(output == "x.kdph");
    CHECK_THAT(args.usage(), Catch::Contains("PART..."));
}
