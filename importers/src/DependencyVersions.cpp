#include "lpv/importers/DependencyVersions.h"

#include <OpenImageIO/imageio.h>
#include <OpenMesh/Core/System/config.h>
#include <assimp/version.h>

namespace lpv::importers {

namespace {

std::string dotted(unsigned major, unsigned minor, unsigned patch) {
    return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

} // namespace

std::vector<scene::DependencyVersion> dependencyVersions() {
    // Assimp and OpenImageIO say which version is loaded; that is the one
    // that matters when a user's system library differs from the build's.
    const int oiio = OIIO::openimageio_version();
    return {
        {"Assimp", dotted(aiGetVersionMajor(), aiGetVersionMinor(), aiGetVersionPatch()), "loaded"},
        {"OpenImageIO",
         dotted(static_cast<unsigned>(oiio / 10000), static_cast<unsigned>(oiio / 100 % 100),
                static_cast<unsigned>(oiio % 100)),
         "loaded"},
        // tinygltf has no version macro or call; CMake's package version is the next best.
        {"tinygltf", LPV_TINYGLTF_VERSION, "built against"},
        {"OpenMesh", dotted(OM_GET_VER, OM_GET_MAJ, OM_GET_MIN), "built against"},
    };
}

} // namespace lpv::importers
