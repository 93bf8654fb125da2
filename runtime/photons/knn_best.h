#pragma once
// The k best photons a k-nearest search has kept so far: unordered slots plus the largest
// distance of each block of 8 slots. Replacing the farthest rewrites one slot and finds the new
// farthest from one block's 8 distances and the k/8 block maxima, with one data-dependent
// branch (which group of four holds it), because a binary max-heap's sift-down costs many
// instructions and mispredicted branches per replacement. On x86 the maxima are SSE2 lanes;
// elsewhere (CUDA, other CPUs) the same steps are scalar loops. The
// slots chosen, and so the order a caller sums them in, are the same on every backend.
#include <cstdint>

#include "formats/host_device.h"

#if defined(__SSE2__) && !defined(__CUDA_ARCH__)
#include <emmintrin.h>
#define KDPM_KNN_SSE2 1
#endif

namespace kdpm {

inline constexpr std::uint32_t kMaxGatherK = 256;

// k as every search and estimate uses it: 1..kMaxGatherK.
KDPM_HD KDPM_INLINE std::uint32_t clamp_gather_k(std::uint32_t k) {
    return k < 1 ? 1 : (k > kMaxGatherK ? kMaxGatherK : k);
}

// A search's result: d2/index[0..count) hold the photons found, d2[0] the farthest of them, the
// others in no particular order. The rest is the search's scratch.
struct KnnHeap {
    static constexpr std::uint32_t kBlock = 8;
    static constexpr std::uint32_t kBlocks = kMaxGatherK / kBlock;
    float d2[kMaxGatherK];
    std::uint32_t index[kMaxGatherK];
    float block_max[kBlocks];
};

namespace knn_detail {

// Below every squared distance: pads the slots and blocks past k so they are never the largest.
inline constexpr float kNoDistance = -1.0f;

// The steps in plain loops: what CUDA and CPUs without SSE2 run, and the reference the SSE2
// versions are tested against.
namespace portable {

KDPM_HD KDPM_INLINE float max_of(const float* v, std::uint32_t n) {
    float m = v[0];
    for (std::uint32_t i = 1; i < n; ++i) m = v[i] > m ? v[i] : m;
    return m;
}

KDPM_HD KDPM_INLINE std::uint32_t first_equal(const float* v, std::uint32_t n, float value) {
    std::uint32_t i = 0;
    while (i + 1 < n && !(v[i] == value)) ++i;
    return i;
}

}  // namespace portable

#if KDPM_KNN_SSE2
// The largest of the four lanes.
inline float max_of_lanes(__m128 m) {
    m = _mm_max_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(1, 0, 3, 2)));
    m = _mm_max_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm_cvtss_f32(m);
}

// v with the lanes whose id equals `slot` set to `value`.
inline __m128 replace_lanes(__m128 v, __m128i ids, __m128i slot, __m128 value) {
    const __m128 m = _mm_castsi128_ps(_mm_cmpeq_epi32(ids, slot));
    return _mm_or_ps(_mm_and_ps(m, value), _mm_andnot_ps(m, v));
}
#endif

// The largest of v[0..n), n a multiple of 4.
KDPM_HD KDPM_INLINE float max_of(const float* v, std::uint32_t n) {
#if KDPM_KNN_SSE2
    __m128 m = _mm_loadu_ps(v);
    for (std::uint32_t i = 4; i < n; i += 4) m = _mm_max_ps(m, _mm_loadu_ps(v + i));
    return max_of_lanes(m);
#else
    return portable::max_of(v, n);
#endif
}

// The first i in [0, n) (n a multiple of 4) with v[i] == value; value is one of them (n - 1
// if it is not, as for a NaN).
KDPM_HD KDPM_INLINE std::uint32_t first_equal(const float* v, std::uint32_t n, float value) {
#if KDPM_KNN_SSE2
    const __m128 want = _mm_set1_ps(value);
    for (std::uint32_t i = 0;; i += 4) {
        const int mask = _mm_movemask_ps(_mm_cmpeq_ps(_mm_loadu_ps(v + i), want));
        if (mask != 0 || i + 4 >= n) {
            const std::uint32_t at = i + static_cast<std::uint32_t>(__builtin_ctz(static_cast<unsigned>(mask) | 16u));
            return at < n ? at : n - 1;
        }
    }
#else
    return portable::first_equal(v, n, value);
#endif
}

// The k best of a search in a KnnHeap: appended until k are kept, then the farthest replaced.
class KnnBest {
public:
    KDPM_HD KDPM_INLINE KnnBest(KnnHeap& h, std::uint32_t k)
        : d2_(h.d2), index_(h.index), block_max_(h.block_max), k_(k),
          blocks_((k + KnnHeap::kBlock - 1) / KnnHeap::kBlock), block_groups_((blocks_ + 3) & ~3u) {}

    KDPM_HD KDPM_INLINE bool full() const { return count_ == k_; }
    // The largest distance kept (valid once full()).
    KDPM_HD KDPM_INLINE float farthest() const { return farthest_; }

    // While not full: keeps photon p at d2. Returns whether that made it full.
    KDPM_HD KDPM_INLINE bool append(float d2, std::uint32_t p) {
        d2_[count_] = d2;
        index_[count_] = p;
        if (++count_ < k_) return false;
        become_full();
        return true;
    }

    // When full: photon p at d2 (nearer than farthest()) takes the farthest's slot.
    KDPM_HD KDPM_INLINE void replace_farthest(float d2, std::uint32_t p) {
        index_[worst_] = p;
        const std::uint32_t b = worst_ / KnnHeap::kBlock;
#if KDPM_KNN_SSE2
        // The slot and its block's maximum rewritten as whole vectors, from registers: the
        // vector loads that follow (this block's maximum, find_farthest's scans) cannot take a
        // single float just stored from the store buffer, and would wait for it to reach the cache
        // on every replacement.
        float* block = d2_ + b * KnnHeap::kBlock;
        const __m128i slot = _mm_set1_epi32(static_cast<int>(worst_ % KnnHeap::kBlock));
        const __m128 value = _mm_set1_ps(d2);
        const __m128 lo = replace_lanes(_mm_loadu_ps(block), _mm_setr_epi32(0, 1, 2, 3), slot, value);
        const __m128 hi = replace_lanes(_mm_loadu_ps(block + 4), _mm_setr_epi32(4, 5, 6, 7), slot, value);
        _mm_storeu_ps(block, lo);
        _mm_storeu_ps(block + 4, hi);
        float* group = block_max_ + (b & ~3u);
        const __m128i group_slot = _mm_set1_epi32(static_cast<int>(b & 3u));
        _mm_storeu_ps(group, replace_lanes(_mm_loadu_ps(group), _mm_setr_epi32(0, 1, 2, 3), group_slot,
                                           _mm_set1_ps(max_of_lanes(_mm_max_ps(lo, hi)))));
#else
        d2_[worst_] = d2;
        block_max_[b] = max_of(d2_ + b * KnnHeap::kBlock, KnnHeap::kBlock);
#endif
        find_farthest();
    }

    // Moves the farthest kept photon to slot 0, as the result promises. Returns how many are kept.
    KDPM_HD KDPM_INLINE std::uint32_t finish() {
        if (count_ == 0) return 0;
        std::uint32_t w = 0;
        if (full()) {
            w = worst_;
        } else {
            for (std::uint32_t i = 1; i < count_; ++i)
                if (d2_[i] > d2_[w]) w = i;
        }
        const float d = d2_[w];
        const std::uint32_t p = index_[w];
        d2_[w] = d2_[0];
        index_[w] = index_[0];
        d2_[0] = d;
        index_[0] = p;
        return count_;
    }

private:
    // Once a search, when the k-th photon is kept: the padding and the block maxima. Out of line
    // on the CPU because, inlined, the compiler sets up this loop's bounds and pointers again
    // before every 16-photon chunk that has a photon to keep; the photons and images are the same
    // bit for bit either way.
#if !defined(__CUDA_ARCH__) && (defined(__GNUC__) || defined(__clang__))
    __attribute__((noinline, cold))
#endif
    KDPM_HD void become_full() {
        for (std::uint32_t i = k_; i < blocks_ * KnnHeap::kBlock; ++i) d2_[i] = kNoDistance;
        for (std::uint32_t b = 0; b < blocks_; ++b) block_max_[b] = max_of(d2_ + b * KnnHeap::kBlock, KnnHeap::kBlock);
        for (std::uint32_t b = blocks_; b < block_groups_; ++b) block_max_[b] = kNoDistance;
        find_farthest();
    }

    KDPM_HD KDPM_INLINE void find_farthest() {
        farthest_ = max_of(block_max_, block_groups_);
        const std::uint32_t b = first_equal(block_max_, block_groups_, farthest_);
        worst_ = b * KnnHeap::kBlock + first_equal(d2_ + b * KnnHeap::kBlock, KnnHeap::kBlock, farthest_);
    }

    float* d2_;
    std::uint32_t* index_;
    float* block_max_;
    std::uint32_t k_, blocks_, block_groups_;
    std::uint32_t count_ = 0, worst_ = 0;
    float farthest_ = 0.0f;
};

}  // namespace knn_detail
}  // namespace kdpm
