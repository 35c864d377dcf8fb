#pragma once
// The Cornell box with a short camera path, for video tests.
#include "TestPaths.h"

#include "lpv/scene/CameraSpline.h"
#include "lpv/scene/Project.h"

#include <filesystem>
#include <string>

namespace lpv::test {

inline std::filesystem::path cornellDir() {
    return std::filesystem::path(kSourceDir) / "projects" / "cornell-box";
}

// The built-in Cornell box plus "dolly": `seconds` long, from the published
// camera forward and to the side, turning a little.
inline scene::Project cornellWithPath(float seconds = 2.0f) {
    auto loaded = scene::loadProject(cornellDir() / "cornell-box.lpvproj");
    scene::Project p = loaded ? *loaded : scene::Project{};
    const scene::Camera camera = p.scene.cameras.empty() ? scene::Camera{} : p.scene.cameras.front();
    scene::CameraPath path;
    path.name = "dolly";
    scene::CameraKeyframe a = scene::keyframeFromCamera(camera, 0.0f);
    scene::Camera moved = camera;
    moved.position += glm::vec3(0.6f, 0.2f, 2.0f);
    scene::CameraKeyframe b = scene::keyframeFromCamera(moved, seconds * 0.5f);
    moved.position += glm::vec3(-1.2f, 0.0f, 1.0f);
    moved.target += glm::vec3(-0.5f, 0.0f, 0.0f);
    scene::CameraKeyframe c = scene::keyframeFromCamera(moved, seconds);
    path.keyframes = {a, b, c};
    p.scene.cameraPaths.push_back(path);
    return p;
}

} // namespace lpv::test
