#include "formats/oiio/oiio_plugin_loader.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace kdpm {
namespace {

constexpr const char* kModuleName = "kdpm-oiio.so";

std::vector<std::filesystem::path> candidates() {
    if (const char* forced = std::getenv("KDPM_OIIO_PLUGIN"); forced && *forced) return {forced};
    std::vector<std::filesystem::path> paths;
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) paths.push_back(exe.parent_path().parent_path() / "lib" / "kdpm" / kModuleName);
    paths.push_back(std::filesystem::path(KDPM_OIIO_PLUGIN_INSTALL_DIR) / kModuleName);
    return paths;
}

const OiioPluginApi* try_load(std::string& why) {
    std::string missing;  // the candidates that are not there, for the message
    for (const std::filesystem::path& path : candidates()) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path, ec)) {
            missing += (missing.empty() ? "" : ", ") + path.string();
            continue;
        }
        // Kept loaded for the life of the process (never dlclose'd): its functions stay valid.
        void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* err = ::dlerror();
            why = "cannot load OpenImageIO support " + path.string() + ": " + (err ? err : "unknown error");
            return nullptr;
        }
        using Entry = const OiioPluginApi* (*)();
        auto entry = reinterpret_cast<Entry>(::dlsym(handle, "kdpm_oiio_plugin_api"));
        const OiioPluginApi* api = entry ? entry() : nullptr;
        if (!api || api->abi_version != kOiioPluginAbi) {
            why = "OpenImageIO support " + path.string() + " is from another kdpm build";
            return nullptr;
        }
        return api;
    }
    why = "cannot load OpenImageIO support: not found (looked for " + missing + ")";
    return nullptr;
}

}  // namespace

const OiioPluginApi& oiio_plugin() {
    static std::mutex mutex;
    static const OiioPluginApi* loaded = nullptr;
    std::lock_guard<std::mutex> lock(mutex);
    if (!loaded) {
        std::string why;
        loaded = try_load(why);
        if (!loaded) throw std::runtime_error(why);
    }
    return *loaded;
}

}  // namespace kdpm
