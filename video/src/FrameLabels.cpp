#include "lpv/video/FrameLabels.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>

namespace lpv::video {
namespace {

constexpr int kGlyphWidth = 5;
constexpr int kGlyphHeight = 7;
constexpr int kAdvance = kGlyphWidth + 1;
constexpr int kPadding = 2; // font pixels between the text and the edge of its box

struct Glyph {
    char c;
    std::array<const char*, kGlyphHeight> rows;
};

// Drawn as text so the shapes can be read and fixed here.
constexpr Glyph kFont[] = {
    {' ', {".....", ".....", ".....", ".....", ".....", ".....", "....."}},
    {'A', {".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
    {'B', {"####.", "#...#", "#...#", "####.", "#...#", "#...#", "####."}},
    {'C', {".###.", "#...#", "#....", "#....", "#....", "#...#", ".###."}},
    {'D', {"####.", "#...#", "#...#", "#...#", "#...#", "#...#", "####."}},
    {'E', {"#####", "#....", "#....", "####.", "#....", "#....", "#####"}},
    {'F', {"#####", "#....", "#....", "####.", "#....", "#....", "#...."}},
    {'G', {".###.", "#...#", "#....", "#.###", "#...#", "#...#", ".####"}},
    {'H', {"#...#", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
    {'I', {".###.", "..#..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'J', {"..###", "...#.", "...#.", "...#.", "...#.", "#..#.", ".##.."}},
    {'K', {"#...#", "#..#.", "#.#..", "##...", "#.#..", "#..#.", "#...#"}},
    {'L', {"#....", "#....", "#....", "#....", "#....", "#....", "#####"}},
    {'M', {"#...#", "##.##", "#.#.#", "#.#.#", "#...#", "#...#", "#...#"}},
    {'N', {"#...#", "#...#", "##..#", "#.#.#", "#..##", "#...#", "#...#"}},
    {'O', {".###.", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
    {'P', {"####.", "#...#", "#...#", "####.", "#....", "#....", "#...."}},
    {'Q', {".###.", "#...#", "#...#", "#...#", "#.#.#", "#..#.", ".##.#"}},
    {'R', {"####.", "#...#", "#...#", "####.", "#.#..", "#..#.", "#...#"}},
    {'S', {".####", "#....", "#....", ".###.", "....#", "....#", "####."}},
    {'T', {"#####", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."}},
    {'U', {"#...#", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
    {'V', {"#...#", "#...#", "#...#", "#...#", "#...#", ".#.#.", "..#.."}},
    {'W', {"#...#", "#...#", "#...#", "#.#.#", "#.#.#", "#.#.#", ".#.#."}},
    {'X', {"#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#"}},
    {'Y', {"#...#", "#...#", ".#.#.", "..#..", "..#..", "..#..", "..#.."}},
    {'Z', {"#####", "....#", "...#.", "..#..", ".#...", "#....", "#####"}},
    {'0', {".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."}},
    {'1', {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'2', {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"}},
    {'3', {"#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###."}},
    {'4', {"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."}},
    {'5', {"#####", "#....", "####.", "....#", "....#", "#...#", ".###."}},
    {'6', {"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."}},
    {'7', {"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."}},
    {'8', {".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."}},
    {'9', {".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."}},
    {'.', {".....", ".....", ".....", ".....", ".....", ".##..", ".##.."}},
    {',', {".....", ".....", ".....", ".....", ".##..", "..#..", ".#..."}},
    {'-', {".....", ".....", ".....", "#####", ".....", ".....", "....."}},
    {'+', {".....", "..#..", "..#..", "#####", "..#..", "..#..", "....."}},
    {'=', {".....", ".....", "#####", ".....", "#####", ".....", "....."}},
    {'_', {".....", ".....", ".....", ".....", ".....", ".....", "#####"}},
    {':', {".....", ".##..", ".##..", ".....", ".##..", ".##..", "....."}},
    {'/', {".....", "....#", "...#.", "..#..", ".#...", "#....", "....."}},
    {'(', {"...#.", "..#..", ".#...", ".#...", ".#...", "..#..", "...#."}},
    {')', {".#...", "..#..", "...#.", "...#.", "...#.", "..#..", ".#..."}},
    {'%', {"##...", "##..#", "...#.", "..#..", ".#...", "#..##", "...##"}},
    {'!', {"..#..", "..#..", "..#..", "..#..", "..#..", ".....", "..#.."}},
    {'?', {".###.", "#...#", "....#", "...#.", "..#..", ".....", "..#.."}},
    {'\'', {"..#..", "..#..", ".#...", ".....", ".....", ".....", "....."}},
    {'"', {".#.#.", ".#.#.", ".....", ".....", ".....", ".....", "....."}},
    {'#', {".#.#.", ".#.#.", "#####", ".#.#.", "#####", ".#.#.", ".#.#."}},
    {'<', {"...#.", "..#..", ".#...", "#....", ".#...", "..#..", "...#."}},
    {'>', {".#...", "..#..", "...#.", "....#", "...#.", "..#..", ".#..."}},
    {'*', {".....", "..#..", "#.#.#", ".###.", "#.#.#", "..#..", "....."}},
    {'^', {"..#..", ".#.#.", "#...#", ".....", ".....", ".....", "....."}},
};

const Glyph& glyphFor(char c) {
    const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    for (const Glyph& g : kFont)
        if (g.c == upper)
            return g;
    for (const Glyph& g : kFont)
        if (g.c == '?')
            return g;
    return kFont[0];
}

// Blends the grey `value` over the pixel with opacity `alpha` (0..255).
void blend(scene::Image8& image, int x, int y, std::uint8_t value, int alpha) {
    std::uint8_t* p =
        image.pixels.data() +
        (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x)) *
            static_cast<std::size_t>(image.channels);
    for (int c = 0; c < 3; ++c)
        p[c] = static_cast<std::uint8_t>((p[c] * (255 - alpha) + value * alpha + 127) / 255);
}

void fillRect(scene::Image8& image, int x0, int y0, int x1, int y1, std::uint8_t value, int alpha,
              int clipRight) {
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min({x1, image.width, clipRight});
    y1 = std::min(y1, image.height);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            blend(image, x, y, value, alpha);
}

} // namespace

int labelScale(int height) {
    return std::max(1, height / 180);
}

int labelWidth(std::string_view text, int scale) {
    return text.empty() ? 0 : (kAdvance * static_cast<int>(text.size()) - 1) * scale;
}

int labelHeight(int scale) {
    return kGlyphHeight * scale;
}

void drawLabel(scene::Image8& image, int x, int y, std::string_view text, int scale, int clipRight) {
    if (text.empty() || image.channels < 3)
        return;
    const int pad = kPadding * scale;
    // A translucent box keeps the text readable over bright and dark frames alike.
    fillRect(image, x, y, x + labelWidth(text, scale) + 2 * pad, y + labelHeight(scale) + 2 * pad, 0, 150,
             clipRight);
    for (std::size_t i = 0; i < text.size(); ++i) {
        const Glyph& g = glyphFor(text[i]);
        const int gx = x + pad + static_cast<int>(i) * kAdvance * scale;
        for (int row = 0; row < kGlyphHeight; ++row)
            for (int col = 0; col < kGlyphWidth; ++col)
                if (g.rows[static_cast<std::size_t>(row)][col] == '#')
                    fillRect(image, gx + col * scale, y + pad + row * scale, gx + (col + 1) * scale,
                             y + pad + (row + 1) * scale, 255, 255, clipRight);
    }
}

scene::Image8 sideBySide(const std::vector<std::uint8_t>& left, int leftWidth,
                         const std::vector<std::uint8_t>& right, int rightWidth, int height,
                         std::string_view leftLabel, std::string_view rightLabel) {
    scene::Image8 out;
    out.width = leftWidth + rightWidth;
    out.height = height;
    out.channels = 4;
    out.pixels.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(height) * 4u);
    const auto rowBytes = [](int w) { return static_cast<std::size_t>(w) * 4u; };
    for (int y = 0; y < height; ++y) {
        std::uint8_t* row = out.pixels.data() + static_cast<std::size_t>(y) * rowBytes(out.width);
        std::memcpy(row, left.data() + static_cast<std::size_t>(y) * rowBytes(leftWidth),
                    rowBytes(leftWidth));
        std::memcpy(row + rowBytes(leftWidth),
                    right.data() + static_cast<std::size_t>(y) * rowBytes(rightWidth), rowBytes(rightWidth));
    }
    fillRect(out, leftWidth - 1, 0, leftWidth + 1, height, 230, 255, out.width);
    const int scale = labelScale(height);
    const int margin = 2 * scale;
    drawLabel(out, margin, margin, leftLabel, scale, leftWidth - 1);
    drawLabel(out, leftWidth + 1 + margin, margin, rightLabel, scale, out.width);
    return out;
}

} // namespace lpv::video
