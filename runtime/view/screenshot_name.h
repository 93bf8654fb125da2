#pragma once
// F12 screenshots: kdpm-view-YYYYMMDD-HHMMSS.png in a folder, with -2, -3, ... when taken.
#include <filesystem>

namespace kdpm {

std::filesystem::path unique_screenshot_name(const std::filesystem::path& folder);

}  // namespace kdpm
