#pragma once
// Versions of lpv_importers' third-party libraries (see lpv/scene/DependencyVersions.h).
#include "lpv/scene/DependencyVersions.h"

#include <vector>

namespace lpv::importers {

// Assimp, OpenImageIO, tinygltf, OpenMesh.
std::vector<scene::DependencyVersion> dependencyVersions();

} // namespace lpv::importers
