#pragma once
// Composition of side-by-side frames and their labels: a built-in 5x7
// bitmap font (upper-case letters, digits and common punctuation; lower case
// is drawn as upper case, anything else as '?'), white on a translucent black
// box, so no font library or file is needed.
#include "lpv/scene/Image.h"

#include <cstdint>
#include <string_view>
#include <vector>

namespace lpv::video {

// Size in pixels of one font pixel for a frame `height` pixels tall:
// height / 180, at least 1 (1 below 360 rows, 4 at 720p, 6 at 1080p).
int labelScale(int height);

// Width and height in pixels of `text` drawn at `scale`, without the box.
int labelWidth(std::string_view text, int scale);
int labelHeight(int scale);

// Draws `text` with its box's top-left corner at (x, y) into an RGBA image,
// clipped to the image and, horizontally, to [x, clipRight).
void drawLabel(scene::Image8& image, int x, int y, std::string_view text, int scale, int clipRight);

// One RGBA frame from two renders of the same height (rows top to bottom):
// `left` fills [0, leftWidth), `right` the rest, a 2-pixel light divider
// between them, each labelled at its top-left corner (no box when the label
// is empty).
scene::Image8 sideBySide(const std::vector<std::uint8_t>& left, int leftWidth,
                         const std::vector<std::uint8_t>& right, int rightWidth, int height,
                         std::string_view leftLabel, std::string_view rightLabel);

} // namespace lpv::video
