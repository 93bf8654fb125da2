// xxh3-64 compiled for AVX2 (this file only; see formats/CMakeLists.txt). checksum64 calls it only
// where the CPU has AVX2. Nothing but xxhash's own static functions is compiled here, so no
// AVX2 code can stand in for an inline function shared with the rest of the program.
#include <cstddef>
#include <cstdint>

#define XXH_INLINE_ALL
#include <xxhash.h>

#if !defined(__AVX2__) || XXH_VECTOR != XXH_AVX2
#error "checksum_avx2.cpp must be compiled with -mavx2"
#endif

namespace kdpm {

std::uint64_t checksum64_avx2(const void* data, std::size_t size) { return XXH3_64bits(data, size); }

}  // namespace kdpm
