#include "lpv/importers/Importer.h"

#include "lpv/importers/GltfImporter.h"

#include <algorithm>
#include <cctype>
#include <fstream>

namespace lpv::importers {

using scene::ErrorCode;
using scene::makeError;

namespace {

std::string lowerExtension(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// The first bytes decide where they are unambiguous ("glTF" binary header), the extension otherwise.
std::string sniff(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    if (in.gcount() == 4 && std::string_view(magic, 4) == "glTF")
        return ".glb";
    return lowerExtension(file);
}

} // namespace

scene::Expected<ImportResult> importScene(const std::filesystem::path& file, const ImportOptions& options) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
        return makeError(ErrorCode::FileNotFound, file.string(), "", "no such file");
    const std::string kind = sniff(file);
    if (kind == ".gltf" || kind == ".glb")
        return importGltf(file, options);
    return makeError(ErrorCode::UnknownFormat, file.string(), "",
                     "no importer for '" + lowerExtension(file) + "' files in this build (glTF: .gltf, .glb)");
}

} // namespace lpv::importers
