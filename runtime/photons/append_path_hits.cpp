#include "runtime/photons/append_path_hits.h"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace kdpm {

void append_path_hits(const PhotonHit* slots, std::uint64_t per_path, const PhotonPathResult* results,
                      std::uint64_t n, std::uint64_t batch_stored, std::vector<PhotonHit>& hits) {
    // Where each block of paths starts writing: a prefix sum over the blocks, so that the workers
    // need no shared cursor and the order is the paths' whatever the thread count.
    constexpr std::uint64_t kBlock = 4096;
    const std::uint64_t blocks = (n + kBlock - 1) / kBlock;
    std::vector<std::uint64_t> block_start(blocks + 1);
    block_start[0] = hits.size();
    for (std::uint64_t b = 0; b < blocks; ++b) {
        std::uint64_t sum = 0;
        for (std::uint64_t i = b * kBlock, end = std::min(n, i + kBlock); i < end; ++i) sum += results[i].stored;
        block_start[b + 1] = block_start[b] + sum;
    }
    hits.resize(hits.size() + batch_stored);
    PhotonHit* out = hits.data();
    tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, blocks), [&](const tbb::blocked_range<std::uint64_t>& r) {
        for (std::uint64_t b = r.begin(); b != r.end(); ++b) {
            PhotonHit* to = out + block_start[b];
            for (std::uint64_t i = b * kBlock, end = std::min(n, i + kBlock); i < end; ++i) {
                // Most paths store a hit or two: one at a time beats a bulk copy call per path.
                const PhotonHit* path_hits = slots + i * per_path;
                for (std::uint32_t k = 0; k < results[i].stored; ++k) *to++ = path_hits[k];
            }
        }
    });
}

}  // namespace kdpm
