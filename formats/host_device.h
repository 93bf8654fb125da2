#pragma once
// KDPM_HD marks a function that runs on both the CPU and a CUDA GPU (DESIGN.md: one kernel,
// two backends). Under nvcc it is __host__ __device__; elsewhere it is empty.
#if defined(__CUDACC__)
#define KDPM_HD __host__ __device__
#define KDPM_INLINE __forceinline__
#else
#define KDPM_HD
#define KDPM_INLINE inline
#endif
