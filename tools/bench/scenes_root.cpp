#include "tools/bench/scenes_root.h"

#include <stdexcept>
#include <vector>

namespace kdpm::bench {
namespace fs = std::filesystem;

namespace {

bool has_scenes(const fs::path& root) {
    std::error_code ec;
    return fs::is_regular_file(root / "scenes" / "cornell-box" / "cornell-box.json", ec);
}

}  // namespace

fs::path find_scenes_root(const std::string& given, const char* argv0) {
    if (!given.empty()) {
        if (!has_scenes(given))
            throw std::runtime_error("--repo " + given + " has no scenes/cornell-box/cornell-box.json");
        return given;
    }
    std::vector<fs::path> tried;
    std::error_code ec;
    for (fs::path dir = fs::current_path(ec); !ec && !dir.empty(); dir = dir.parent_path()) {
        tried.push_back(dir);
        if (dir == dir.parent_path()) break;
    }
    fs::path exe = fs::canonical("/proc/self/exe", ec);
    if (ec) exe = fs::absolute(argv0);
    tried.push_back(exe.parent_path().parent_path().parent_path());  // <repo>/build/bin/kdpm-bench
    tried.push_back(exe.parent_path().parent_path() / "share" / "kdpm");  // <prefix>/bin/kdpm-bench
    for (const auto& dir : tried)
        if (has_scenes(dir)) return dir;
    throw std::runtime_error("cannot find the scenes/ folder from " + fs::current_path(ec).string() +
                             " or from the executable; run it from the kdpm source tree or pass --repo DIR");
}

}  // namespace kdpm::bench
