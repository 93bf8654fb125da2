#pragma once
// Writes a file so that it appears whole or not at all, by the discipline of output_file.h:
// a private temporary beside the (resolved) destination, flushed to disk, then renamed over it.
// On failure the destination is untouched and the temporary is removed.
#include <cstddef>
#include <filesystem>
#include <functional>

namespace kdpm {

// `fill` receives a sink that appends bytes; any exception it throws aborts the write.
using ByteSink = std::function<void(const void* data, std::size_t size)>;
void write_file_atomically(const std::filesystem::path& destination,
                           const std::function<void(const ByteSink&)>& fill);

}  // namespace kdpm
