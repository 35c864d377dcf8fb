#pragma once
// What a frame-graph resource is: its kind, format and size. Passes declare
// their inputs and outputs with these; the graph allocates transient and
// history targets from them and prints them in `lpv render --graph`.
#include "lpv/renderer/GlHandle.h"

#include <cstddef>
#include <string>

namespace lpv::renderer::graph {

enum class ResourceKind { Texture2D, Texture2DArray, Texture3D, CubeMapArray, Buffer };

struct ResourceDesc {
    ResourceKind kind = ResourceKind::Texture2D;
    GLenum format = 0;         // GL_RGBA16F, GL_DEPTH_COMPONENT32F, ... (0 for buffers)
    int width = 0, height = 0; // texels
    int layers = 1;            // array layers, or a 3D texture's depth
    std::size_t bytes = 0;     // buffers only
    bool linearFilter = false; // graph-owned textures: linear instead of nearest sampling

    bool operator==(const ResourceDesc&) const = default;
};

// "2D RGBA16F 1280x720", "2D array DEPTH32F 2048x2048x6", "buffer 1.0 MiB".
std::string describe(const ResourceDesc& desc);
// An empty description: the pass allocates it on its first run.
bool known(const ResourceDesc& desc);
// A texture of that shape, nearest-filtered (or linear) and clamped.
Texture allocateTexture(const ResourceDesc& desc);
// The shape of an existing texture or buffer, asked of GL (0: empty description).
ResourceDesc queryTexture(GLuint texture);
ResourceDesc queryBuffer(GLuint buffer);

} // namespace lpv::renderer::graph
