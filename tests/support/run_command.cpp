#include "tests/support/run_command.h"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace kdpm::test {

std::string tool_path(const std::string& tool) { return std::string(KDPM_BIN_DIR) + "/" + tool; }
std::string source_path(const std::string& relative) { return std::string(KDPM_SOURCE_DIR) + "/" + relative; }

CommandResult run_tool(const std::string& command) {
    // KDPM_TEST_BIN_DIR runs the end-to-end tests against other builds of the tools (e.g. an
    // older main, to see a regression test fail there).
    const char* other = std::getenv("KDPM_TEST_BIN_DIR");
    return run_shell(std::string(other && *other ? other : KDPM_BIN_DIR) + "/" + command);
}

CommandResult run_shell(const std::string& command) {
    const std::string full = command + " 2>&1 </dev/null";
    FILE* pipe = ::popen(full.c_str(), "r");
    if (!pipe) throw std::runtime_error("popen failed");
    CommandResult r{0, {}};
    std::array<char, 4096> buf;
    while (std::size_t n = std::fread(buf.data(), 1, buf.size(), pipe)) r.output.append(buf.data(), n);
    int status = ::pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return r;
}

std::string shared_scenes_dir() {
    if (const char* env = std::getenv("KDPM_SCENES"); env && *env) return env;
    auto p = std::filesystem::path(KDPM_SOURCE_DIR) / ".." / "shared" / "scenes";
    std::error_code ec;
    return std::filesystem::is_directory(p, ec) ? std::filesystem::weakly_canonical(p).string() : std::string();
}

}  // namespace kdpm::test
