#pragma once
// The sky-injection tests' scene (two and three SH bands): one cascade of
// 16^3 half-metre cells under a height map of 2 texels per cell, a
// courtyard (ground at y = 0.1) inside walls 3.3 high, a roof at 9 (above
// the cascade) over one corner and a strip with no surface at all; the depth
// texture the GPU reads it from, and an RSM of one dark texel, so the sky is
// the only light.
#include "passes/lpv/LpvPass.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/lpv/LpvReference.h"

#include <glm/glm.hpp>

#include <limits>
#include <vector>

namespace lpv::renderer {

// A one-layer 2D array texture of `size`^2 texels from `data` (floats).
inline Texture layerTexture(GLenum format, int size, GLenum dataFormat, const void* data) {
    Texture t = createTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(t.id(), 1, format, size, size, 1);
    glTextureSubImage3D(t.id(), 0, 0, 0, 0, size, size, 1, dataFormat, GL_FLOAT, data);
    return t;
}

struct SkyCourtyard {
    lpvref::GridFrame grid{glm::vec3(-2.0f, -1.0f, 3.0f), 0.5f, 16};
    lpvref::HeightMap map;
    float top = 12.0f, bottom = -4.0f; // the height map's depth range
    glm::vec3 radiance{0.5f, 0.7f, 1.0f};
    Texture depth, position, normal, flux;

    SkyCourtyard() {
        map.size = 32;
        map.min = {grid.origin.x, grid.origin.z};
        map.texelSize = grid.cellSize / 2.0f;
        std::vector<float> depths(std::size_t(map.size * map.size));
        map.height.resize(depths.size());
        for (int j = 0; j < map.size; ++j)
            for (int i = 0; i < map.size; ++i) {
                const float h = (i >= 24 && j >= 24) ? 9.0f : (i < 4 || j < 4 || i >= 28) ? 3.3f : 0.1f;
                const bool empty = j >= 30;
                const std::size_t t = std::size_t(i + map.size * j);
                depths[t] = empty ? 1.0f : (top - h) / (top - bottom);
                map.height[t] = empty ? -std::numeric_limits<float>::infinity() : h;
            }
        depth = layerTexture(GL_DEPTH_COMPONENT32F, map.size, GL_DEPTH_COMPONENT, depths.data());
        const float zero[4] = {0, 0, 0, 0};
        position = layerTexture(GL_RGBA32F, 1, GL_RGBA, zero);
        normal = layerTexture(GL_RGBA32F, 1, GL_RGBA, zero);
        flux = layerTexture(GL_RGBA32F, 1, GL_RGBA, zero);
    }

    LpvRsmInput rsm() const {
        LpvRsmInput in;
        in.cascades = {LpvCascade{grid.origin, grid.cellSize, grid.n}};
        in.texelArea = {0.01f};
        in.tileSize = 1;
        in.position = position.id();
        in.normal = normal.id();
        in.flux = flux.id();
        return in;
    }
    LpvSkyInput sky() const { return {depth.id(), map.size, map.min, map.texelSize, top, bottom, radiance}; }
};

} // namespace lpv::renderer
