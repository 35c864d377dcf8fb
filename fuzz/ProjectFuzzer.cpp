// libFuzzer target fuzz_project: loadProject (scene/src/Project.cpp,
// ProjectJson.cpp) with the fuzz input as the project file's JSON.
//
// At start-up the committed projects/cornell-box/cornell-box.assets folder is
// copied into a private work folder (on tmpfs /dev/shm when there is one);
// each input is written there as cornell-box.lpvproj and loaded, so the JSON
// validation, the parameter registry, the asset path checks and the mesh
// loading (real .lpvmesh files with checksums, vertex/triangle counts checked
// against the JSON) all run. The mesh decoder on its own is fuzz_mesh_asset.
//
// LPV_FUZZ_TMP (environment) picks the folder the work folder is made in.
// The work folder, lpv-fuzz-project-<pid>, is removed at exit (not after a
// crash: scripts/fuzz.sh removes it then).
#include "SceneChecks.h"

#include "lpv/scene/Project.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace {

namespace fs = std::filesystem;

fs::path gWorkFolder;
fs::path gProjectFile;

void removeWorkFolder() {
    std::error_code ignored;
    fs::remove_all(gWorkFolder, ignored);
}

fs::path tempParent() {
    if (const char* env = std::getenv("LPV_FUZZ_TMP"); env && *env)
        return env;
    std::error_code ec;
    if (fs::is_directory("/dev/shm", ec))
        return "/dev/shm";
    return fs::temp_directory_path();
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    const fs::path source = fs::path(LPV_FUZZ_PROJECT_DIR) / "cornell-box.assets";
    gWorkFolder = tempParent() / ("lpv-fuzz-project-" + std::to_string(getpid()));
    gProjectFile = gWorkFolder / "cornell-box.lpvproj";
    std::error_code ec;
    fs::remove_all(gWorkFolder, ec);
    fs::create_directories(gWorkFolder, ec);
    if (!ec)
        fs::copy(source, gWorkFolder / "cornell-box.assets", fs::copy_options::recursive, ec);
    if (ec) {
        std::fprintf(stderr, "fuzz_project: cannot copy %s to %s: %s\n", source.string().c_str(),
                     gWorkFolder.string().c_str(), ec.message().c_str());
        std::exit(1);
    }
    std::atexit(removeWorkFolder);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    {
        std::ofstream out(gProjectFile, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
        if (!out) {
            std::fprintf(stderr, "fuzz_project: cannot write %s\n", gProjectFile.string().c_str());
            std::abort();
        }
    }
    const auto project = lpv::scene::loadProject(gProjectFile);
    if (project)
        lpv::fuzz::checkScene(project->scene, gProjectFile.string());
    return 0;
}
