#pragma once
// xxh3-64, the checksum of headers, section tables and sections.
#include <cstddef>
#include <cstdint>

namespace kdpm {

std::uint64_t checksum64(const void* data, std::size_t size);

}  // namespace kdpm
