#include "formats/checksum.h"

#define XXH_INLINE_ALL
#include <xxhash.h>

namespace kdpm {

#if KDPM_CHECKSUM_AVX2
// checksum_avx2.cpp: the same xxh3, compiled for AVX2.
std::uint64_t checksum64_avx2(const void* data, std::size_t size);
#endif

bool checksum_isa_available(ChecksumIsa isa) {
    switch (isa) {
        case ChecksumIsa::portable: return true;
        case ChecksumIsa::avx2:
#if KDPM_CHECKSUM_AVX2
        {
            static const bool has = __builtin_cpu_supports("avx2");
            return has;
        }
#else
            return false;
#endif
    }
    return false;
}

std::uint64_t checksum64_with(ChecksumIsa isa, const void* data, std::size_t size) {
#if KDPM_CHECKSUM_AVX2
    if (isa == ChecksumIsa::avx2) return checksum64_avx2(data, size);
#endif
    (void)isa;
    return XXH3_64bits(data, size);
}

std::uint64_t checksum64(const void* data, std::size_t size) {
    static const ChecksumIsa best =
        checksum_isa_available(ChecksumIsa::avx2) ? ChecksumIsa::avx2 : ChecksumIsa::portable;
    return checksum64_with(best, data, size);
}

}  // namespace kdpm
