#include "TextureResolver.h"

#include "lpv/importers/Importer.h"

#include <algorithm>
#include <system_error>

namespace lpv::importers {

namespace fs = std::filesystem;

std::string asciiLower(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z')
            c = static_cast<char>(c - 'A' + 'a');
    return out;
}

std::string_view textureFileName(std::string_view name) {
    const auto slash = name.find_last_of("/\\");
    return slash == std::string_view::npos ? name : name.substr(slash + 1);
}

std::vector<fs::path> textureFoldersFor(const fs::path& modelFile, const std::vector<fs::path>& searchPaths) {
    std::error_code ec;
    fs::path modelDir = fs::absolute(modelFile, ec).parent_path();
    if (ec)
        modelDir = modelFile.parent_path();
    std::vector<fs::path> folders = {modelDir / "maps", modelDir, modelDir.parent_path() / "maps"};
    for (const fs::path& p : searchPaths) {
        fs::path abs = fs::absolute(p, ec);
        if (ec)
            abs = p;
        folders.push_back(abs);
        folders.push_back(abs / "maps");
    }
    std::vector<fs::path> unique;
    for (fs::path& f : folders) {
        f = f.lexically_normal();
        if (std::find(unique.begin(), unique.end(), f) == unique.end())
            unique.push_back(f);
    }
    return unique;
}

scene::ReadRoots importReadRoots(const fs::path& file, const ImportOptions& options) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(file, ec);
    scene::ReadRoots roots;
    roots.add(ec ? file.parent_path() : absolute.parent_path());
    for (const fs::path& folder : textureFoldersFor(file, options.textureSearchPaths))
        roots.add(folder);
    for (const fs::path& folder : options.allowPaths)
        roots.add(folder);
    for (const fs::path& folder : scene::allowPathsFromEnvironment())
        roots.add(folder);
    return roots;
}

TextureResolver::TextureResolver(std::vector<fs::path> folders) : folders_(std::move(folders)) {}

const TextureResolver::Listing& TextureResolver::listing(const fs::path& folder) {
    if (auto it = listings_.find(folder); it != listings_.end())
        return it->second;
    Listing& list = listings_[folder];
    std::error_code ec;
    // Non-throwing iteration: an unreadable or missing folder is just empty.
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        std::error_code typeEc;
        if (!it->is_regular_file(typeEc))
            continue;
        list[asciiLower(it->path().filename().string())].push_back(it->path());
    }
    // Deterministic choice among names that differ only in case.
    for (auto& [key, paths] : list)
        std::sort(paths.begin(), paths.end());
    return list;
}

std::optional<fs::path> TextureResolver::findIn(const fs::path& folder, std::string_view fileName) {
    if (fileName.empty() || fileName == "." || fileName == "..")
        return std::nullopt;
    const Listing& list = listing(folder);
    const auto it = list.find(asciiLower(fileName));
    if (it == list.end())
        return std::nullopt;
    for (const fs::path& p : it->second)
        if (p.filename().string() == fileName)
            return p; // the exact spelling wins over a case-folded one
    return it->second.front();
}

std::optional<fs::path> TextureResolver::find(std::string_view name) {
    const std::string_view fileName = textureFileName(name);
    for (const fs::path& folder : folders_)
        if (auto found = findIn(folder, fileName))
            return found;
    return std::nullopt;
}

std::optional<fs::path> TextureResolver::findCompanion(const fs::path& texture, std::string_view suffix) {
    const std::string companion =
        texture.stem().string() + std::string(suffix) + texture.extension().string();
    return findIn(texture.parent_path(), companion);
}

} // namespace lpv::importers
