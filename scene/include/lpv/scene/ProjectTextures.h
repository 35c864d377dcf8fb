#pragma once
// Textures travel with the project: importers return absolute paths to the
// files they found (beside the model, in a maps/ folder, in a search path);
// before a project is saved they are copied into `<Name>.assets/textures/`
// and the materials point there, relative to the project file, so the
// project opens on another machine without the source folders.
#include "lpv/scene/Error.h"
#include "lpv/scene/Material.h"
#include "lpv/scene/ReadRoots.h"
#include "lpv/scene/Scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lpv::scene {

struct TextureCopyStats {
    std::size_t copied = 0;        // files written into the project
    std::size_t alreadyThere = 0;  // identical file already in the project
    std::size_t missing = 0;       // references to files that do not exist (drawn as a placeholder)
    std::vector<std::string> missingNames;
};

// Every texture slot of a material, in a fixed order.
std::vector<std::string*> textureSlots(Material& m);
std::vector<const std::string*> textureSlots(const Material& m);

// Copies each texture that lies outside the project's assets folder to
// `<stem>.assets/textures/<content hash>-<file name>` (identical files are
// stored once, whatever their names; a name too long for the file system is
// shortened and keeps its extension, the hash keeps it unique) and rewrites
// the slot to that relative path, with the source's permissions but never
// wider than rw-r--r--. References to files that do not exist, and relative
// references that lead out of the project's folder ("../../x"), are not
// copied and count as missing. Absolute slots are trusted: they come from
// an importer or from loadProject, which both keep references inside the
// folders they may read (ReadRoots). Errors only for I/O failures; the scene
// is unchanged then.
Expected<TextureCopyStats> copyTexturesIntoProject(Scene& scene, const std::filesystem::path& projectFile);

// Keeps every texture reference of `scene` (stored relative to
// `projectFile`'s folder or absolute) inside `roots`: one that resolves
// elsewhere (after "..", symbolic links) becomes its last path component,
// which names nothing outside the project, and gets a warning line naming
// the material, the reference and the folders. Returns the warnings.
std::vector<std::string> keepTexturesInside(Scene& scene, const ReadRoots& roots,
                                            const std::filesystem::path& projectFile);

// `<16 hex digits>-<name>` for a texture copy, at most 200 bytes (file
// systems hold 255, and the atomic write's temporary name adds a suffix): a
// longer name keeps its extension and as much of its start as fits (cut at
// a UTF-8 character boundary).
std::string textureCopyName(std::uint64_t contentHash, const std::string& fileName);

} // namespace lpv::scene
