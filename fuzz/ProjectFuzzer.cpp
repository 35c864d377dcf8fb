// libFuzzer target fuzz_project: loadProject (scene/src/Project.cpp,
// ProjectJson.cpp) with the fuzz input as the project file's JSON.
//
// At start-up the committed projects/cornell-box/cornell-box.assets folder is
// copied into a private work folder (WorkFolder.h: on tmpfs /dev/shm when
// there is one); each input is written there as cornell-box.lpvproj and
// loaded, so the JSON validation, the parameter registry, the asset path
// checks and the mesh loading (real .lpvmesh files with checksums,
// vertex/triangle counts checked against the JSON) all run. The mesh decoder
// on its own is fuzz_mesh_asset; JSON-level mutations of the same project are
// fuzz_project_structure.
#include "ProjectInput.h"
#include "SceneChecks.h"
#include "WorkFolder.h"

#include "lpv/scene/Project.h"

#include <cstdint>
#include <filesystem>
#include <string_view>

namespace {

std::filesystem::path gProjectFile;

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    gProjectFile = lpv::fuzz::makeCornellBoxFolder("project", LPV_FUZZ_PROJECT_DIR) / "cornell-box.lpvproj";
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    lpv::fuzz::loadAndCheckProject(gProjectFile, std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
