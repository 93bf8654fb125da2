// checksum64 picks its implementation from the CPU at run time: every implementation must give
// the value of the portable one, on every length class of xxh3 (0-16, 17-128, 129-240 bytes,
// then stripes, blocks and a tail) and at any alignment.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include "formats/checksum.h"

using namespace kdpm;

TEST_CASE("checksum64 is xxh3-64", "[formats]") {
    // The value the xxHash specification gives for no input (seed 0).
    CHECK(checksum64(nullptr, 0) == 0x2D06800538D394C2ull);
    CHECK(checksum64_with(ChecksumIsa::portable, nullptr, 0) == 0x2D06800538D394C2ull);
}

TEST_CASE("every checksum implementation the CPU has agrees with the portable one", "[formats]") {
    std::vector<std::uint8_t> bytes((std::size_t{1} << 20) + 64);
    std::uint64_t state = 0x9E3779B97F4A7C15ull;
    for (auto& b : bytes) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        b = static_cast<std::uint8_t>(state >> 56);
    }
    std::vector<std::size_t> sizes;
    for (std::size_t s = 0; s <= 300; ++s) sizes.push_back(s);
    for (std::size_t s : {1023u, 1024u, 1025u, 16383u, 16384u, 16385u, 100003u, 1u << 20}) sizes.push_back(s);

    for (ChecksumIsa isa : {ChecksumIsa::portable, ChecksumIsa::avx2}) {
        if (!checksum_isa_available(isa)) {
            WARN("this CPU lacks checksum implementation " << static_cast<int>(isa) << ": not compared");
            continue;
        }
        for (std::size_t offset : {0u, 1u, 7u, 32u}) {
            for (std::size_t size : sizes) {
                const std::uint8_t* p = bytes.data() + offset;
                INFO("implementation " << static_cast<int>(isa) << ", offset " << offset << ", size " << size);
                const std::uint64_t expected = checksum64_with(ChecksumIsa::portable, p, size);
                REQUIRE(checksum64_with(isa, p, size) == expected);
                REQUIRE(checksum64(p, size) == expected);
            }
        }
    }
    // A changed byte changes the value whatever the implementation.
    const std::uint64_t before = checksum64(bytes.data(), bytes.size());
    bytes[bytes.size() / 2] ^= 0x10;
    CHECK(checksum64(bytes.data(), bytes.size()) != before);
}
