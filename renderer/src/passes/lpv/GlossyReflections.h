#pragma once
// Glossy LPV reflections in the forward pass (shaders/lpv_glossy.glsl): the
// registry's settings as the shader's uniforms. The march reads the LPV
// accumulators the diffuse lookup already binds, so the effect owns no GPU
// memory; when it does not run, the shader skips the march.
#include "gl/ProgramCache.h"
#include "lpv/scene/ParameterRegistry.h"

#include <epoxy/gl.h>

namespace lpv::renderer {

void bindGlossyReflections(const CachedProgram& program, const scene::ParameterSet& params, bool runs);

} // namespace lpv::renderer
