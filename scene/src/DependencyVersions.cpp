#include "lpv/scene/DependencyVersions.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <xxhash.h>

namespace lpv::scene {

namespace {

std::string dotted(unsigned major, unsigned minor, unsigned patch) {
    return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

} // namespace

std::vector<DependencyVersion> dependencyVersions() {
    // xxHash is a shared library: report the one loaded, which can differ
    // from the headers we were compiled with.
    const unsigned xxh = XXH_versionNumber();
    return {
        {"glm",
         dotted(GLM_VERSION_MAJOR, GLM_VERSION_MINOR, GLM_VERSION_PATCH) + "." +
             std::to_string(GLM_VERSION_REVISION),
         "header-only"},
        {"nlohmann_json",
         dotted(NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR, NLOHMANN_JSON_VERSION_PATCH),
         "header-only"},
        {"xxHash", dotted(xxh / 10000, xxh / 100 % 100, xxh % 100), "loaded"},
    };
}

} // namespace lpv::scene
