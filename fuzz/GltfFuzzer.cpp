// libFuzzer target fuzz_gltf: glTF 2.0 through our importer, importScene
// (importers/src/Importer.cpp -> GltfImporter.cpp: tinygltf with our file
// callbacks, accessors, materials, the node graph, lights and cameras, then
// the common mesh clean-up and emissive-panel lights).
//
// Each input is written to a private work folder (WorkFolder.h) as
// model/fuzz.glb when it starts with the binary container's "glTF" magic,
// else as model/fuzz.gltf, and imported from there, so buffer and image
// uris resolve through the importer's real path handling against real
// files. The work folder holds:
//   model/     the input, and copies of every buffer and image of the shared
//              glTF scenes (Box0.bin, CesiumLogoFlat.png, cornellBox.bin, ...),
//              flattened, so the shared .gltf files work as seeds unchanged;
//   outside/   decoys (secret.png, secret.bin) that no import may reach:
//              "../outside/secret.png" or an absolute uri naming them is an
//              escape from the folders the import may read;
//   cache/     LPV_CACHE_DIR, where embedded images (data: uris, .glb buffer
//              views) are stored; emptied after every input.
//
// A successful import must keep SceneChecks.h's promises, and every texture
// it reports found must lie in model/, model/maps/, maps/ (the Mafia layout's
// ../maps) or cache/ (checkTexturesInside; LPV_FUZZ_READ_ROOTS=off skips
// that check, e.g. to fuzz on while an escape is being fixed).
#include "SceneChecks.h"
#include "WorkFolder.h"

#include "lpv/importers/Importer.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string_view>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Folders under the shared scenes whose buffers and images the seeds name.
constexpr const char* kCompanionFolders[] = {
    "gltf-small/Box/glTF",
    "gltf-small/BoxTextured/glTF",
    "gltf-small/NormalTangentMirrorTest/glTF",
    "gltf-small/AlphaBlendModeTest/glTF",
    "cornell/gltf",
};

fs::path gWork;
fs::path gModelFolder;
fs::path gCacheFolder;
std::vector<fs::path> gReadRoots;
bool gCheckReadRoots = true;

fs::path sharedScenes() {
    const char* env = std::getenv("LPV_SHARED_SCENES_DIR");
    return env && *env ? fs::path(env) : fs::path(LPV_FUZZ_SHARED_SCENES_DIR);
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    gWork = lpv::fuzz::makeWorkFolder("gltf");
    gModelFolder = gWork / "model";
    gCacheFolder = gWork / "cache";
    std::error_code ec;
    fs::create_directories(gModelFolder / "maps", ec);
    fs::create_directories(gWork / "maps", ec);
    fs::create_directories(gWork / "outside", ec);

    const fs::path shared = sharedScenes();
    std::size_t companions = 0;
    for (const char* folder : kCompanionFolders)
        for (const fs::directory_entry& entry : fs::directory_iterator(shared / folder, ec))
            if (entry.is_regular_file() && entry.path().extension() != ".gltf" &&
                entry.path().extension() != ".txt") {
                lpv::fuzz::copyInto("gltf", entry.path(), gModelFolder / entry.path().filename());
                ++companions;
            }
    if (companions == 0)
        std::fprintf(stderr, "fuzz_gltf: no buffers or images found under %s; uris will find nothing\n",
                     shared.string().c_str());
    // Real files, so an escape that reaches them is a found texture (or a buffer that loads).
    lpv::fuzz::writeInput(gWork / "outside/secret.png", "\x89PNG\r\n\x1a\n not really");
    if (fs::exists(gModelFolder / "Box0.bin"))
        lpv::fuzz::copyInto("gltf", gModelFolder / "Box0.bin", gWork / "outside/secret.bin");
    lpv::fuzz::writeInput(gModelFolder / "maps/inside.png", "\x89PNG\r\n\x1a\n not really");

    if (setenv("LPV_CACHE_DIR", gCacheFolder.c_str(), 1) != 0)
        lpv::fuzz::setUpFailed("gltf", "cannot set LPV_CACHE_DIR");
    gReadRoots = {gModelFolder, gWork / "maps", gCacheFolder};
    if (const char* env = std::getenv("LPV_FUZZ_READ_ROOTS"); env && std::strcmp(env, "off") == 0)
        gCheckReadRoots = false;
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const fs::path file = gModelFolder / (bytes.starts_with("glTF") ? "fuzz.glb" : "fuzz.gltf");
    lpv::fuzz::writeInput(file, bytes);
    const auto result = lpv::importers::importScene(file);
    if (result) {
        lpv::fuzz::checkScene(result->scene, file.string());
        if (gCheckReadRoots)
            lpv::fuzz::checkTexturesInside(result->scene, gReadRoots);
    }
    std::error_code ignored;
    fs::remove_all(gCacheFolder, ignored);
    return 0;
}
