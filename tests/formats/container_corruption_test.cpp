#include <catch2/catch.hpp>

#include "formats/container_reader.h"
#include "formats/tree_validation.h"
#include "tests/formats/sample_container.h"

using namespace kdpm;

namespace {

// Open + full validation, as kdpm-validate does; true when the bytes were rejected.
bool rejected(const std::vector<std::uint8_t>& bytes) {
    try {
        auto r = ContainerReader::from_bytes(bytes, "corrupt");
        validate_file(r, {});
        return false;
    } catch (const FormatError&) {
        return true;
    }
}

}  // namespace

TEST_CASE("every truncation of a file is rejected", "[formats]") {
    const auto bytes = test::sample_writer().bytes();
    REQUIRE_FALSE(rejected(bytes));
    for (std::size_t len = 0; len < bytes.size(); ++len) {
        std::vector<std::uint8_t> cut(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(len));
        INFO("length " << len);
        CHECK(rejected(cut));
    }
}

TEST_CASE("every single-bit flip of a file is detected", "[formats]") {
    const auto bytes = test::sample_writer().bytes();
    std::size_t missed = 0;
    for (std::size_t bit = 0; bit < bytes.size() * 8; ++bit) {
        auto flipped = bytes;
        flipped[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
        if (!rejected(flipped)) {
            ++missed;
            UNSCOPED_INFO("undetected flip at byte " << bit / 8 << " bit " << bit % 8);
        }
    }
    CHECK(missed == 0);
}

TEST_CASE("extra bytes after the section table are rejected", "[formats]") {
    auto bytes = test::sample_writer().bytes();
    bytes.push_back(0);
    CHECK_THROWS_WITH(ContainerReader::from_bytes(bytes, "padded"), Catch::Contains("truncated or padded"));
}
