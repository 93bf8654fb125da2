#pragma once
// Whether this CPU (and its OS) runs the AVX2 / AVX-512 code paths, asked once: the walks compile
// those paths in regions of their own and choose at run time, so one binary runs on every x86-64.
#if defined(__x86_64__) && !defined(__CUDACC__)
#define KDPM_CPU_FEATURES 1

// KDPM_BEGIN_TARGET("avx2") ... KDPM_END_TARGET: the functions between are compiled for that
// instruction set (GCC's target pragma, clang's target attribute), the rest of the file for the
// baseline. Name the one set meant and no more: "avx2" alone brings no fused multiply-add, which
// would round once where the scalar walks round twice.
#define KDPM_PRAGMA(text) _Pragma(#text)
#if defined(__clang__)
#define KDPM_BEGIN_TARGET(isa) KDPM_PRAGMA(clang attribute push(__attribute__((target(isa))), apply_to = function))
#define KDPM_END_TARGET _Pragma("clang attribute pop")
#else
#define KDPM_BEGIN_TARGET(isa) _Pragma("GCC push_options") KDPM_PRAGMA(GCC target(isa))
#define KDPM_END_TARGET _Pragma("GCC pop_options")
#endif

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
