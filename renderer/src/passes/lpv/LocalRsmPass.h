#pragma once
// Reflective shadow maps of spot and point lights (docs/lpv.md, "Local
// lights, emissive surfaces and bounces"): a perspective view per spot light
// and six cube faces per point light (ShadowLights.h's views), each one layer
// of 2D array targets in RsmPass's formats, so the LPV injects their texels as
// VPLs the way it injects the sun's. Created by ForwardRenderer only while the
// scene has a spot or point light: without one nothing is allocated.
#include "frame/FrameContext.h"
#include "passes/lpv/RsmTargets.h"
#include "scenegpu/MaterialGpu.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/SceneGpu.h"
#include "lpv/scene/Error.h"

#include <vector>

namespace lpv::renderer {

class GpuMemoryLedger;

// At most this many spot / point lights are injected (the first in scene
// order among the shaded lights); 4 point lights are 24 layers.
inline constexpr int kMaxInjectedLocalLights = 4;

// The lights a local RSM renders: indices of spot and point lights among the shaded ones, in scene order.
std::vector<int> selectInjectedLocalLights(const scene::Scene& scene);

class LocalRsmPass {
  public:
    static scene::Expected<LocalRsmPass> create();

    // Renders every face of every selected light ("localRsm"); `size` is
    // lpv.localRsmSize. With no light selected it renders nothing and frees its targets.
    scene::Expected<void> render(const FrameContext& frame, const SceneGpu& geometry,
                                 const MaterialGpu& materials, int size);

    bool active() const { return targets_.layers() > 0; }
    int size() const { return targets_.size(); }
    int layers() const { return targets_.layers(); }
    int lights() const { return lights_; }
    GLuint positionArray() const { return targets_.position(); }
    GLuint normalArray() const { return targets_.normal(); }
    GLuint fluxArray() const { return targets_.flux(); }
    std::size_t allocatedBytes() const { return targets_.bytes(); }
    // Names its GL objects for ForwardRenderer::gpuMemory().
    void addGpuMemory(GpuMemoryLedger& ledger) const;
    // "localrsm-L-position", "-normal", "-flux" per layer L.
    std::vector<DebugImage> debugImages() const;

  private:
    LocalRsmPass() = default;
    scene::Expected<void> ensureTargets(int size, int layers);
    void release();

    Program program_;
    int lights_ = 0;
    RsmTargets targets_;
};

} // namespace lpv::renderer
