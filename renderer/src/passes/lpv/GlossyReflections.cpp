#include "passes/lpv/GlossyReflections.h"

namespace lpv::renderer {

void bindGlossyReflections(const CachedProgram& p, const scene::ParameterSet& params, bool runs) {
    auto at = [&](const char* name) { return p.uniform(name); };
    const GLuint program = p.id();
    glProgramUniform1i(program, at("uGlossyEnabled"), runs ? 1 : 0);
    glProgramUniform1f(program, at("uGlossyThreshold"), params.getFloat("effects.glossyThreshold"));
    glProgramUniform1i(program, at("uGlossySteps"), params.getInt("effects.glossySteps"));
    glProgramUniform1f(program, at("uGlossyMaxDistance"), params.getFloat("effects.glossyMaxDistance"));
    glProgramUniform1f(program, at("uGlossyIntensity"), params.getFloat("effects.glossyIntensity"));
}

} // namespace lpv::renderer
