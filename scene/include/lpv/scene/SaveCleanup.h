#pragma once
// Saves that clean up after themselves and after the saves before them
// (issue #29): a killed save leaves its temporary file behind, a failed or
// killed import its texture copies, an edit the copies no material uses any
// more. Everything here removes only files with the names LPV Studio gives
// them, in the folders a project owns; never anything else
// (docs/project-format.md, "Saving").
#include "lpv/scene/Scene.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lpv::scene {

// `<folder>/<stem>.assets` for `<folder>/<stem>.lpvproj`: the folder the project owns.
std::filesystem::path assetsFolderOf(const std::filesystem::path& projectFile);

// The parts of a name writeFileAtomically gives its temporary files,
// `<base>.tmp-<pid>-<counter>`; nullopt for any other name.
struct TemporaryName {
    std::string base; // the target's file name
    long long pid = 0;
};
std::optional<TemporaryName> parseTemporaryName(std::string_view fileName);

// Removes the temporary files in `folder` whose base `ours` accepts and
// whose save can no longer finish: no process has their pid, or (Linux) the
// process that has it now started after the file was last written, so the
// pid was reused. This process's own are kept (another thread may be saving).
// Only regular files. Returns how many were removed.
std::size_t removeStaleTemporaries(const std::filesystem::path& folder,
                                   const std::function<bool(std::string_view base)>& ours);
// The same for the temporary files of the one target `file`.
std::size_t removeStaleTemporaries(const std::filesystem::path& file);

// `<16 lower-case hex digits>-<name>`, as copyTexturesIntoProject names a
// copy, and not a temporary file's name.
bool isTextureCopyName(std::string_view fileName);

// Removes texture copies from `<stem>.assets/textures/` that no texture slot
// of `scene` (the scene just saved to `projectFile`) names. Conservative: a
// copy stays while any slot, in any folder, ends in its file name (compared
// without case, for file systems that ignore it). Returns how many were removed.
std::size_t removeOrphanTextures(const Scene& scene, const std::filesystem::path& projectFile);

// Undoes a save that writes several files in several steps (texture copies,
// a radiosity solution, then the project file) when a later step fails: what
// it created goes again, what existed before stays. A file it replaced is not
// restored (each is written atomically, so it is the old or the new one).
class SaveRollback {
public:
    // Before writing `file`: undo() removes it if it does not exist now,
    // and then the folders above it that do not exist now, once empty.
    void willWrite(const std::filesystem::path& file);
    // Before a call that copies textures into `folder` (copyTexturesIntoProject):
    // undo() removes the texture copies that were not there at this call.
    void watchTextureCopies(const std::filesystem::path& folder);
    // Removes what was recorded; safe to call more than once.
    void undo();

private:
    void noteMissingFolders(std::filesystem::path folder);

    std::vector<std::filesystem::path> newFiles_;
    std::vector<std::filesystem::path> newFolders_;
    std::vector<std::pair<std::filesystem::path, std::set<std::string>>> watched_; // folder, names before
};

} // namespace lpv::scene
