#pragma once
// Whether this CPU (and its OS) runs the AVX2 / AVX-512 code paths, asked once: the walks compile
// those paths in regions of their own and choose at run time, so one binary runs on every x86-64.
#if defined(__x86_64__) && !defined(__CUDACC__)
#define KDPM_CPU_FEATURES 1

namespace kdpm {

inline bool cpu_has_avx2() {
    static const bool has = __builtin_cpu_supports("avx2");
    return has;
}
inline bool cpu_has_avx512() {
    static const bool has = __builtin_cpu_supports("avx512f");
    return has;
}

}  // namespace kdpm
#endif
