#include <catch2/catch.hpp>

#include <string>
#include <vector>

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
    CHECK_THAT(args.usage(), Catch::Contains("-o, --output FILE"));
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
