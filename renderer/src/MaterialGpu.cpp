#include "MaterialGpu.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace lpv::renderer {

MaterialGpu::MaterialGpu(const scene::Scene& scene, const scene::TextureImages& /*textures*/)
    : materials_(scene.materials) {}

void MaterialGpu::bind(GLuint program, std::uint32_t material, MaterialBindMode mode) const {
    if (mode == MaterialBindMode::DepthOnly)
        return;
    const scene::Material m = material < materials_.size() ? materials_[material] : scene::Material{};
    auto loc = [&](const char* name) { return glGetUniformLocation(program, name); };
    glProgramUniform3fv(program, loc("uDiffuse"), 1, glm::value_ptr(m.diffuseColor));
    if (mode != MaterialBindMode::Full)
        return;
    glProgramUniform3fv(program, loc("uSpecular"), 1, glm::value_ptr(m.specularColor));
    glProgramUniform1f(program, loc("uShininess"), std::max(m.shininess, 1.0f));
    glProgramUniform3fv(program, loc("uEmissive"), 1, glm::value_ptr(m.emissive));
    glProgramUniform1i(program, loc("uTwoSided"), m.twoSided ? 1 : 0);
}

} // namespace lpv::renderer
