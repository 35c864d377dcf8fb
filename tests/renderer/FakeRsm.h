#pragma once
// RSM tiles written by hand for the LPV GL tests: each texel a VPL (flux > 0)
// and a geometry-volume surfel at once, as RsmPass writes them.
#include "lpv/renderer/GlHandle.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <vector>

namespace lpv::renderer {

// One RSM-like texel: a VPL (flux > 0) and a GV surfel at once, like RsmPass writes them.
struct Texel {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec3 flux;
};

// RSM tiles as 2D arrays (RGBA32F, so the GPU sees exactly the CPU's numbers).
struct FakeRsm {
    Texture position, normal, flux;
    int tileSize = 0;

    FakeRsm(int size, const std::vector<std::vector<Texel>>& tiles) : tileSize(size) {
        const int layers = int(tiles.size());
        auto make = [&](Texture& t) {
            t = createTexture(GL_TEXTURE_2D_ARRAY);
            glTextureStorage3D(t.id(), 1, GL_RGBA32F, size, size, layers);
        };
        make(position);
        make(normal);
        make(flux);
        const std::size_t texels = std::size_t(size) * std::size_t(size);
        for (int k = 0; k < layers; ++k) {
            std::vector<glm::vec4> p(texels, glm::vec4(0.0f)), n(texels, glm::vec4(0.0f)),
                f(texels, glm::vec4(0.0f));
            const auto& tile = tiles[std::size_t(k)];
            EXPECT_LE(tile.size(), texels);
            for (std::size_t i = 0; i < tile.size() && i < texels; ++i) {
                p[i] = glm::vec4(tile[i].position, 1.0f);
                n[i] = glm::vec4(tile[i].normal, 1.0f);
                f[i] = glm::vec4(tile[i].flux, 1.0f);
            }
            glTextureSubImage3D(position.id(), 0, 0, 0, k, size, size, 1, GL_RGBA, GL_FLOAT, p.data());
            glTextureSubImage3D(normal.id(), 0, 0, 0, k, size, size, 1, GL_RGBA, GL_FLOAT, n.data());
            glTextureSubImage3D(flux.id(), 0, 0, 0, k, size, size, 1, GL_RGBA, GL_FLOAT, f.data());
        }
    }
};

} // namespace lpv::renderer
