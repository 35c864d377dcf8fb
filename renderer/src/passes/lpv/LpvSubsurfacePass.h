#pragma once
// Subsurface-scattering LPV (docs/lpv.md, "Subsurface LPV"; the thesis' third
// extension): a second volume set, fed only by translucent RSM texels (VPLs
// along -normal, no offset, flux * translucency), propagated a few steps
// without occlusion and attenuated per step, read when shading translucent
// surfaces (shaders/lpv_subsurface_lookup.glsl). CPU twin:
// lpvref::injectSubsurface / propagateSubsurface.
//
// It runs after LpvPass::run on the same frame and reuses that pass's
// fixed-point sums (cleared again by then) and injection scale, so it adds
// only its own three packed volumes. The renderer creates it on the first
// frame the scene analysis wants it and drops it when not: a skipped pass
// holds no GPU memory.
#include "passes/lpv/LpvPass.h"
#include "gl/ProgramCache.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/ParameterRegistry.h"

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace lpv::renderer {

class GpuMemoryLedger;

struct LpvSubsurfaceSettings {
    int steps = 4;            // effects.subsurfaceSteps
    float attenuation = 0.5f; // effects.subsurfaceAttenuation: fraction lost per step (cell)

    static LpvSubsurfaceSettings fromParameters(const scene::ParameterSet& params);
};

class LpvSubsurfacePass {
  public:
    static scene::Expected<LpvSubsurfacePass> create();

    // Injection and propagation into the packed volumes, on the cascades
    // `lpv` computed this frame (which must be active); the frame graph
    // times both as the pass "subsurface".
    void run(const LpvSubsurfaceSettings& settings, const LpvPass& lpv, const LpvRsmInput& rsm);

    // lpv_subsurface_lookup.glsl's uniforms; the accumulator on texture unit `unit`.
    void bindForShading(const CachedProgram& program, GLuint unit) const;
    // No subsurface light this frame: the lookup is off, the sampler names an empty unit.
    static void bindNone(const CachedProgram& program, GLuint unit);

    // Read-back for tests: per channel N^3 SH of cascade k.
    std::array<std::vector<glm::vec4>, 3> readAccumulator(int cascade) const;
    std::size_t allocatedBytes() const;
    // Names its GL objects for ForwardRenderer::gpuMemory().
    void addGpuMemory(GpuMemoryLedger& ledger) const;
    GLuint accumulatorTexture() const { return accumulator_.id(); }
    int steps() const { return steps_; }

  private:
    LpvSubsurfacePass() = default;
    void ensureVolumes(int gridSize, int cascades);
    void setCascadeUniforms(GLuint program, const LpvPass& lpv) const;

    Program inject_, resolve_, gather_;
    // Ping-pong volumes and the accumulator, 3N x N x NK RGBA32F each (lpv_subsurface.glsl).
    std::array<Texture, 2> volume_;
    Texture accumulator_;
    int gridSize_ = 0, cascades_ = 0;
    int steps_ = 0;
};

} // namespace lpv::renderer
