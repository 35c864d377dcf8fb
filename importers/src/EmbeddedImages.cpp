#include "EmbeddedImages.h"

#include "lpv/scene/MeshAsset.h"
#include "lpv/scene/Project.h"

#include <cstdlib>
#include <cstdio>
#include <string_view>

namespace lpv::importers {

namespace fs = std::filesystem;

namespace {

fs::path fromEnvironment(const char* name) {
    const char* value = std::getenv(name);
    return value && *value ? fs::path(value) : fs::path();
}

std::string extensionFor(std::span<const std::uint8_t> bytes, const std::string& mimeType) {
    if (mimeType == "image/png")
        return ".png";
    if (mimeType == "image/jpeg")
        return ".jpg";
    if (mimeType == "image/bmp")
        return ".bmp";
    if (mimeType == "image/vnd-ms.dds" || mimeType == "image/vnd.ms-dds")
        return ".dds";
    const std::string_view head(reinterpret_cast<const char*>(bytes.data()), std::min<std::size_t>(bytes.size(), 4));
    if (head.starts_with("\x89PNG"))
        return ".png";
    if (head.starts_with("\xFF\xD8"))
        return ".jpg";
    if (head.starts_with("BM"))
        return ".bmp";
    if (head.starts_with("DDS "))
        return ".dds";
    return ".bin"; // OpenImageIO still sniffs the content when it is read
}

} // namespace

fs::path embeddedImageFolder() {
    if (fs::path p = fromEnvironment("LPV_CACHE_DIR"); !p.empty())
        return p / "embedded-images";
    if (fs::path p = fromEnvironment("XDG_CACHE_HOME"); !p.empty())
        return p / "lpvstudio/embedded-images";
    if (fs::path p = fromEnvironment("HOME"); !p.empty())
        return p / ".cache/lpvstudio/embedded-images";
    return fs::temp_directory_path() / "lpvstudio-cache/embedded-images";
}

scene::Expected<fs::path> storeEmbeddedImage(std::span<const std::uint8_t> bytes, const std::string& mimeType) {
    const std::string_view content(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    char name[32];
    std::snprintf(name, sizeof name, "%016llx", static_cast<unsigned long long>(scene::contentHash64(content)));
    const fs::path folder = embeddedImageFolder();
    const fs::path file = folder / (std::string(name) + extensionFor(bytes, mimeType));
    std::error_code ec;
    if (fs::is_regular_file(file, ec) && fs::file_size(file, ec) == bytes.size())
        return file;
    fs::create_directories(folder, ec);
    if (ec)
        return scene::makeError(scene::ErrorCode::IoError, folder.string(), "",
                                "cannot create the folder for embedded images: " + ec.message());
    if (auto written = scene::writeFileAtomically(file, content); !written)
        return std::unexpected(written.error());
    return file;
}

} // namespace lpv::importers
