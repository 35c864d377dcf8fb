#pragma once
// Display values at patch corners. Smoothed: each corner takes the
// area-weighted mean of the patches that share its welded vertex and face
// the same way (normals within ~25 degrees), so flat walls show no patch
// seams while the crease between two walls stays sharp.
#include "lpv/radiosity/PatchMesh.h"

#include <span>
#include <vector>

namespace lpv::radiosity {

// Four values per patch (corner k of patch i at 4 * i + k; unused fourth
// corners of triangles repeat the third). Unsmoothed: the patch's own value.
std::vector<glm::vec3> cornerValues(const PatchMesh& mesh, std::span<const glm::vec3> perPatch, bool smooth);

} // namespace lpv::radiosity
