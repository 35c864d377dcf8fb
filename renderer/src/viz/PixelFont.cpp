// A 3x5 pixel font, so that images written by `lpv dump` carry their legend
// numbers and labels without a font library (the editor shows the same images).
#include "lpv/renderer/viz/SliceImage.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace lpv::renderer::viz {

namespace {

struct Glyph {
    char c;
    const char* rows; // 5 rows of 3 columns (15 characters), '#' = lit
};

constexpr Glyph kGlyphs[] = {
    {'A', ".#.#.#####.##.#"}, {'B', "##.#.###.#.###."}, {'C', ".###..#..#...##"}, {'D', "##.#.##.##.###."},
    {'E', "####..##.#..###"}, {'F', "####..##.#..#.."}, {'G', ".###..#.##.#.##"}, {'H', "#.##.#####.##.#"},
    {'I', "###.#..#..#.###"}, {'J', "..#..#..##.#.#."}, {'K', "#.##.###.#.##.#"}, {'L', "#..#..#..#..###"},
    {'M', "#.########.##.#"}, {'N', "##.#.##.##.##.#"}, {'O', ".#.#.##.##.#.#."}, {'P', "##.#.###.#..#.."},
    {'Q', ".#.#.##.###..##"}, {'R', "##.#.###.#.##.#"}, {'S', ".###...#...###."}, {'T', "###.#..#..#..#."},
    {'U', "#.##.##.##.####"}, {'V', "#.##.##.##.#.#."}, {'W', "#.##.########.#"}, {'X', "#.##.#.#.#.##.#"},
    {'Y', "#.##.#.#..#..#."}, {'Z', "###..#.#.#..###"}, {'0', "####.##.##.####"}, {'1', ".#.##..#..#.###"},
    {'2', "##...#.#.#..###"}, {'3', "##...#.#...###."}, {'4', "#.##.####..#..#"}, {'5', "####..##...###."},
    {'6', ".###..####.####"}, {'7', "###..#.#..#..#."}, {'8', "####.#####.####"}, {'9', "####.####..###."},
    {'.', ".............#."}, {'-', "......###......"}, {'+', "....#.###.#...."}, {'=', "...###...###..."},
    {':', "....#.....#...."}, {'/', "..#..#.#.#..#.."}, {'(', ".#.#..#..#...#."}, {')', ".#...#..#..#.#."},
    {'^', ".#.#.#........."}, {'_', "............###"}, {',', "..........#.#.."}, {'%', "#....#.#.#....#"},
};

bool lit(const char* rows, int x, int y) {
    return rows[y * 3 + x] == '#';
}

const char* glyphRows(char c) {
    const char upper = char(std::toupper(static_cast<unsigned char>(c)));
    for (const Glyph& g : kGlyphs)
        if (g.c == upper)
            return g.rows;
    return nullptr; // space and anything unknown: blank
}

} // namespace

int textWidth(const std::string& text, int scale) {
    return text.empty() ? 0 : int(text.size()) * 4 * scale - scale;
}

void drawText(scene::Image8& image, int x, int y, const std::string& text, int scale,
              const glm::vec3& colour) {
    // Rounded, as the slice's own pixels are: a colour reads back as the bytes it names.
    auto byte = [](float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
    const std::uint8_t rgb[3] = {byte(colour.r), byte(colour.g), byte(colour.b)};
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char* rows = glyphRows(text[i]);
        if (!rows)
            continue;
        const int left = x + int(i) * 4 * scale;
        for (int gy = 0; gy < 5; ++gy)
            for (int gx = 0; gx < 3; ++gx) {
                if (!lit(rows, gx, gy))
                    continue;
                for (int sy = 0; sy < scale; ++sy)
                    for (int sx = 0; sx < scale; ++sx) {
                        const int px = left + gx * scale + sx, py = y + gy * scale + sy;
                        if (px < 0 || py < 0 || px >= image.width || py >= image.height)
                            continue;
                        std::uint8_t* p =
                            &image.pixels[(std::size_t(py) * std::size_t(image.width) + std::size_t(px)) * 4];
                        p[0] = rgb[0];
                        p[1] = rgb[1];
                        p[2] = rgb[2];
                        p[3] = 255;
                    }
            }
    }
}

} // namespace lpv::renderer::viz
