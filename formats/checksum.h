#pragma once
// xxh3-64, the checksum of headers, section tables and sections.
#include <cstddef>
#include <cstdint>

namespace kdpm {

// Every load hashes each file whole, so the hash runs with the widest vectors the CPU has,
// chosen at run time (one binary for every x86-64). All implementations give the same value.
std::uint64_t checksum64(const void* data, std::size_t size);

// The implementations, for tests and benchmarks: checksum64 runs the best available one.
enum class ChecksumIsa : std::uint8_t { portable, avx2 };
bool checksum_isa_available(ChecksumIsa isa);
// Precondition: checksum_isa_available(isa).
std::uint64_t checksum64_with(ChecksumIsa isa, const void* data, std::size_t size);

}  // namespace kdpm
