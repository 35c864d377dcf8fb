#pragma once
// Decodes every texture a scene's materials name, once each, into the
// scene::TextureImages the renderer uploads. Two derived images are stored
// under their own keys because they depend on how a material uses the file:
// - colour-keyed diffuse maps (4ds COLOR_KEY): `path + kColorKeySuffix`,
// - normal maps made from height/bump maps: `path + kHeightNormalSuffix`.
#include "lpv/importers/TextureBudget.h"
#include "lpv/scene/Image.h"
#include "lpv/scene/Scene.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lpv::importers {

// Keys of the derived images in scene::TextureImages (the renderer looks them up the same way).
using scene::kColorKeySuffix;
using scene::kHeightNormalSuffix;

struct SceneTextures {
    scene::TextureImages images;
    // One per texture that could not be read (it is drawn as a placeholder), naming the file.
    std::vector<std::string> warnings;
};

// Texture paths are relative to `projectDir` or absolute. Never fails: an
// unreadable file becomes the magenta/black placeholder plus a warning.
// The images together keep within `budget` (TextureBudget.h): over it, the
// largest are decoded at half size, or smaller, with a warning for each.
SceneTextures loadSceneTextures(const scene::Scene& scene, const std::filesystem::path& projectDir,
                                std::uint64_t budget = kSceneTextureBudgetBytes);

// How strongly height maps bend normals: a height step from 0 to 1 (black to
// white) across one texel tilts the normal as a slope of this many units.
// Bump maps carry no scale of their own (OBJ's -bm is rarely written); this
// value keeps Sponza's and Sibenik's relief visible without looking embossed.
inline constexpr float kHeightMapStrength = 8.0f;

// Tangent-space normal map from a height map (red channel, white = high),
// central differences with wrap-around (textures repeat). Rows top to bottom,
// v up (bottom-left UV origin): a height rising towards +u tilts the normal
// towards -u; rising towards the top of the image (+v) tilts it towards -v.
// Encoded as RGB = n * 0.5 + 0.5, alpha 255.
// Done here on the CPU, once per file at load (31 ms for 1024x1024 measured),
// rather than on the GPU: a pure function with its own unit test, and the
// result is an ordinary normal map, so shading has one normal-map path and
// mipmaps filter normals rather than heights.
scene::Image8 heightToNormalMap(const scene::Image8& height, float strength = kHeightMapStrength);

// The colour-key of a BMP file: its first palette entry (RGB) if it is
// palettised (8 bits or fewer per pixel), nothing otherwise (and for files
// that are not BMPs).
std::optional<std::array<std::uint8_t, 3>> bmpFirstPaletteColour(const std::filesystem::path& file);

// Alpha 0 wherever the pixel's RGB equals `key` exactly; those texels then
// take the colour of their visible neighbours (no key-coloured fringes when filtered).
void applyColorKey(scene::Image8& image, const std::array<std::uint8_t, 3>& key);

} // namespace lpv::importers
