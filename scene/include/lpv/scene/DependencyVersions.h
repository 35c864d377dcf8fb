#pragma once
// Versions of the third-party libraries each layer uses, for `lpv --version`
// and the editor's About box. Every library reports its own dependencies
// (most are private to it, so only it can include their headers); the app
// layer puts the lists together (app/common, lpv/app/VersionInfo.h).
#include <string>
#include <vector>

namespace lpv::scene {

struct DependencyVersion {
    std::string name;    // "glm"
    std::string version; // "0.9.9.8"
    std::string note;    // how it was found: "header-only", "loaded", "built against"
};

// lpv_scene's: glm, nlohmann_json, xxHash.
std::vector<DependencyVersion> dependencyVersions();

} // namespace lpv::scene
