#include "lpv/importers/Importer.h"

#include "TextEncoding.h"

#include "lpv/importers/AssimpImporter.h"
#include "lpv/importers/FourDsReader.h"
#include "lpv/importers/GltfImporter.h"
#include "lpv/importers/MeshCleanup.h"

#include "EmissiveLamps.h"
#include "lpv/scene/Project.h"
#include "lpv/scene/SceneScale.h"
#include "lpv/scene/ValueRepair.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace lpv::importers {

using scene::ErrorCode;
using scene::makeError;

namespace {

enum class Format { FourDs, Gltf, Assimp, Unknown };

std::string lowerExtension(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// Magic bytes decide where a format has them ("4DS\0" + version, "glTF"),
// the extension otherwise.
Format detectFormat(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::uint8_t head[8] = {};
    in.read(reinterpret_cast<char*>(head), sizeof head);
    const auto got = static_cast<std::size_t>(in.gcount());
    if (looksLikeFourDs({head, got}))
        return Format::FourDs;
    if (got >= 4 && std::string_view(reinterpret_cast<const char*>(head), 4) == "glTF")
        return Format::Gltf;
    const std::string ext = lowerExtension(file);
    if (ext == ".4ds")
        return Format::FourDs; // wrong magic or version: the reader says which
    if (ext == ".gltf" || ext == ".glb")
        return Format::Gltf;
    if (assimpReads(file))
        return Format::Assimp;
    return Format::Unknown;
}

scene::Expected<std::vector<std::uint8_t>> readAllBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary | std::ios::ate);
    if (!in)
        return makeError(ErrorCode::IoError, file.string(), "", "cannot open the file for reading");
    const std::streamoff size = in.tellg();
    if (size < 0)
        return makeError(ErrorCode::IoError, file.string(), "", "cannot tell the file's size");
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
    in.seekg(0);
    in.read(reinterpret_cast<char*>(bytes.data()), size);
    if (in.gcount() != size)
        return makeError(ErrorCode::IoError, file.string(), "", "the file could not be read completely");
    return bytes;
}

scene::Expected<ImportResult> readFormat(Format format, const std::filesystem::path& file,
                                         const ImportOptions& options) {
    switch (format) {
    case Format::FourDs: {
        auto bytes = readAllBytes(file);
        if (!bytes)
            return std::unexpected(bytes.error());
        return readFourDs(*bytes, file, options);
    }
    case Format::Gltf:
        return importGltf(file, options);
    case Format::Assimp:
        return importWithAssimp(file, options);
    case Format::Unknown:
        break;
    }
    return makeError(
        ErrorCode::UnknownFormat, file.string(), "",
        "no importer reads '" + lowerExtension(file) +
            "' files (4ds, glTF .gltf/.glb, and what Assimp reads: .obj, .3ds, .fbx, .dae, .ply, ...)");
}

// Colours below zero (a 4ds or MTL can store them) mean nothing to a
// renderer and the project format refuses them: they become 0, with a warning.
void clampNegativeColours(const std::filesystem::path& file, ImportResult& result) {
    for (scene::Material& m : result.scene.materials) {
        bool clamped = false;
        for (glm::vec3* colour : {&m.diffuseColor, &m.specularColor, &m.emissive}) {
            const glm::vec3 fixed = glm::max(*colour, glm::vec3(0.0f));
            clamped |= fixed != *colour;
            *colour = fixed;
        }
        if (clamped)
            result.warnings.push_back(file.string() + ": material '" + m.name +
                                      "' has negative colour components; they were set to 0");
    }
}

// Names that are not UTF-8 (an OBJ written by a Windows tool in its 8-bit
// code page) cannot go into the project's JSON: the whole save failed on one
// byte. They are read as Windows-1250 instead, with a warning.
void makeNamesUtf8(const std::filesystem::path& file, ImportResult& result) {
    std::size_t renamed = 0;
    const auto fix = [&](std::string& name) {
        if (auto utf8 = legacyNameToUtf8(name)) {
            name = std::move(*utf8);
            ++renamed;
        }
    };
    scene::Scene& s = result.scene;
    for (auto& o : s.objects)
        fix(o.name);
    for (auto& m : s.meshes)
        fix(m.name);
    for (auto& m : s.materials)
        fix(m.name);
    for (auto& l : s.lights)
        fix(l.name);
    for (auto& c : s.cameras)
        fix(c.name);
    for (auto& p : s.cameraPaths)
        fix(p.name);
    if (renamed > 0)
        result.warnings.push_back(file.string() + ": " + std::to_string(renamed) +
                                  " name(s) were not UTF-8 and were read as Windows-1250");
}

// Every importer's result gets the same repairs, each with a warning naming
// the file.
void repairImportedValues(const std::filesystem::path& file, ImportResult& result) {
    makeNamesUtf8(file, result);
    clampNegativeColours(file, result);
    // Values a project would refuse as products (ValueChecks.h) are repaired
    // here with a warning: a parallel up vector must not cost the whole file.
    for (const std::string& note : scene::repairSceneValues(result.scene))
        result.warnings.push_back(file.string() + ": " + note);
}

std::string factorText(double f) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", f);
    return text;
}

// The user's unit replaces the file's; the file's is read in; else metres.
AppliedScale chooseLengthScale(const ImportOptions& options, const ImportResult& result) {
    AppliedScale applied;
    if (options.metresPerUnit) {
        applied.factor = *options.metresPerUnit;
        applied.source =
            options.unitSource.empty() ? "--scale " + factorText(applied.factor) : options.unitSource;
        applied.knew = UnitKnowledge::GivenByUser;
    } else if (result.statedUnit) {
        applied.factor = result.statedUnit->metresPerUnit;
        applied.source = result.statedUnit->how;
        applied.knew = UnitKnowledge::StatedByFile;
    }
    return applied;
}

// Every length into metres before the clean-up and the repairs, so that
// they (and the emissive panels' notes in metres) see the scene as it stays.
void applyLengthScale(const ImportOptions& options, ImportResult& result) {
    const AppliedScale applied = chooseLengthScale(options, result);
    if (options.metresPerUnit && result.statedUnit &&
        std::abs(result.statedUnit->metresPerUnit - *options.metresPerUnit) > 1e-9 * *options.metresPerUnit)
        result.notes.push_back(applied.source + " replaces the unit the file states (" +
                               result.statedUnit->how + ")");
    scene::SceneScaleParts parts;
    // Clip planes are lengths of the file only where its reader set them.
    parts.cameraPlanes = result.cameraPlanesFromFile;
    scene::scaleSceneLengths(result.scene, applied.factor, parts);
    result.stats.lengthScale = applied;
}

} // namespace

void finishImport(const std::filesystem::path& file, ImportResult& result) {
    repairImportedValues(file, result);
    std::size_t repairedNormals = 0;
    for (scene::Mesh& mesh : result.scene.meshes) {
        const MeshCleanupStats s = cleanupMesh(mesh);
        result.stats.degenerateTrianglesDropped += s.degenerateTrianglesDropped;
        repairedNormals += s.invalidNormalsRepaired;
    }
    if (result.stats.degenerateTrianglesDropped > 0)
        result.warnings.push_back(file.string() + ": " +
                                  std::to_string(result.stats.degenerateTrianglesDropped) +
                                  " degenerate triangle(s) (zero area, repeated corners, or corners not "
                                  "finite or beyond +-1e18) dropped");
    if (repairedNormals > 0)
        result.warnings.push_back(file.string() + ": " + std::to_string(repairedNormals) +
                                  " invalid normal(s) (zero length or non-finite) recomputed");
    addAreaLightsForEmissivePanels(result.scene, result.notes);
    const RecentreStats recentred = recentreFarMeshes(result.scene);
    result.stats.meshesRecentred = recentred.meshes;
    if (recentred.meshes > 0)
        result.notes.push_back(std::to_string(recentred.meshes) +
                               (recentred.meshes == 1 ? " mesh" : " meshes") +
                               " far from the origin (up to " + factorText(recentred.farthest) +
                               " m) stored relative to " + (recentred.meshes == 1 ? "its" : "their") +
                               " centre, the offset moved into the objects' translations (float precision)");
    result.stats.objects = result.scene.objects.size();
    result.stats.triangles = result.scene.triangleCount();
    result.stats.materials = result.scene.materials.size();
}

scene::Expected<ImportResult> importScene(const std::filesystem::path& file, const ImportOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
        return makeError(ErrorCode::FileNotFound, file.string(), "", "no such file");
    auto result = readFormat(detectFormat(file), file, options);
    if (!result)
        return result;
    applyLengthScale(options, *result);
    finishImport(file, *result);
    if (auto note = sizeNote(result->scene.worldBounds(), result->stats.lengthScale.knew))
        result->notes.push_back(*note);
    // What a save would refuse (a number infinite as a float, an index out
    // of range) is reported now, against this file, not later against the
    // project the import writes.
    if (auto valid = scene::validateSceneContent(result->scene, file.string()); !valid) {
        scene::Error e = valid.error();
        e.location = "as imported: " + e.location;
        return std::unexpected(e);
    }
    result->stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace lpv::importers
