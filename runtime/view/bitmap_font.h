#pragma once
// A tiny 5x7 bitmap font (kdpm's own glyph table) for the viewer's on-screen text: stats and
// the help overlay, drawn straight into the displayed image. Covers printable ASCII; any other
// character is drawn as a hollow box.
#include <cstdint>
#include <string_view>

#include <glm/vec3.hpp>

#include "runtime/render/image.h"

namespace kdpm {

struct BitmapFont {
    static constexpr int kGlyphWidth = 5;
    static constexpr int kGlyphHeight = 7;
    static constexpr int kAdvance = 6;      // glyph plus one column of spacing
    static constexpr int kLineHeight = 9;   // glyph plus two rows of spacing

    // Row r (0 at the top) of the glyph for c; bit 4 is the leftmost column.
    static std::uint8_t row(char c, int r);
    static bool known(char c);
    // Size in pixels of `text` (lines split at '\n') drawn at `scale`.
    static int text_width(std::string_view text, int scale);
    static int text_height(std::string_view text, int scale);
};

// Draws `text` with its top-left corner at (x, y) into an RGB image (values in [0, 1]).
// Each glyph pixel becomes a scale x scale block; pixels outside the image are skipped.
// With a shadow, a dark copy offset by one block is drawn first so text reads on any background.
void draw_text(Image& image, int x, int y, std::string_view text, glm::vec3 color, int scale = 1,
               bool shadow = true);

// Darkens a rectangle (panel behind multi-line text); factor 0 is black, 1 unchanged.
void darken_rect(Image& image, int x, int y, int width, int height, float factor);

}  // namespace kdpm
