#pragma once
// The scenes as a user first opens them, shared by the GL tests that render
// the shared scenes: Sponza and Sibenik as `lpv import` makes them, and the
// built-in Cornell box template.
#include "TestPaths.h"

#include "lpv/app/ImportDefaults.h"
#include "lpv/importers/Importer.h"
#include "lpv/scene/Project.h"
#include "lpv/scene/SceneMerge.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace lpv::test {

struct OpeningView {
    scene::Project project;
    scene::Camera camera;
};

// What `lpv import FILE -o NEW.lpvproj` saves (ImportCommand.cpp): the file's
// scene appended to an empty project with the registry's defaults, and the
// sun it adds to a scene without lights; the view the editor and `lpv render`
// open it with. `relative` is under the shared scenes folder.
inline OpeningView importedScene(const std::string& relative) {
    OpeningView v;
    auto result = importers::importScene(std::filesystem::path(kSharedScenesDir) / relative);
    EXPECT_TRUE(result.has_value()) << (result ? "" : result.error().describe());
    if (!result)
        return v;
    scene::appendScene(v.project.scene, std::move(result->scene));
    if (v.project.scene.lights.empty())
        v.project.scene.lights.push_back(app::chooseDefaultSun(v.project.scene).light);
    v.camera = app::firstView(v.project.scene);
    return v;
}

inline std::filesystem::path builtInCornellBoxFile() {
    return std::filesystem::path(kSourceDir) / "projects/cornell-box/cornell-box.lpvproj";
}

inline OpeningView builtInCornellBox() {
    OpeningView v;
    auto loaded = scene::loadProject(builtInCornellBoxFile());
    EXPECT_TRUE(loaded.has_value()) << (loaded ? "" : loaded.error().describe());
    if (!loaded)
        return v;
    v.project = std::move(*loaded);
    v.camera = app::firstView(v.project.scene);
    return v;
}

} // namespace lpv::test
