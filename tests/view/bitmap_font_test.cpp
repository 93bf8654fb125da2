#include <catch2/catch.hpp>

#include <set>
#include <string>
#include <tuple>

#include "runtime/view/bitmap_font.h"

using namespace kdpm;

namespace {

// The seven rows packed into one number (for comparing glyphs).
std::uint64_t packed(char c) {
    std::uint64_t bits = 0;
    for (int r = 0; r < BitmapFont::kGlyphHeight; ++r) bits = (bits << 8) | BitmapFont::row(c, r);
    return bits;
}

int lit(const Image& img) {
    int n = 0;
    for (std::size_t i = 0; i < img.pixel_count(); ++i) n += img.rgb[i * 3] > 0.5f;
    return n;
}

}  // namespace

TEST_CASE("bitmap font has a distinct non-empty glyph for every visible ASCII character", "[view][font]") {
    std::set<std::uint64_t> seen;
    for (char c = 33; c < 127; ++c) {
        INFO("character '" << c << "'");
        int bits = 0;
        for (int r = 0; r < BitmapFont::kGlyphHeight; ++r) {
            CHECK(BitmapFont::row(c, r) < 32);  // five columns
            bits += __builtin_popcount(BitmapFont::row(c, r));
        }
        CHECK(bits > 0);
        CHECK(seen.insert(packed(c)).second);
    }
    for (int r = 0; r < 7; ++r) CHECK(BitmapFont::row(' ', r) == 0);
}

TEST_CASE("bitmap font draws a glyph's bits as pixels", "[view][font]") {
    Image img(12, 10);
    draw_text(img, 1, 2, "H", glm::vec3(1.0f), 1, false);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const int gx = x - 1, gy = y - 2;
            const bool expected = gx >= 0 && gx < 5 && gy >= 0 && gy < 7 && (BitmapFont::row('H', gy) & (0x10 >> gx));
            INFO("pixel " << x << "," << y);
            CHECK((img.rgb[(static_cast<std::size_t>(y) * img.width + x) * 3] > 0.5f) == expected);
        }
    // Scale 2 lights four times the pixels.
    Image big(24, 20);
    draw_text(big, 0, 0, "H", glm::vec3(1.0f), 2, false);
    CHECK(lit(big) == 4 * lit(img));
}

TEST_CASE("bitmap font survives unknown characters and text off the image", "[view][font]") {
    Image img(40, 12);
    const std::string odd = std::string("\x01\t\x7f") + static_cast<char>(0xC3) + static_cast<char>(0xA9);
    draw_text(img, 0, 0, odd, glm::vec3(1.0f));
    CHECK(lit(img) > 0);  // drawn as boxes
    CHECK_FALSE(BitmapFont::known('\x01'));
    CHECK(BitmapFont::row('\x01', 0) == 0x1f);
    CHECK(BitmapFont::row('A', -1) == 0);
    CHECK(BitmapFont::row('A', 7) == 0);
    // Text partly off the image draws exactly the visible part of the same text drawn on a
    // larger canvas (out-of-bounds writes themselves are caught by the asan preset).
    auto clipped = [](int x, int y, const std::string& text, int scale) {
        Image small(8, 8);
        draw_text(small, x, y, text, glm::vec3(1.0f), scale);
        return small;
    };
    auto cropped = [](int x, int y, const std::string& text, int scale) {
        const int pad = 200;
        Image big(8 + 2 * pad, 8 + 2 * pad), crop(8, 8);
        draw_text(big, x + pad, y + pad, text, glm::vec3(1.0f), scale);
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i)
                for (int c = 0; c < 3; ++c)
                    crop.rgb[(static_cast<std::size_t>(j) * 8 + i) * 3 + c] =
                        big.rgb[(static_cast<std::size_t>(j + pad) * big.width + i + pad) * 3 + c];
        return crop;
    };
    for (auto [x, y, text, scale] : {std::tuple{-100, -3, std::string("off the left edge"), 1},
                                     std::tuple{3, 1, std::string("clipped\nat the corner"), 3},
                                     std::tuple{-2, -4, std::string("Wg"), 2}}) {
        INFO(text << " at " << x << ", " << y);
        const Image a = clipped(x, y, text, scale);
        CHECK(a.rgb == cropped(x, y, text, scale).rgb);
        CHECK(lit(a) > 0);
    }
    const Image far = clipped(1000, 1000, "far away", 1);
    CHECK(far.rgb == Image(8, 8).rgb);
    // A rectangle larger than the image darkens every pixel, and only by the factor.
    Image dark = clipped(-2, -4, "Wg", 2);
    const Image before = dark;
    darken_rect(dark, -5, -5, 100, 100, 0.5f);
    for (std::size_t i = 0; i < dark.rgb.size(); ++i) CHECK(dark.rgb[i] == before.rgb[i] * 0.5f);
}

TEST_CASE("bitmap font measures multi-line text", "[view][font]") {
    CHECK(BitmapFont::text_width("", 1) == 0);
    CHECK(BitmapFont::text_width("ab", 1) == 11);
    CHECK(BitmapFont::text_width("a\nabc", 2) == 34);
    CHECK(BitmapFont::text_height("a", 1) == 7);
    CHECK(BitmapFont::text_height("a\nb", 1) == 16);
}
