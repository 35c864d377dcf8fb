#pragma once
// One fuzz input as a project file: written over `projectFile` (in the
// work folder, WorkFolder.h), loaded, and when it loads, its scene checked
// (SceneChecks.h) and its render inputs checked finite (RenderChecks.h).
// fuzz_project takes the input as it comes; fuzz_project_structure after
// its own mutation of the JSON.
#include "SceneChecks.h"
#include "WorkFolder.h"

#include "lpv/scene/Project.h"

#include <filesystem>
#include <string_view>

namespace lpv::fuzz {

inline void loadAndCheckProject(const std::filesystem::path& projectFile, std::string_view bytes) {
    writeInput(projectFile, bytes);
    const auto project = scene::loadProject(projectFile);
    if (project) {
        checkScene(project->scene, projectFile.string());
        checkProjectRenderFinite(*project);
    }
}

} // namespace lpv::fuzz
