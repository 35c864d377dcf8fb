#include "lpv/scene/ProjectTextures.h"

#include "FileText.h"

#include "lpv/scene/MeshAsset.h"
#include "lpv/scene/Project.h"

#include <map>

namespace lpv::scene {
namespace {

namespace fs = std::filesystem;

using detail::fromUtf8;
using detail::hex16;
using detail::readFileBytes;
using detail::utf8;

// Absolute path of a slot's file: absolute as stored, else relative to the project's folder.
fs::path locate(const std::string& slot, const fs::path& projectFolder) {
    const fs::path p = fromUtf8(slot);
    return p.is_absolute() ? p : projectFolder / p;
}

} // namespace

std::vector<std::string*> textureSlots(Material& m) {
    return {&m.diffuseTexture,          &m.normalTexture,    &m.heightTexture,   &m.specularTexture,
            &m.metallicRoughnessTexture, &m.occlusionTexture, &m.emissiveTexture, &m.alphaTexture,
            &m.environmentTexture};
}

std::vector<const std::string*> textureSlots(const Material& m) {
    std::vector<const std::string*> out;
    for (std::string* s : textureSlots(const_cast<Material&>(m)))
        out.push_back(s);
    return out;
}

Expected<TextureCopyStats> copyTexturesIntoProject(Scene& scene, const fs::path& projectFile) {
    const fs::path projectFolder = projectFile.parent_path().empty() ? fs::path(".") : projectFile.parent_path();
    const std::string relativeFolder = utf8(projectFile.stem()) + ".assets/textures/";
    const fs::path textureFolder = projectFolder / fromUtf8(relativeFolder);
    const fs::path canonicalAssets = fs::weakly_canonical(textureFolder);

    TextureCopyStats stats;
    std::map<fs::path, std::string> copiedAs;      // source file -> relative path in the project
    std::map<std::uint64_t, std::string> storedAs; // content hash -> relative path in the project
    Scene updated = scene;                     // the caller's scene changes only on success
    for (Material& m : updated.materials) {
        for (std::string* slot : textureSlots(m)) {
            if (slot->empty())
                continue;
            const fs::path source = fs::weakly_canonical(locate(*slot, projectFolder));
            if (source.parent_path() == canonicalAssets)
                continue; // already the project's own
            if (const auto known = copiedAs.find(source); known != copiedAs.end()) {
                *slot = known->second;
                continue;
            }
            std::error_code ec;
            if (!fs::is_regular_file(source, ec)) {
                ++stats.missing;
                stats.missingNames.push_back(*slot);
                continue;
            }
            const auto bytes = readFileBytes(source);
            if (!bytes)
                return std::unexpected(bytes.error());
            // One copy per content: the first name it was met under is kept.
            const std::uint64_t hash = contentHash64(*bytes);
            const auto [stored, isNew] =
                storedAs.try_emplace(hash, relativeFolder + hex16(hash) + "-" + utf8(source.filename()));
            const std::string& relative = stored->second;
            const fs::path target = projectFolder / fromUtf8(relative);
            if (!isNew || fs::is_regular_file(target, ec)) {
                ++stats.alreadyThere;
            } else {
                fs::create_directories(textureFolder, ec);
                if (ec)
                    return makeError(ErrorCode::IoError, textureFolder.string(), "",
                                     "cannot create the texture folder: " + ec.message());
                if (auto written = writeFileAtomically(target, *bytes); !written)
                    return std::unexpected(written.error());
                ++stats.copied;
            }
            copiedAs.emplace(source, relative);
            *slot = relative;
        }
    }
    scene = std::move(updated);
    return stats;
}

} // namespace lpv::scene
