#pragma once
#include <array>
#include <cstdint>
#include <string_view>

#include "engine/eval/rgb_image.h"

namespace hdprior {

// A 5 x 7 pixel font for figure labels (two more rows below the baseline for g j p q y ,): digits,
// both cases of A-Z and the punctuation of axis titles (space . , - + ( ) / : = % _ ?). Other
// characters draw as '?'.
constexpr int kGlyphWidth = 5, kGlyphAdvance = 6;  // one blank column between glyphs
constexpr int kGlyphCapHeight = 7, kGlyphHeight = 9;  // above the baseline; with the descender rows

// The glyph's rows, top first; bit 4 is the leftmost column.
const std::array<uint8_t, kGlyphHeight>& glyph(char c);

// Pixel size of `text` drawn with every font pixel a scale x scale square.
int textWidth(std::string_view text, int scale);
inline int textHeight(int scale) { return kGlyphHeight * scale; }
inline int capHeight(int scale) { return kGlyphCapHeight * scale; }

enum class TextDirection { Horizontal, Upwards };  // Upwards: rotated 90 degrees anticlockwise, for y axis titles

// Draws `text` with its top-left corner at (x, y) (Upwards: its bottom-left corner, reading upwards).
void drawText(RgbImage& image, int x, int y, std::string_view text, int scale, Rgb colour,
              TextDirection direction = TextDirection::Horizontal);

}  // namespace hdprior
