// LpvPass's injection of spot and point lights' VPLs (shaders/lpv_inject_local.comp),
// kept apart from the sun's injection it joins.
#include "passes/lpv/LpvPass.h"

namespace lpv::renderer {

namespace {

GLuint groups(int count, int size) {
    return GLuint((count + size - 1) / size);
}

} // namespace

std::string localNote(const std::vector<LpvLocalInput>& local) {
    std::string note;
    for (const LpvLocalInput& l : local)
        note += ", " + l.label + " injected";
    return note;
}

void LpvPass::localFluxMax(const LpvLocalInput& local) {
    const GLuint p = kernel(LpvKernel::LocalFluxMax);
    glUseProgram(p);
    setCascadeUniforms(p);
    glBindTextureUnit(0, local.position);
    glBindTextureUnit(1, local.flux);
    glProgramUniform1i(p, loc(p, "uLocalPosition"), 0);
    glProgramUniform1i(p, loc(p, "uLocalFlux"), 1);
    glDispatchCompute(groups(local.size, 8), groups(local.size, 8), GLuint(local.layers));
}

void LpvPass::injectLocal(const LpvLocalInput& local, bool directed) {
    const GLuint p = kernel(LpvKernel::LocalInject);
    glUseProgram(p);
    setCascadeUniforms(p);
    glBindTextureUnit(0, local.position);
    glBindTextureUnit(1, local.flux);
    glBindTextureUnit(2, local.normal);
    glProgramUniform1i(p, loc(p, "uLocalPosition"), 0);
    glProgramUniform1i(p, loc(p, "uLocalFlux"), 1);
    glProgramUniform1i(p, loc(p, "uLocalNormal"), 2);
    glProgramUniform1i(p, loc(p, "uTexelsPerTile"), injectedTexels_);
    glProgramUniform1i(p, loc(p, "uScaleSlot"), -1);
    glProgramUniform1f(p, loc(p, "uInjectionOffset"), injectionOffset_);
    // The normal sums are bound by inject() while directed propagation runs.
    glProgramUniform1i(p, loc(p, "uDirected"), directed ? 1 : 0);
    glDispatchCompute(groups(local.size, 8), groups(local.size, 8), GLuint(local.layers));
}

} // namespace lpv::renderer
