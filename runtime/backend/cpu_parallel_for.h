#pragma once
// The CPU backend's launcher: runs body(i) for i in [0, n) on oneTBB's workers in grains.
// Kernels must write only to slots owned by i, so results never depend on the thread count.
#include <cstdint>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace kdpm {

template <class Body>
void cpu_parallel_for(std::uint64_t n, const Body& body, std::uint64_t grain = 64) {
    tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, n, grain),
                      [&](const tbb::blocked_range<std::uint64_t>& r) {
                          for (std::uint64_t i = r.begin(); i != r.end(); ++i) body(i);
                      });
}

}  // namespace kdpm
