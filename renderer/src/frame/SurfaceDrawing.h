#pragma once
// Draws a frame's opaque and alpha-masked surfaces (surfaceDraws, DrawList.h)
// through one program variant in two forms: the opaque items with
// `opaqueDefine` set (a program that never discards, so llvmpipe tests their
// depth early), the masked ones without it (the variant that cuts their
// holes, materials bound for coverage). The passes that draw the scene
// again at the camera's view use it: the reduced lookup, its resolve.
#include "frame/FrameState.h"
#include "gl/ProgramCache.h"
#include "lpv/renderer/DrawList.h"
#include "lpv/scene/Error.h"

#include <glm/gtc/type_ptr.hpp>

#include <string>

namespace lpv::renderer {

// `setUniforms(const CachedProgram&)` sets what else each of the two programs reads.
template <typename SetUniforms>
scene::Expected<void> drawSurfaces(const SurfaceDraws& draws, ProgramCache& programs, ProgramVariant variant,
                                   const std::string& opaqueDefine, const FrameState& state,
                                   const SetUniforms& setUniforms) {
    for (const bool cutOut : {false, true}) {
        const std::vector<const DrawItem*>& list = cutOut ? draws.masked : draws.opaque;
        if (list.empty())
            continue;
        ProgramVariant form = variant;
        if (!cutOut)
            form.defines.push_back(opaqueDefine + " 1");
        auto program = programs.get(form);
        if (!program)
            return std::unexpected(program.error());
        const CachedProgram& shader = **program;
        const GLuint p = shader.id();
        glUseProgram(p);
        glProgramUniformMatrix4fv(p, shader.uniform("uViewProj"), 1, GL_FALSE,
                                  glm::value_ptr(state.frame.viewProj));
        setUniforms(shader);
        state.sceneGpu->draw(
            p, list, [&](std::uint32_t m) { state.materialGpu->bind(p, m, MaterialBindMode::Coverage); });
    }
    return {};
}

} // namespace lpv::renderer
