#pragma once
// A radiosity solution's patches as GL triangles with one value per corner
// (radiosity::cornerValues): what RadiosityView shows and what the
// radiosityIndirect pass draws, built and uploaded one way.
#include "lpv/radiosity/PatchMesh.h"
#include "lpv/renderer/GlHandle.h"

#include <functional>
#include <span>
#include <vector>

namespace lpv::renderer {

struct PatchVertex {
    glm::vec3 position;
    glm::vec3 value;  // the corner's value: radiance to show, incident light...
    glm::vec3 normal; // the patch's, so a shader can tell which side of it the camera sees
};

// One triangle per triangle patch, two per quad; `cornerValues` holds four
// values per patch as radiosity::cornerValues gives them. A patch for which
// `keep` (if given) returns false is left out.
std::vector<PatchVertex> patchTriangles(const radiosity::PatchMesh& mesh,
                                        std::span<const glm::vec3> cornerValues,
                                        const std::function<bool(const radiosity::Patch&)>& keep = {});
// Every patch's edges as pairs of line vertices (the wireframe).
std::vector<PatchVertex> patchOutlines(const radiosity::PatchMesh& mesh,
                                       std::span<const glm::vec3> cornerValues);

// The vertices in a buffer behind a vertex array: attribute 0 the position,
// 1 the value, 2 the normal.
struct PatchDraw {
    Buffer buffer;
    VertexArray vao;
    GLsizei vertices = 0;
};
PatchDraw uploadPatchVertices(const std::vector<PatchVertex>& vertices);

} // namespace lpv::renderer
