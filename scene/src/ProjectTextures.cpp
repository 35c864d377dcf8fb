#include "lpv/scene/ProjectTextures.h"

#include "FileText.h"

#include "lpv/scene/MeshAsset.h"
#include "lpv/scene/Project.h"

#include <map>
#include <system_error>

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

// rw-r--r--: a copy never becomes executable or writable by others.
constexpr fs::perms kWidestCopyPerms = fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                                       fs::perms::others_read;

// Most file systems hold names of up to 255 bytes (ext4, XFS, btrfs); the
// atomic write's temporary file adds ".tmp-<pid>-<n>" to the name, so copies
// keep well below.
constexpr std::size_t kMaxFileNameBytes = 200;

// The length of the longest prefix of `s` of at most `bytes` bytes that ends
// on a UTF-8 character boundary.
std::size_t utf8PrefixLength(const std::string& s, std::size_t bytes) {
    if (bytes >= s.size())
        return s.size();
    while (bytes > 0 && (static_cast<unsigned char>(s[bytes]) & 0xC0) == 0x80)
        --bytes; // s[bytes] continues a character: cut before it
    return bytes;
}

} // namespace

std::string textureCopyName(std::uint64_t contentHash, const std::string& fileName) {
    const std::string prefix = hex16(contentHash) + "-";
    if (prefix.size() + fileName.size() <= kMaxFileNameBytes)
        return prefix + fileName;
    std::string extension = utf8(fromUtf8(fileName).extension());
    if (extension.size() > 16)
        extension.clear(); // not an extension worth keeping
    const std::size_t room = kMaxFileNameBytes - prefix.size() - extension.size();
    return prefix + fileName.substr(0, utf8PrefixLength(fileName, room)) + extension;
}

std::vector<std::string> keepTexturesInside(Scene& scene, const ReadRoots& roots, const fs::path& projectFile) {
    const fs::path projectFolder = projectFile.parent_path().empty() ? fs::path(".") : projectFile.parent_path();
    std::vector<std::string> warnings;
    for (Material& m : scene.materials)
        for (std::string* slot : textureSlots(m)) {
            if (slot->empty() || roots.contains(locate(*slot, projectFolder)))
                continue;
            const std::string kept = utf8(fromUtf8(*slot).filename());
            warnings.push_back("material '" + capErrorText(m.name) + "': texture '" + capErrorText(*slot) +
                               "' lies outside the folders the project may read from (" + roots.describe() +
                               "; --allow-path DIR or LPV_ALLOW_PATH widens them): not read, kept as '" +
                               capErrorText(kept) + "' (placeholder)");
            *slot = kept;
        }
    return warnings;
}

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
    const ReadRoots projectFolderOnly({projectFolder});

    TextureCopyStats stats;
    std::map<fs::path, std::string> copiedAs;      // source file -> relative path in the project
    std::map<std::uint64_t, std::string> storedAs; // content hash -> relative path in the project
    Scene updated = scene;                     // the caller's scene changes only on success
    for (Material& m : updated.materials) {
        for (std::string* slot : textureSlots(m)) {
            if (slot->empty())
                continue;
            const fs::path located = locate(*slot, projectFolder);
            std::error_code ec;
            const fs::path source = fs::weakly_canonical(located, ec);
            if (ec || (!fromUtf8(*slot).is_absolute() && !projectFolderOnly.contains(located))) {
                // "../../etc/passwd" stored relative: not the project's to copy.
                ++stats.missing;
                stats.missingNames.push_back(*slot);
                continue;
            }
            if (source.parent_path() == canonicalAssets)
                continue; // already the project's own
            if (const auto known = copiedAs.find(source); known != copiedAs.end()) {
                *slot = known->second;
                continue;
            }
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
                storedAs.try_emplace(hash, relativeFolder + textureCopyName(hash, utf8(source.filename())));
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
                // A private source (rw-r-----) stays private in the project.
                const fs::perms sourcePerms = fs::status(source, ec).permissions();
                if (!ec)
                    fs::permissions(target, sourcePerms & kWidestCopyPerms, ec);
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
