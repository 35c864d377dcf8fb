// libFuzzer target fuzz_obj: Wavefront OBJ + MTL through importScene
// (importers/src/Importer.cpp -> AssimpImporter.cpp: Assimp's OBJ and MTL
// parsers, our material, mesh, node, light and camera conversion and texture
// resolution (TextureResolver), then the common mesh clean-up and
// emissive-panel lights).
//
// The input is one OBJ and one MTL: the bytes up to the first "\n#mtl\n"
// (a comment line in both formats, so a seed still reads as an OBJ) become
// model/fuzz.obj, with "mtllib fuzz.mtl" put in front, and the bytes after it
// model/fuzz.mtl (empty when there is no separator). Both are written to a
// private work folder (WorkFolder.h) that holds:
//   model/maps/, maps/   small real files (the model's maps/ and the Mafia
//                        layout's ../maps), found case-insensitively;
//   outside/secret.png   a decoy that no import may reach.
// The import's extra texture search paths are the shared Sponza and Sibenik
// folders, so map_Kd names find real textures there through real,
// case-insensitive listings (10 of Sponza's names match only that way).
//
// Assimp is Debian's build, not instrumented: libFuzzer sees no coverage
// inside its parsers and AddressSanitizer catches its memory errors only at
// the intercepted calls (memcpy, strlen, ...); its crashes still count.
//
// A successful import must keep SceneChecks.h's promises and every texture it
// reports found must lie in a folder the import may read (checkTexturesInside;
// LPV_FUZZ_READ_ROOTS=off skips that check).
#include "SceneChecks.h"
#include "WorkFolder.h"

#include "lpv/importers/Importer.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kSeparator = "\n#mtl\n";
constexpr std::string_view kMtllib = "mtllib fuzz.mtl\n";

fs::path gObjFile;
fs::path gMtlFile;
lpv::importers::ImportOptions gOptions;
std::vector<fs::path> gReadRoots;
bool gCheckReadRoots = true;
std::string gObjText; // reused: one allocation for every input

fs::path sharedScenes() {
    const char* env = std::getenv("LPV_SHARED_SCENES_DIR");
    return env && *env ? fs::path(env) : fs::path(LPV_FUZZ_SHARED_SCENES_DIR);
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    const fs::path work = lpv::fuzz::makeWorkFolder("obj");
    const fs::path model = work / "model";
    std::error_code ec;
    for (const char* folder : {"model/maps", "maps", "outside"})
        fs::create_directories(work / folder, ec);
    lpv::fuzz::writeInput(model / "maps/Brick.png", "not decoded by the import");
    lpv::fuzz::writeInput(work / "maps/floor.bmp", "not decoded by the import");
    lpv::fuzz::writeInput(work / "outside/secret.png", "not decoded by the import");
    gObjFile = model / "fuzz.obj";
    gMtlFile = model / "fuzz.mtl";

    const fs::path shared = sharedScenes();
    for (const char* folder : {"sponza", "sibenik"}) {
        if (!fs::is_directory(shared / folder, ec))
            std::fprintf(stderr, "fuzz_obj: %s is missing; its textures will not be found\n",
                         (shared / folder).string().c_str());
        gOptions.textureSearchPaths.push_back(shared / folder);
    }
    gReadRoots = {model, work / "maps"};
    for (const fs::path& p : gOptions.textureSearchPaths)
        gReadRoots.push_back(p);
    if (const char* env = std::getenv("LPV_FUZZ_READ_ROOTS"); env && std::strcmp(env, "off") == 0)
        gCheckReadRoots = false;
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const std::size_t split = bytes.find(kSeparator);
    gObjText.assign(kMtllib);
    gObjText.append(bytes.substr(0, split));
    lpv::fuzz::writeInput(gObjFile, gObjText);
    lpv::fuzz::writeInput(gMtlFile, split == std::string_view::npos
                                        ? std::string_view()
                                        : bytes.substr(split + kSeparator.size()));
    const auto result = lpv::importers::importScene(gObjFile, gOptions);
    if (result) {
        lpv::fuzz::checkScene(result->scene, gObjFile.string());
        if (gCheckReadRoots)
            lpv::fuzz::checkTexturesInside(result->scene, gReadRoots);
    }
    return 0;
}
