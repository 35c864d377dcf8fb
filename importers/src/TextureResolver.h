#pragma once
// Finds the texture files a model names, the way Windows would: model
// formats from Windows games store names in any case ("SIBENIK_KAMEN.BMP")
// while the files on disk may be lower case, so every lookup here is
// case-insensitive (ASCII letters) on every platform.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lpv::importers {

class TextureResolver {
  public:
    // Folders are searched in the order given; missing ones are ignored.
    explicit TextureResolver(std::vector<std::filesystem::path> folders);

    // The absolute path of the file `name` names. Only the last component of
    // the name counts ('/' and '\\' both separate): a model cannot point
    // outside the search folders with "..\\..\\secret".
    std::optional<std::filesystem::path> find(std::string_view name);

    // `<stem><suffix><ext>` in the folder of `texture` (an absolute path that
    // find() returned), e.g. suffix "_ddn" for the normal map next to a
    // diffuse map.
    std::optional<std::filesystem::path> findCompanion(const std::filesystem::path& texture,
                                                       std::string_view suffix);

    const std::vector<std::filesystem::path>& folders() const { return folders_; }

  private:
    // Lower-case file name -> the files with that name (several when names
    // differ only in case), listed once per folder.
    using Listing = std::map<std::string, std::vector<std::filesystem::path>>;

    const Listing& listing(const std::filesystem::path& folder);
    std::optional<std::filesystem::path> findIn(const std::filesystem::path& folder,
                                                std::string_view fileName);

    std::vector<std::filesystem::path> folders_;
    std::map<std::filesystem::path, Listing> listings_;
};

// The folders searched for a model's textures, in order: `<model dir>/maps`,
// the model's folder, `<model dir>/../maps` (Mafia keeps models/ and maps/
// side by side), then every options folder and its maps/ subfolder.
std::vector<std::filesystem::path> textureFoldersFor(const std::filesystem::path& modelFile,
                                                     const std::vector<std::filesystem::path>& searchPaths);

// The last path component of a name stored in a model file.
std::string_view textureFileName(std::string_view name);

std::string asciiLower(std::string_view s);

} // namespace lpv::importers
