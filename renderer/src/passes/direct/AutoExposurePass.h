#pragma once
// The GPU side of auto exposure (AutoExposure.h): meters the HDR image into a
// small storage buffer that tonemap.frag reads at binding 1, so the exposure
// never travels through the CPU (no read-back stall in the frame).
#include "lpv/renderer/AutoExposure.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/scene/Error.h"

namespace lpv::renderer {

class GpuMemoryLedger;

class AutoExposurePass {
public:
    static scene::Expected<AutoExposurePass> create();

    // Meters `hdr` (width x height) and moves the exposure toward `target`'s
    // (targetLogExposure) by `blend` (adaptationBlend; 1 = at once). The first
    // frame after create() or reset() takes its target whatever the blend.
    void meter(GLuint hdr, int width, int height, const MeterTarget& target, float blend);
    // Forgets the adapted exposure (a new scene, manual mode, a jump in time).
    void reset();
    // The buffer tonemap.frag reads: {ln exposure, exposure, valid, lit pixels}.
    GLuint exposureBuffer() const { return exposure_.id(); }
    // The exposure of the last meter() (1 before any frame with lit pixels).
    // Reads the GPU buffer back, so it waits for the frame: for the CLI and tests.
    double readExposure() const;
    // Names its GL objects for ForwardRenderer::gpuMemory().
    void addGpuMemory(GpuMemoryLedger& ledger) const;

private:
    AutoExposurePass() = default;
    Program reduce_, adapt_;
    Buffer tiles_, exposure_, histogram_;
    int tileCapacity_ = 0;
};

} // namespace lpv::renderer
