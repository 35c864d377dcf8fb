#pragma once
// Materials on the GPU: their constants and textures, bound per draw. Each
// pass asks only for what it reads (depth-only passes for nothing, shadow
// passes for coverage, the RSM for reflectance, shading for everything).
#include "lpv/renderer/GlHandle.h"
#include "lpv/scene/Image.h"
#include "lpv/scene/Scene.h"

#include <cstdint>
#include <vector>

namespace lpv::renderer {

enum class MaterialBindMode {
    DepthOnly,   // nothing
    Coverage,    // alpha mask / colour key only, so masked leaves cast masked shadows
    Reflectance, // coverage + diffuse albedo (RSM flux)
    Full,        // everything forward shading reads
};

class MaterialGpu {
public:
    MaterialGpu(const scene::Scene& scene, const scene::TextureImages& textures);

    // Sets the uniforms and texture units of `program` for `material`.
    void bind(GLuint program, std::uint32_t material, MaterialBindMode mode) const;

private:
    std::vector<scene::Material> materials_;
};

} // namespace lpv::renderer
