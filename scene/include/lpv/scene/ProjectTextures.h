#pragma once
// Textures travel with the project: importers return absolute paths to the
// files they found (beside the model, in a maps/ folder, in a search path);
// before a project is saved they are copied into `<Name>.assets/textures/`
// and the materials point there, relative to the project file, so the
// project opens on another machine without the source folders.
#include "lpv/scene/Error.h"
#include "lpv/scene/Material.h"
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
// stored once, whatever their names) and rewrites the slot to that relative
// path. References to files that do not exist stay as they are. Errors only
// for I/O failures; the scene is unchanged then.
Expected<TextureCopyStats> copyTexturesIntoProject(Scene& scene, const std::filesystem::path& projectFile);

} // namespace lpv::scene
