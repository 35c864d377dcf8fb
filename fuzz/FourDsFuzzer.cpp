// libFuzzer target fuzz_4ds: the Mafia .4ds reader (importers/src/FourDsReader.cpp)
// on arbitrary bytes. The model "lives" in the shared 4ds folder (it is never
// read from there: the bytes are the fuzz input), so material texture names
// go through TextureResolver's real, case-insensitive directory listings of
// maps/ and find real files and their _ddn/_spec companions.
//
// A successful read must hand back a scene that keeps SceneChecks.h's
// promises, and once finished as importScene finishes it, one that renders
// finite; an error is fine, a crash, sanitizer report, leak, timeout or allocation over
// -malloc_limit_mb is a finding.
#include "SceneChecks.h"

#include "lpv/importers/FourDsReader.h"
#include "lpv/importers/Importer.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <span>

namespace {

namespace fs = std::filesystem;

// LPV_FUZZ_4DS_DIR (environment) overrides the folder compiled in (the shared scenes' 4ds/).
fs::path modelFolder() {
    const char* env = std::getenv("LPV_FUZZ_4DS_DIR");
    return env && *env ? fs::path(env) : fs::path(LPV_FUZZ_4DS_DEFAULT_DIR);
}

fs::path gModelFile;

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    const fs::path folder = modelFolder();
    std::error_code ec;
    if (!fs::is_directory(folder / "maps", ec))
        std::fprintf(stderr, "fuzz_4ds: %s has no maps/ folder; texture lookups will find nothing\n",
                     folder.string().c_str());
    gModelFile = folder / "fuzz.4ds";
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const lpv::importers::ImportOptions options;
    auto result = lpv::importers::readFourDs(std::span<const std::uint8_t>(data, size), gModelFile, options);
    if (result) {
        // The reader's own scene keeps the structural promises; the render
        // check applies to what importScene hands on, once finishImport has
        // repaired values and cleaned meshes (a 3e38 corner goes there).
        lpv::fuzz::checkScene(result->scene, gModelFile.string(), false);
        lpv::importers::finishImport(gModelFile, *result);
        lpv::fuzz::checkRenderFinite(result->scene);
    }
    return 0;
}
