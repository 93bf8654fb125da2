#include "runtime/view/screenshot_name.h"

#include <ctime>
#include <string>

namespace kdpm {

std::filesystem::path unique_screenshot_name(const std::filesystem::path& folder) {
    std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    const std::string base = std::string("kdpm-view-") + stamp;
    std::filesystem::path candidate = folder / (base + ".png");
    for (int n = 2; std::filesystem::exists(candidate); ++n)
        candidate = folder / (base + "-" + std::to_string(n) + ".png");
    return candidate;
}

}  // namespace kdpm
