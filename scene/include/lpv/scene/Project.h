#pragma once
// Project format v1 (docs/project-format.md): `Name.lpvproj` (JSON) plus a
// `Name.assets/` folder holding meshes in the binary `.lpvmesh` form.
#include "lpv/scene/Error.h"
#include "lpv/scene/ParameterRegistry.h"
#include "lpv/scene/ProjectLock.h"
#include "lpv/scene/Scene.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lpv::scene {

inline constexpr const char* kProjectFormatName = "lpvstudio-project";
inline constexpr int kProjectFormatVersion = 2; // 2: area lights (1 is migrated on load)

// A named set of parameter values kept in the project, so settings can be
// compared (the editor's preset bar and A/B view) without losing the current
// ones. Like Project::parameters it holds overrides only; an absent key reads
// as its registry default.
struct ParameterPreset {
    std::string name; // non-empty and unique within a project
    ParameterSet parameters;

    bool operator==(const ParameterPreset&) const = default;
};

struct Project {
    std::string name;
    Scene scene;
    ParameterSet parameters;
    std::vector<ParameterPreset> presets; // in the order the user made them
    // Where the editor's view was when the project was last saved from it, so
    // that opening it again shows what the user left. Not one of the scene's
    // cameras: `lpv render` and the reference never use it.
    std::optional<Camera> editorView;
    // What loading changed and why, one line each (a texture reference that
    // leads out of the project's folder, see loadProject). Not saved, not
    // compared.
    std::vector<std::string> loadWarnings;

    bool operator==(const Project&) const;
};

// Loads and validates everything (JSON structure, ranges, finiteness,
// parameter keys, mesh assets with their checksums and indices). Never writes.
// A texture reference that resolves outside the project's folder,
// `allowPaths` and LPV_ALLOW_PATH (projectReadRoots) is kept as its last
// path component only, with a warning in loadWarnings: a project someone
// sends you cannot make the renderer read, or a save copy, "/etc/shadow".
Expected<Project> loadProject(const std::filesystem::path& file,
                              const std::vector<std::filesystem::path>& allowPaths = {});

// The checks a save makes (meshes, finite numbers, ranges, indices) on a
// scene that came from elsewhere, with errors naming `source` (an imported
// file) and the place as it would be stored ("objects[0].translation[0]"),
// so an importer can report a bad value against its input rather than
// against the project it would write.
// The scene is moved into a project for the check and back, not copied
// (meshes are megabytes); it is unchanged afterwards.
Expected<void> validateSceneContent(Scene& scene, const std::string& source);

// Writes the assets then the JSON, each to a temporary file in the same
// folder that is flushed and renamed over the target: a failed save leaves
// the previous project intact. A project file the loader would refuse (over
// its size limit, more than kMaxMaterials) is refused before anything is
// written. The writes and the clean-up happen under the project's lock
// (ProjectLock), so concurrent saves follow one another.
struct SaveOptions {
    // Remove texture copies no material names any more (removeOrphanTextures).
    // The editor turns it off while its undo history could bring a removed
    // texture back.
    bool collectOrphanTextures = true;
    // The project file as the caller found it when its work began
    // (projectFileIdentity before loading it; absent for a new project).
    // When set, a save finds it changed refuses with projectChangedError
    // rather than replace another process's work.
    std::optional<ProjectFileIdentity> unchangedSince;
    std::string operation = "save"; // what that error says ran: "import", "path import"
    // A lock the caller already holds on this project (it also spans the
    // texture copies of an import); without one, the save takes the lock
    // itself, waiting up to lockWait.
    const ProjectLock* heldLock = nullptr;
    std::chrono::milliseconds lockWait = kProjectLockWait;
};
Expected<void> saveProject(const Project& project, const std::filesystem::path& file,
                           const SaveOptions& options = {});

// Atomic write of one file (temp file, flush, fsync, rename).
Expected<void> writeFileAtomically(const std::filesystem::path& file, std::string_view bytes);

// Pushes a file another library wrote (and may not have checked) to the
// disk; the error carries the system's reason. For writers that cannot give
// their bytes to writeFileAtomically.
Expected<void> syncFileToDisk(const std::filesystem::path& file);

} // namespace lpv::scene
