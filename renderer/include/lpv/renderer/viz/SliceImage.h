#pragma once
// The LPV slice viewer's image, in plain C++ (no GL, no Qt): the editor's
// Visualizers dock and `lpv dump` both call these two functions, so the CLI
// writes exactly the picture the editor shows.
//
// extractSlice reads one slice of a volume (an LPV cascade's SH per colour
// channel, the geometry volume, or a heat map) as numbers; renderSlice turns
// those numbers into an RGBA image, magnified, in false colour or true
// colour, linear or logarithmic, with a legend strip underneath.
#include "lpv/scene/Error.h"
#include "lpv/scene/Image.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lpv::renderer::viz {

// Slice axis, and the in-plane axes the image shows (u to the right, v up):
// X: (z, y), Y: (x, z), Z: (x, y).
enum class Axis { X, Y, Z };
enum class Quantity {
    Band0,       // the DC coefficient Y00 (for a heat map: its value)
    Coefficient, // one of the four SH coefficients, signed
    Directional, // light: irradiance (W/m^2) on a surface facing `direction`, as shading reads it;
                 // geometry volume: the fraction of light travelling along `direction` it blocks
};
enum class Channel { Red, Green, Blue, Luminance, Rgb };
enum class Scale { Linear, Log };

struct SliceSpec {
    Axis axis = Axis::Z;
    int index = 0;
    Quantity quantity = Quantity::Band0;
    int coefficient = 0; // 0..3 (Y00, Y1-1, Y10, Y11) for Quantity::Coefficient
    glm::vec3 direction{0.0f, 1.0f, 0.0f};
    Channel channel = Channel::Luminance;
};

// A cubic volume as the slice reads it: per cell one vec4 (SH, or a value in
// .x) per colour channel; colourless volumes (the GV) set only channels[0].
// Cell (x, y, z) is at x + n (y + n z).
struct VolumeView {
    int size = 0;
    float cellSize = 1.0f;
    std::array<const std::vector<glm::vec4>*, 3> channels{};

    bool coloured() const { return channels[1] && channels[2]; }
};

// width x height cells, 1 component (a channel or luminance) or 3 (rgb).
struct SliceField {
    int width = 0;
    int height = 0;
    int components = 1;
    bool isSigned = false;     // a coefficient: negative values are meaningful
    std::vector<float> values; // rows bottom to top (v = 0 first), `components` per cell

    float at(int u, int v, int component = 0) const {
        return values[(std::size_t(v) * std::size_t(width) + std::size_t(u)) * std::size_t(components) +
                      std::size_t(component)];
    }
};

// Errors name the field that is out of range (slice index, coefficient, an empty volume).
scene::Expected<SliceField> extractSlice(const VolumeView& volume, const SliceSpec& spec);

struct ColourSpec {
    Scale scale = Scale::Linear;
    bool falseColour = true; // ignored for Channel::Rgb (true colour)
    int pixelsPerCell = 8;
    int logDecades = 4; // log scale spans max / 10^decades .. max
    // The top of the colour range; nullopt: the slice's largest magnitude.
    // A fixed value keeps colours comparable while stepping through propagation.
    std::optional<float> rangeMax;
    std::string title; // printed in the legend, e.g. "cascade 0  z = 12  band 0"
};

// The range a rendered slice used (for legends drawn outside the image).
struct SliceRange {
    float low = 0.0f;
    float high = 0.0f;
};

// Where a slice lies in the world, so that its picture says so (issue #46):
// the world coordinates of its edges on both in-plane axes, a scale bar in
// scene units, the plane's own coordinate, and the outline of the geometry
// that crosses the plane.
struct SliceGuides {
    Axis axis = Axis::Z;
    glm::vec2 origin{0.0f}; // world (u, v) of the slice's lower-left corner (cell (0, 0)'s corner)
    float plane = 0.0f;     // world coordinate of the slice plane along `axis`
    float cellSize = 1.0f;  // world units per cell of the field
    // Per cell of the field (rows bottom to top), 1 where geometry crosses
    // the plane; its boundary is drawn over the slice. Empty: no outline.
    std::vector<std::uint8_t> geometry;
};

// The in-plane axes (u, v) of a slice across `axis`: 0 = x, 1 = y, 2 = z.
glm::ivec2 inPlaneAxes(Axis axis);
// The scale bar's length for a slice `worldWidth` wide: the largest of 1, 2,
// 5 x 10^k at most a third of it, so it reads the same in any unit.
float scaleBarLength(float worldWidth);

// Colours of what renderSlice draws besides the slice and ramp (tests find them by colour).
inline constexpr glm::vec3 kCaptionColour{0.85f};            // the title under the legend
inline constexpr glm::vec3 kAxisLabelColour{0.7f};           // world coordinates beside the slice
inline constexpr glm::vec3 kScaleBarColour{1.0f};            // the scale bar
inline constexpr glm::vec3 kOutlineColour{0.0f, 1.0f, 1.0f}; // the geometry's outline (cyan)

// The slice magnified by pixelsPerCell (v up) at the image's top-left, then
// (with `guides`) the world coordinates of its edges beside and under it, a
// scale bar and the plane's coordinate, and the geometry's outline over it;
// then a legend strip: the colour ramp with its low, middle and high values,
// and the title, wrapped onto as many lines as it needs, all inside the image.
scene::Image8 renderSlice(const SliceField& field, const ColourSpec& colour, SliceRange* usedRange = nullptr,
                          const SliceGuides* guides = nullptr);

// The false-colour ramp at t in 0..1 (dark purple to yellow), and the
// diverging one for signed values at t in -1..1 (blue, white, red).
glm::vec3 falseColour(float t);
glm::vec3 divergingColour(float t);

// Text for legends and labels in a 3x5 pixel font (digits, A-Z, . - + = : / ( ) ^ _ , %), scaled.
void drawText(scene::Image8& image, int x, int y, const std::string& text, int scale,
              const glm::vec3& colour = glm::vec3(1.0f));
int textWidth(const std::string& text, int scale);

} // namespace lpv::renderer::viz
