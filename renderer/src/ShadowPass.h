#pragma once
// Shadow maps for the scene's lights, and what forward shading needs to
// sample them (shaders/shadow_sampling.glsl).
#include "FrameContext.h"
#include "MaterialGpu.h"
#include "ShadowView.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/SceneGpu.h"
#include "lpv/scene/Error.h"

namespace lpv::renderer {

class ShadowPass {
public:
    static scene::Expected<ShadowPass> create();

    // Renders the shadow maps of this frame (timed as "shadowMap").
    scene::Expected<void> render(const FrameContext& frame, const SceneGpu& geometry, const MaterialGpu& materials);

    // Sets the uniforms of shadow_sampling.glsl in `program` and binds its
    // textures from unit `firstUnit` on; returns the next free unit.
    int bindForShading(GLuint program, const FrameContext& frame, int firstUnit) const;

    // The depth of every shadow map of the last frame.
    std::vector<DebugImage> debugImages() const;

private:
    ShadowPass() = default;
    scene::Expected<void> ensureMap(int size);

    Program depthProgram_;
    int lightIndex_ = -1;
    ShadowView view_;
    int size_ = 0;
    Texture map_;
    Framebuffer fbo_;
};

} // namespace lpv::renderer
