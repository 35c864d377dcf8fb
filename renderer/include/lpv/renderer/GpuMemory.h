#pragma once
// The GPU memory a frame's resources hold (issue #43: memory as a second
// cost beside time). ForwardRenderer::gpuMemory() counts, after the last
// frame, every frame-graph resource (graph-owned transient and history
// targets, and the imported ones its passes own: shadow maps, RSMs, the
// exposure buffer...) and the LPV's own volumes, buffers and sums that the
// graph names only by one representative texture. Each GL object is counted
// once, at the bytes its format and size give (width x height x layers x
// bytes per texel, every mip level); what a driver pads or compresses is not
// seen. Scene meshes and material textures are left out: they do not change
// with the settings. Texture views share their texture's storage and add nothing.
#include "lpv/renderer/GlHandle.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lpv::renderer {

struct GpuAllocation {
    std::string name; // a frame-graph resource or a pass's own: camera.depth, lpv.volumes
    std::string what; // its shape (graph::describe): "2D RGBA16F 320x180", "6 x 3D RGBA32F 32x32x128"
    std::uint64_t bytes = 0;
};

struct GpuMemory {
    std::vector<GpuAllocation> allocations; // largest first
    std::uint64_t totalBytes = 0;

    // The bytes of the allocations whose name starts with `prefix` ("lpv." : the LPV's volumes).
    std::uint64_t bytesOf(std::string_view prefix) const;
    // The allocation of that name, or null.
    const GpuAllocation* find(std::string_view name) const;
};

// Bytes per texel of a sized internal format the renderer allocates
// (GL_RGBA32F: 16, GL_DEPTH_COMPONENT32F: 4...); 0 for one it does not know.
std::uint64_t bytesPerTexel(GLenum internalFormat);

// "12.3 MiB", "640 KiB", "512 B": binary units, one decimal unless whole.
std::string formatBytes(std::uint64_t bytes);

} // namespace lpv::renderer
