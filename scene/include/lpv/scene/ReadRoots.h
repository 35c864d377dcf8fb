#pragma once
// What an import or a project may read (issue #29, docs/importers.md "What a
// scene may read"). A scene file someone sends you must not pull private
// files into a project you then share: every file a scene or project names
// is read only when, after resolving "..", percent-encoding (the glTF
// importer decodes first) and symbolic links, it is a regular file inside
// one of these folders. Anything else becomes a missing texture (placeholder)
// or an error, with a message that names the reference and the reason.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lpv::scene {

class ReadRoots {
  public:
    ReadRoots() = default;
    explicit ReadRoots(const std::vector<std::filesystem::path>& folders);

    // Adds a folder (made absolute and canonical where it exists; a folder
    // that does not exist yet is kept as written, normalised).
    void add(const std::filesystem::path& folder);

    // Why `file` may not be read, or nothing when it may: "lies outside the
    // folders it may be read from (...)" or notARegularFile's reasons for
    // the file it resolves to (a folder, a FIFO, a device, no such file).
    // Never throws.
    std::optional<std::string> refusal(const std::filesystem::path& file) const;

    // True when `file` resolves to a place inside one of the folders
    // (whether or not it exists).
    bool contains(const std::filesystem::path& file) const;

    const std::vector<std::filesystem::path>& folders() const { return folders_; }
    // The folders for a message: "/a, /b" ("none" when there are none).
    std::string describe() const;

  private:
    std::vector<std::filesystem::path> folders_;
};

// `LPV_ALLOW_PATH`: folders (separated by ':') every import and project may
// also read from, for a studio whose projects share a texture library; the
// command-line `--allow-path DIR` adds to it per run.
std::vector<std::filesystem::path> allowPathsFromEnvironment();

// The folders a project file may name its textures in: its own folder (which
// holds `<stem>.assets/`), then `allowPaths` and LPV_ALLOW_PATH.
ReadRoots projectReadRoots(const std::filesystem::path& projectFile,
                           const std::vector<std::filesystem::path>& allowPaths = {});

} // namespace lpv::scene
