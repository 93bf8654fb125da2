// The builder's radix sort orders like std::stable_sort by the same key, ties and all.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "formats/stable_radix_sort.h"

using namespace kdpm;

namespace {

struct Item {
    std::uint64_t key;      // below 2^kRadixKeyBits
    std::uint32_t arrival;  // tells equal keys apart
    bool operator==(const Item&) const = default;
};

std::vector<Item> random_items(std::size_t n, std::uint64_t key_range, std::uint32_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<std::uint64_t> key(0, key_range - 1);
    std::vector<Item> items(n);
    for (std::size_t i = 0; i < n; ++i) items[i] = {key(rng), static_cast<std::uint32_t>(i)};
    return items;
}

void check_sorts_like_stable_sort(std::vector<Item> items) {
    std::vector<Item> expected = items;
    std::stable_sort(expected.begin(), expected.end(), [](const Item& a, const Item& b) { return a.key < b.key; });
    stable_radix_sort(items, [](const Item& i) { return i.key; });
    CHECK(items == expected);
}

}  // namespace

TEST_CASE("the radix sort is a stable sort by the key", "[geometry][builder]") {
    constexpr std::uint64_t kFullRange = std::uint64_t{1} << kRadixKeyBits;
    SECTION("keys over all digits") { check_sorts_like_stable_sort(random_items(20000, kFullRange, 1)); }
    SECTION("many equal keys") { check_sorts_like_stable_sort(random_items(5000, 37, 2)); }
    SECTION("keys differing only in the top digit") {
        std::vector<Item> items = random_items(3000, 8, 3);
        for (Item& i : items) i.key <<= kRadixKeyBits - 3;
        check_sorts_like_stable_sort(items);
    }
    SECTION("all keys equal, already sorted, reversed, one item, none") {
        check_sorts_like_stable_sort(random_items(1000, 1, 4));
        std::vector<Item> ascending(1500), descending(1500);
        for (std::uint32_t i = 0; i < 1500; ++i) {
            ascending[i] = {i * 12345ull, i};
            descending[i] = {(1500 - i) * 999ull, i};
        }
        check_sorts_like_stable_sort(ascending);
        check_sorts_like_stable_sort(descending);
        check_sorts_like_stable_sort(random_items(1, kFullRange, 5));
        check_sorts_like_stable_sort({});
    }
}
