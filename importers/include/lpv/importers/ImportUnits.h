#pragma once
// Units at import (issue #41, docs/importers.md "Units (issue #41)"): the
// scale an import applies to reach metres, the note when a scene's size
// suggests another unit, and meshes far from their origin recentred.
#include "lpv/scene/Scene.h"

#include <optional>
#include <string>
#include <string_view>

namespace lpv::importers {

// Metres per unit of a name `lpv import --unit` takes (mm, cm, m, in, ft);
// nothing for any other name.
std::optional<double> metresPerUnit(std::string_view name);
// "mm, cm, m, in, ft", for messages.
const char* unitNames();

// The unit a file states: glTF and Mafia 4ds are in metres by their specs,
// FBX says how many centimetres its unit is (GlobalSettings UnitScaleFactor),
// Collada names its unit in metres (<unit meter=...>, which Assimp applies).
struct StatedUnit {
    double metresPerUnit = 1.0; // what the import multiplies the file's lengths by
    std::string how;            // "the file's UnitScaleFactor 1 (centimetres)"
};

// Where an import's unit came from: nowhere (metres assumed), the file, the user.
enum class UnitKnowledge { Assumed, StatedByFile, GivenByUser };

// What an import made of its lengths, for its printed line.
struct AppliedScale {
    double factor = 1.0; // metres per unit of the file
    std::string source;  // "--unit cm", "--scale 0.5", a StatedUnit's `how`, or empty (metres assumed)
    UnitKnowledge knew = UnitKnowledge::Assumed;
};

// The note when the imported part's size suggests that its unit is not the
// one the import assumed, or nothing. `bounds` are in metres after the scale.
// A unit the file states is believed unless the size is absurd; the user's
// is never questioned.
std::optional<std::string> sizeNote(const scene::Bounds& bounds, UnitKnowledge knew);

// Meshes whose vertices sit far from their own origin compared with their
// size (a scene 100 km from the world origin) get vertices relative to their
// bounding-box centre c, and every object that draws them gets c moved into
// its translation (T' = T + R*S*c; its children get T - c), so every world
// position stays where it was within float rounding while the vertices keep
// their precision. An object's LOD meshes move with its main mesh (by the
// same c, taken over all of them) or not at all; a mesh shared by several
// objects moves once. Meshes no object uses are left alone.
struct RecentreStats {
    std::size_t meshes = 0; // meshes moved
    double farthest = 0.0;  // the largest |c| among them
};
RecentreStats recentreFarMeshes(scene::Scene& s);

} // namespace lpv::importers
