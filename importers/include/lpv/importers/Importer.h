#pragma once
// One interface for every scene format: a file in, a scene::Scene or an error
// out. The format is chosen by content (magic bytes) first, extension second.
#include "lpv/importers/ImportUnits.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/ReadRoots.h"
#include "lpv/scene/Scene.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lpv::importers {

using ImportError = scene::Error;

struct ImportOptions {
    // Extra folders searched for textures after the model's own folder and its maps/ folder.
    std::vector<std::filesystem::path> textureSearchPaths;
    // Folders outside those that the scene may still name files in (textures,
    // glTF buffers): `lpv import --allow-path DIR`. See importReadRoots.
    std::vector<std::filesystem::path> allowPaths;
    // Metres per unit of the file (`lpv import --unit/--scale`), replacing
    // the unit the file states. Unset: the unit the file states
    // (ImportResult::statedUnit), else metres (docs/importers.md, "Units").
    std::optional<double> metresPerUnit;
    // How the user gave it, for the printed line: "--unit cm", "--scale 0.5".
    std::string unitSource;
};

// The folders an import of `file` may read from (docs/importers.md, "What a
// scene may read"): the scene file's folder, the texture folders searched for
// it (textureFoldersFor: its maps/, the Mafia layout's ../maps, each
// --texture-path and its maps/), `options.allowPaths` and LPV_ALLOW_PATH.
// A reference that resolves anywhere else (an absolute system path, a "../"
// or "%2e%2e/" escape, a symbolic link out) becomes a missing texture with a
// warning that names it, or an error for a glTF buffer.
scene::ReadRoots importReadRoots(const std::filesystem::path& file, const ImportOptions& options);

struct ImportStats {
    std::size_t objects = 0;
    std::size_t triangles = 0;
    std::size_t materials = 0;
    std::size_t texturesFound = 0;
    std::size_t texturesMissing = 0;
    std::size_t degenerateTrianglesDropped = 0;
    double seconds = 0.0; // wall time of importScene
    // What every length of the file was multiplied by to reach metres, and why.
    AppliedScale lengthScale;
    // Meshes far from their origin recentred (recentreFarMeshes).
    std::size_t meshesRecentred = 0;
};

struct ImportResult {
    scene::Scene scene;
    // Non-fatal problems, each naming the file and what was skipped or replaced.
    std::vector<std::string> warnings;
    // What the import made of the file beyond its meshes, e.g. an emissive
    // panel that became an area light (one line each, for the user).
    std::vector<std::string> notes;
    ImportStats stats;
    // The unit the file states, set by its reader (glTF and 4ds: metres; FBX
    // UnitScaleFactor; Collada <unit>); unset when the format states none.
    std::optional<StatedUnit> statedUnit;
    // The cameras' near/far planes come from the file (glTF) and scale with
    // it; otherwise they are the Camera defaults, already in metres.
    bool cameraPlanesFromFile = false;
};

// Reads the file with the importer its content (or extension) calls for,
// multiplies its lengths into metres (options.metresPerUnit, else the unit
// the file states: scene::scaleSceneLengths), then cleans every mesh
// (cleanupMesh: weld, degenerate triangles, normals, tangents) and adds a
// note when the scene's size suggests another unit (sizeNote). Texture
// paths in the result are absolute where the file was found and may be read
// (importReadRoots), else the stored name's last component (counted and
// warned about): never a path that leads elsewhere.
scene::Expected<ImportResult> importScene(const std::filesystem::path& file,
                                          const ImportOptions& options = {});

// What importScene does to every importer's result after reading it, each
// step with a warning naming `file`: names that are not UTF-8 read as
// Windows-1250, negative colours set to 0, values a project would refuse as
// products repaired (ValueRepair.h), every mesh cleaned (cleanupMesh),
// emissive panels made area lights, meshes far from their origin recentred
// (recentreFarMeshes), the counts filled in. For callers of one
// importer's reader (the fuzz targets).
void finishImport(const std::filesystem::path& file, ImportResult& result);

} // namespace lpv::importers
