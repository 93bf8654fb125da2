// The output discipline (formats/output_file.h) for container files: symlinks written through,
// non-regular targets refused, full disks reported, inputs never overwritten, temporaries
// removed on signals and after a SIGKILL, long names accepted.
#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <utime.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "formats/atomic_file.h"
#include "formats/format_error.h"
#include "formats/output_file.h"
#include "tests/hostile/fork_child.h"
#include "tests/support/file_contents.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;
namespace fs = std::filesystem;

namespace {

void write_text(const fs::path& p, const std::string& text) {
    write_file_atomically(p, [&](const ByteSink& sink) { sink(text.data(), text.size()); });
}

std::vector<std::string> names_in(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    return names;
}

}  // namespace

TEST_CASE("a write to a symlink replaces its target and keeps the link", "[hostile][output]") {
    test::TempDir dir;
    { std::ofstream(dir / "real.kdg") << "old"; }
    fs::create_symlink("real.kdg", dir / "link.kdg");
    write_text(dir / "link.kdg", "new");
    CHECK(fs::is_symlink(dir / "link.kdg"));
    CHECK(test::file_contents(dir / "real.kdg") == "new");
    // A dangling link names the file to create.
    fs::create_symlink("made.kdg", dir / "dangling.kdg");
    write_text(dir / "dangling.kdg", "made");
    CHECK(fs::is_symlink(dir / "dangling.kdg"));
    CHECK(test::file_contents(dir / "made.kdg") == "made");
}

TEST_CASE("a write onto a FIFO or a folder is refused and leaves it in place", "[hostile][output]") {
    test::TempDir dir;
    REQUIRE(::mkfifo((dir / "pipe").c_str(), 0600) == 0);
    CHECK_THROWS_WITH(write_text(dir / "pipe", "x"), Catch::Contains("not a regular file"));
    struct stat st{};
    REQUIRE(::lstat((dir / "pipe").c_str(), &st) == 0);
    CHECK(S_ISFIFO(st.st_mode));
    fs::create_symlink("pipe", dir / "to-pipe");
    CHECK_THROWS_WITH(write_text(dir / "to-pipe", "x"), Catch::Contains("not a regular file"));
    CHECK(names_in(dir.path()).size() == 2);
}

TEST_CASE("a full disk is an error and the old file survives", "[hostile][output]") {
    test::TempDir dir;
    const fs::path dest = dir / "tree.kdg";
    write_text(dest, "old contents");
    const auto end = test::run_in_child([&] {
        ::signal(SIGXFSZ, SIG_IGN);
        struct rlimit lim{4096, 4096};
        ::setrlimit(RLIMIT_FSIZE, &lim);
        try {
            write_text(dest, std::string(100000, 'x'));
        } catch (const FormatError& e) {
            return std::string(e.what()).find("write failed") != std::string::npos ? 0 : 2;
        }
        return 1;
    });
    CHECK(end.exit_code == 0);
    CHECK(test::file_contents(dest) == "old contents");
    CHECK(names_in(dir.path()).size() == 1);
}

TEST_CASE("an output that is one of the inputs is refused", "[hostile][output]") {
    test::TempDir dir;
    { std::ofstream(dir / "scene.kdg") << "input"; }
    fs::create_symlink("scene.kdg", dir / "alias.kdg");
    const std::vector<fs::path> inputs{dir / "scene.kdg"};
    CHECK_THROWS_WITH(check_output_not_input(dir / "scene.kdg", inputs), Catch::Contains("it is the input"));
    CHECK_THROWS_WITH(check_output_not_input(dir / "alias.kdg", inputs), Catch::Contains("it is the input"));
    fs::create_hard_link(dir / "scene.kdg", dir / "hard.kdg");
    CHECK_THROWS(check_output_not_input(dir / "hard.kdg", inputs));
    CHECK_NOTHROW(check_output_not_input(dir / "other.kdg", inputs));
}

TEST_CASE("SIGINT, SIGTERM, SIGHUP and SIGXFSZ remove the temporary of a write in progress", "[hostile][output]") {
    for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGXFSZ}) {
        test::TempDir dir;
        const auto end = test::run_in_child([&] {
            for (int s : {SIGINT, SIGTERM, SIGHUP, SIGXFSZ}) ::signal(s, SIG_DFL);  // not the test framework's
            write_file_atomically(dir / "out.kdph", [&](const ByteSink& sink) {
                sink("partial", 7);
                ::raise(sig);
            });
            return 0;
        });
        CHECK(end.signal == sig);
        CHECK(names_in(dir.path()).empty());
    }
}

TEST_CASE("the temporary of a killed writer is recognisable and removed by the next write", "[hostile][output]") {
    test::TempDir dir;
    const auto end = test::run_in_child([&] {
        write_file_atomically(dir / "out.kdph", [&](const ByteSink& sink) {
            sink("partial", 7);
            ::raise(SIGKILL);
        });
        return 0;
    });
    REQUIRE(end.signal == SIGKILL);
    auto left = names_in(dir.path());
    REQUIRE(left.size() == 1);
    CHECK(is_output_temporary_name(left[0]));
    CHECK_FALSE(is_output_temporary_name("out.kdph"));
    const auto validated = test::run_tool("kdpm-validate '" + (dir / left[0]).string() + "'");
    CHECK(validated.exit_code == 1);
    CHECK_THAT(validated.output, Catch::Contains("interrupted kdpm write"));
    // Age it past the grace period that protects writers in other PID namespaces.
    const struct utimbuf old{::time(nullptr) - 3600, ::time(nullptr) - 3600};
    REQUIRE(::utime((dir / left[0]).c_str(), &old) == 0);
    write_text(dir / "out.kdph", "whole");
    CHECK(names_in(dir.path()) == std::vector<std::string>{"out.kdph"});
}

TEST_CASE("an output name of 252 characters is written (its temporary's name is shortened)", "[hostile][output]") {
    test::TempDir dir;
    const fs::path dest = dir / (std::string(248, 'n') + ".kdg");
    write_text(dest, "long");
    CHECK(test::file_contents(dest) == "long");
    CHECK(names_in(dir.path()).size() == 1);
}
