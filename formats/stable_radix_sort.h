#pragma once
// A stable LSD radix sort by a key of at most 36 bits, in three passes of up to 12-bit digits.
// The geometry builder sorts a node's split events by position and type (34 bits) while they
// already arrive in triangle order: stability then yields exactly what std::sort by the whole
// event gives, in a few linear passes instead of n log n compares, which shortens the serial
// start of a build (the root's sort). The CPU photon shooter orders each wave of rays by a 30-bit
// key of origin and direction, ties in path order.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace kdpm {

inline constexpr int kRadixKeyBits = 36;

// Sorts `items` stably by key(item), a std::uint64_t below 2^kRadixKeyBits.
template <class T, class Key>
void stable_radix_sort(std::vector<T>& items, const Key& key) {
    constexpr int kDigitBits = kRadixKeyBits / 3;
    constexpr std::size_t kBuckets = std::size_t{1} << kDigitBits;
    constexpr std::uint64_t kMask = kBuckets - 1;
    const std::size_t n = items.size();
    if (n < 2) return;
    std::vector<std::uint32_t> count(3 * kBuckets, 0);
    for (const T& item : items) {
        const std::uint64_t k = key(item);
        ++count[k & kMask];
        ++count[kBuckets + ((k >> kDigitBits) & kMask)];
        ++count[2 * kBuckets + ((k >> (2 * kDigitBits)) & kMask)];
    }
    std::vector<T> scratch(n);
    std::vector<T>* from = &items;
    std::vector<T>* to = &scratch;
    for (int pass = 0; pass < 3; ++pass) {
        std::uint32_t* c = count.data() + pass * kBuckets;
        // A digit that every item shares leaves the order as it is.
        const std::uint64_t digit0 = (key((*from)[0]) >> (pass * kDigitBits)) & kMask;
        if (c[digit0] == n) continue;
        std::uint32_t sum = 0;
        for (std::size_t b = 0; b < kBuckets; ++b) sum += std::exchange(c[b], sum);
        const int shift = pass * kDigitBits;
        T* out = to->data();
        for (const T& item : *from) out[c[(key(item) >> shift) & kMask]++] = item;
        std::swap(from, to);
    }
    if (from != &items) items.swap(*from);
}

}  // namespace kdpm
