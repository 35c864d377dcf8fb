#pragma once
// Our own reader for Mafia (PC) .4ds models, format version 29 (0x1D).
//
// What arrives in the scene:
// - every frame becomes an Object (name, parent, transform), so the hierarchy
//   survives even where a frame's own data is skipped;
// - standard meshes (and the base mesh of billboards, morphs and skinned
//   meshes) become Meshes from their LOD 0, one Submesh per face group;
//   further LODs are read, validated and reported in a warning;
// - materials with colours, flags (two-sided, colour key, additive, opacity)
//   and texture paths resolved case-insensitively (see TextureResolver), with
//   the `<name>_ddn` normal and `<name>_spec` specular companions that sit
//   next to a diffuse map;
// - frame and visual types that carry no renderable geometry (glow, mirror,
//   sector, occluder, target, joint) are parsed past with a warning naming
//   the type and the frame; a type whose layout is unknown ends the frame list
//   with a warning, keeping what was read.
//
// Coordinates: see the comments at convertPosition() in FourDsReader.cpp;
// in short, X is negated (Mafia is left-handed, we are right-handed), the
// triangle winding is reversed to match, quaternions (stored w, x, y, z)
// become (w, x, -y, -z), and V = 1 - v (V measured up from the image's
// bottom row, the OBJ/OpenGL convention).
#include "lpv/importers/Importer.h"
#include "lpv/scene/Error.h"

#include <cstdint>
#include <filesystem>
#include <span>

namespace lpv::importers {

inline constexpr std::uint16_t kFourDsVersion = 29; // Mafia (PC)

// True for the "4DS\0" signature followed by version 29.
bool looksLikeFourDs(std::span<const std::uint8_t> bytes);

// Parses a whole .4ds file held in memory. `file` names the file in errors
// and warnings and locates the textures; it is not read. Errors carry the
// byte offset of the offending field ("byte offset N"). Never throws.
scene::Expected<ImportResult> readFourDs(std::span<const std::uint8_t> bytes,
                                         const std::filesystem::path& file, const ImportOptions& options);

} // namespace lpv::importers
