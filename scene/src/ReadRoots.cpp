#include "lpv/scene/ReadRoots.h"

#include "lpv/scene/FileRead.h"

#include <algorithm>
#include <cstdlib>
#include <string_view>
#include <system_error>

namespace lpv::scene {

namespace fs = std::filesystem;

namespace {

// Absolute, with symbolic links and ".." resolved as far as the path exists
// (weakly_canonical), lexically normalised beyond; nothing when the system
// cannot resolve it (a name too long, a loop of links).
std::optional<fs::path> resolved(const fs::path& p) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(p, ec);
    if (ec)
        return std::nullopt;
    fs::path canonical = fs::weakly_canonical(absolute, ec);
    if (ec)
        return std::nullopt;
    return canonical.lexically_normal();
}

bool isInside(const fs::path& file, const fs::path& folder) {
    auto f = file.begin();
    for (auto d = folder.begin(); d != folder.end(); ++d, ++f) {
        if (d->empty() && std::next(d) == folder.end())
            return true; // a trailing separator ends the folder
        if (f == file.end() || *f != *d)
            return false;
    }
    return true;
}

} // namespace

ReadRoots::ReadRoots(const std::vector<fs::path>& folders) {
    for (const fs::path& f : folders)
        add(f);
}

void ReadRoots::add(const fs::path& folder) {
    fs::path root = resolved(folder).value_or(folder.lexically_normal());
    if (std::find(folders_.begin(), folders_.end(), root) == folders_.end())
        folders_.push_back(std::move(root));
}

std::string ReadRoots::describe() const {
    std::string out;
    for (const fs::path& f : folders_)
        out += (out.empty() ? "" : ", ") + f.string();
    return out.empty() ? "none" : out;
}

bool ReadRoots::contains(const fs::path& file) const {
    const auto path = resolved(file);
    return path && std::any_of(folders_.begin(), folders_.end(),
                               [&](const fs::path& root) { return isInside(*path, root); });
}

std::optional<std::string> ReadRoots::refusal(const fs::path& file) const {
    const auto path = resolved(file);
    if (!path) {
        // The system's own word (a name too long, a loop of links).
        if (auto why = notARegularFile(file))
            return why;
        return std::string("cannot be resolved to a file");
    }
    if (!std::any_of(folders_.begin(), folders_.end(), [&](const fs::path& root) { return isInside(*path, root); }))
        return "lies outside the folders it may be read from (" + describe() +
               "; --allow-path DIR or LPV_ALLOW_PATH widens them)";
    return notARegularFile(*path);
}

std::vector<fs::path> allowPathsFromEnvironment() {
    std::vector<fs::path> out;
    const char* value = std::getenv("LPV_ALLOW_PATH");
    if (!value)
        return out;
    std::string_view rest(value);
    while (!rest.empty()) {
        const std::size_t colon = rest.find(':');
        const std::string_view part = rest.substr(0, colon);
        if (!part.empty())
            out.emplace_back(std::string(part));
        if (colon == std::string_view::npos)
            break;
        rest.remove_prefix(colon + 1);
    }
    return out;
}

ReadRoots projectReadRoots(const fs::path& projectFile, const std::vector<fs::path>& allowPaths) {
    ReadRoots roots;
    std::error_code ec;
    const fs::path absolute = fs::absolute(projectFile, ec);
    roots.add(ec ? projectFile.parent_path() : absolute.parent_path());
    for (const fs::path& p : allowPaths)
        roots.add(p);
    for (const fs::path& p : allowPathsFromEnvironment())
        roots.add(p);
    return roots;
}

} // namespace lpv::scene
