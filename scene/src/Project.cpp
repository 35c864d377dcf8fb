// Loading and saving projects (docs/project-format.md): `Name.lpvproj` plus
// the mesh assets in `Name.assets/meshes/`.
#include "lpv/scene/Project.h"

#include "FileText.h"
#include "ProjectJson.h"
#include "lpv/scene/MeshAsset.h"
#include "lpv/scene/ProjectLimits.h"
#include "lpv/scene/ProjectTextures.h"
#include "lpv/scene/ReadRoots.h"
#include "lpv/scene/SaveCleanup.h"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

namespace lpv::scene {
namespace {

namespace fs = std::filesystem;
using detail::Json;

using detail::fromUtf8;
using detail::hex16;
using detail::readFileBytes;
using detail::utf8;

std::string meshLocation(std::size_t i) { return "meshes[" + std::to_string(i) + "]"; }

// The counts the project file records bound the asset's size (all four
// vertex streams, indices, at most one submesh per triangle, its name): a
// larger file is refused before it is read, and saveProject refuses to write
// one (a mesh name over 1 MiB).
detail::ReadLimit meshAssetLimit(std::uint64_t vertices, std::uint64_t triangles) {
    constexpr std::uint64_t kCountLimit = std::uint64_t{1} << 40; // no overflow below
    const std::uint64_t bound = std::min(vertices, kCountLimit) * 48 + std::min(triangles, kCountLimit) * 24 +
                                kMeshAssetHeaderSize + (std::uint64_t{1} << 20);
    return {bound, "mesh asset of " + std::to_string(vertices) + " vertices and " + std::to_string(triangles) +
                       " triangles"};
}

Expected<Mesh> loadMesh(const fs::path& projectFile, const detail::MeshReference& ref, std::size_t i,
                        std::size_t materialCount) {
    const std::string where = projectFile.string();
    // checkAssetPath has already confined ref.asset to the project's folder.
    const fs::path assetFile = projectFile.parent_path() / fromUtf8(ref.asset);
    const auto bytes = readFileBytes(assetFile, meshAssetLimit(ref.vertices, ref.triangles));
    if (!bytes && bytes.error().code == ErrorCode::FileNotFound)
        return makeError(ErrorCode::MissingAsset, where, meshLocation(i) + ".asset",
                         "mesh asset \"" + ref.asset + "\" does not exist (looked for " + assetFile.string() + ")");
    if (!bytes)
        return std::unexpected(bytes.error());
    auto mesh = decodeMeshAsset(*bytes, assetFile.string(), materialCount);
    if (!mesh)
        return mesh;
    // A mismatch means the asset is not the one this project file was saved with.
    if (mesh->positions.size() != ref.vertices || mesh->triangleCount() != ref.triangles)
        return makeError(ErrorCode::CorruptAsset, where, meshLocation(i),
                         "the project records " + std::to_string(ref.vertices) + " vertices and " +
                             std::to_string(ref.triangles) + " triangles, but " + ref.asset + " holds " +
                             std::to_string(mesh->positions.size()) + " and " +
                             std::to_string(mesh->triangleCount()));
    // The project file's name wins: it is the one a user edits.
    mesh->name = ref.name;
    return mesh;
}

// Where mesh i goes, relative to the project's folder. The name carries a
// checksum of the asset's bytes, so a save never overwrites a file the
// previous project file refers to (unless with identical bytes): renaming
// the new project file over the old one is the single moment the saved
// project changes, and a save that fails before it changes nothing.
std::string assetPathFor(const fs::path& projectFile, std::size_t i, std::string_view bytes) {
    return utf8(projectFile.stem()) + ".assets/meshes/" + std::to_string(i) + "-" + hex16(contentHash64(bytes)) +
           ".lpvmesh";
}

bool hasContent(const fs::path& path, std::string_view bytes) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec) || fs::file_size(path, ec) != bytes.size() || ec)
        return false;
    const auto existing = readFileBytes(path);
    return existing && *existing == bytes;
}

// Undoes the files and folders a failed save created; what existed before is untouched.
struct CreatedPaths {
    std::vector<fs::path> files;
    std::vector<fs::path> folders; // innermost first

    void remove() const {
        std::error_code ignored;
        for (const fs::path& f : files)
            fs::remove(f, ignored);
        for (const fs::path& d : folders)
            fs::remove(d, ignored); // only if empty
    }
};

// After a successful save: assets the new project file no longer refers to
// are deleted. The project owns its `<stem>.assets/meshes` folder.
void removeUnreferencedAssets(const fs::path& meshFolder, const std::set<std::string>& referenced) {
    std::error_code ec;
    std::vector<fs::path> stale;
    for (fs::directory_iterator it(meshFolder, ec), end; !ec && it != end; it.increment(ec))
        if (it->path().extension() == ".lpvmesh" && it->is_regular_file(ec) &&
            !referenced.contains(utf8(it->path().filename())))
            stale.push_back(it->path());
    for (const fs::path& p : stale)
        fs::remove(p, ec);
}

// Everything a save could object to, found before anything is written:
// meshes (stream sizes, finite values, indices), the document as the loader
// will read it back, and the limits the loader applies (ProjectLimits.h).
Expected<std::string> buildDocument(const Project& project, const fs::path& file,
                                    const std::vector<std::string>& assetPaths) {
    const std::string where = file.string();
    if (auto fits = checkMaterialCount(project.scene.materials.size(), where, "materials"); !fits)
        return std::unexpected(fits.error());
    for (std::size_t i = 0; i < project.scene.meshes.size(); ++i)
        if (auto valid = validateMesh(project.scene.meshes[i], where, meshLocation(i), project.scene.materials.size());
            !valid)
            return std::unexpected(valid.error());
    const Json document = detail::projectToJson(project, assetPaths);
    if (auto valid = detail::projectFromJson(document, where); !valid)
        return std::unexpected(valid.error());
    try {
        std::string text = document.dump(2) + "\n";
        if (auto fits = checkWriteFits(text.size(), detail::kProjectFileLimit, where); !fits)
            return std::unexpected(fits.error());
        return text;
    } catch (const Json::exception& e) {
        // nlohmann refuses strings that are not UTF-8 (e.g. names from an old 8-bit file).
        return makeError(ErrorCode::InvalidValue, where, "", std::string("cannot write the project: ") + e.what());
    }
}

} // namespace

bool Project::operator==(const Project& other) const {
    return name == other.name && scene == other.scene && parameters == other.parameters &&
           presets == other.presets && editorView == other.editorView;
}

Expected<Project> loadProject(const fs::path& file, const std::vector<fs::path>& allowPaths) {
    const std::string where = file.string();
    const auto text = readFileBytes(file, detail::kProjectFileLimit);
    if (!text)
        return std::unexpected(text.error());
    const auto json = detail::parseProjectText(*text, where);
    if (!json)
        return std::unexpected(json.error());
    auto document = detail::projectFromJson(*json, where);
    if (!document)
        return std::unexpected(document.error());

    Project project = std::move(document->project);
    if (auto fits = checkMaterialCount(project.scene.materials.size(), where, "materials"); !fits)
        return std::unexpected(fits.error());
    const std::size_t materialCount = project.scene.materials.size();
    project.scene.meshes.reserve(document->meshes.size());
    for (std::size_t i = 0; i < document->meshes.size(); ++i) {
        auto mesh = loadMesh(file, document->meshes[i], i, materialCount);
        if (!mesh)
            return std::unexpected(mesh.error());
        project.scene.meshes.push_back(std::move(*mesh));
    }
    project.loadWarnings = keepTexturesInside(project.scene, projectReadRoots(file, allowPaths), file);
    return project;
}

Expected<void> validateSceneContent(Scene& scene, const std::string& source) {
    Project project;
    project.name = "import";
    project.scene = std::move(scene);
    // Placeholder asset names: only the content is checked here.
    const std::vector<std::string> assetPaths(project.scene.meshes.size(), "import.assets/meshes/mesh.lpvmesh");
    auto built = buildDocument(project, source, assetPaths);
    scene = std::move(project.scene);
    if (!built)
        return std::unexpected(built.error());
    return {};
}

Expected<void> saveProject(const Project& project, const fs::path& file, const SaveOptions& options) {
    const std::string where = file.string();
    if (file.filename().empty() || file.stem().empty())
        return makeError(ErrorCode::InvalidValue, where, "", "not a project file name");

    std::vector<std::string> assets;
    std::vector<std::string> assetPaths;
    for (std::size_t i = 0; i < project.scene.meshes.size(); ++i) {
        const Mesh& mesh = project.scene.meshes[i];
        assets.push_back(encodeMeshAsset(mesh));
        if (auto fits = checkWriteFits(assets.back().size(),
                                       meshAssetLimit(mesh.positions.size(), mesh.triangleCount()), where);
            !fits) {
            fits.error().location = meshLocation(i);
            return fits;
        }
        assetPaths.push_back(assetPathFor(file, i, assets.back()));
    }
    const auto text = buildDocument(project, file, assetPaths);
    if (!text)
        return std::unexpected(text.error());

    // From here to the clean-up no other save of this project runs: its
    // clean-up would delete the assets this project file names, ours those
    // of its project file.
    std::optional<ProjectLock> ownLock;
    if (!options.heldLock) {
        auto lock = ProjectLock::acquire(file, options.lockWait);
        if (!lock)
            return std::unexpected(lock.error());
        ownLock.emplace(std::move(*lock));
    }
    if (options.unchangedSince && projectFileIdentity(file) != *options.unchangedSince)
        return std::unexpected(projectChangedError(file, options.operation));

    const fs::path folder = file.parent_path();
    const fs::path assetFolder = folder / fromUtf8(utf8(file.stem()) + ".assets");
    const fs::path meshFolder = assetFolder / "meshes";
    // Temporary files of saves that were killed (never this one's, nor one
    // still running): first, so on a full disk their space is free again.
    const std::string projectName = utf8(file.filename());
    removeStaleTemporaries(folder.empty() ? fs::path(".") : folder,
                           [&](std::string_view base) { return base == projectName; });
    removeStaleTemporaries(meshFolder, [](std::string_view base) { return base.ends_with(".lpvmesh"); });
    removeStaleTemporaries(assetFolder / "textures", isTextureCopyName);

    CreatedPaths created;
    std::error_code ec;
    if (!fs::exists(meshFolder, ec))
        created.folders.push_back(meshFolder);
    if (!fs::exists(assetFolder, ec))
        created.folders.push_back(assetFolder);

    std::set<std::string> referenced;
    for (std::size_t i = 0; i < assets.size(); ++i) {
        const fs::path target = folder / fromUtf8(assetPaths[i]);
        referenced.insert(utf8(target.filename()));
        if (hasContent(target, assets[i]))
            continue; // an unchanged mesh keeps its file
        const bool existed = fs::exists(target, ec);
        if (auto written = detail::writeFileAtomicallyFolderUnsynced(target, assets[i]); !written) {
            created.remove();
            return written;
        }
        if (!existed)
            created.files.push_back(target);
    }
    // The assets' renames are durable before the project file that names them.
    if (!assets.empty())
        detail::syncFolderToDisk(meshFolder);
    if (auto written = writeFileAtomically(file, *text); !written) {
        created.remove();
        return written;
    }
    removeUnreferencedAssets(meshFolder, referenced);
    if (options.collectOrphanTextures)
        removeOrphanTextures(project.scene, file);
    return {};
}

} // namespace lpv::scene
