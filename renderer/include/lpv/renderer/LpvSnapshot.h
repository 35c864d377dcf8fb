#pragma once
// What the visualizers read back from the LPV: one cascade's volumes at one
// propagation step. Reading back stalls the GPU, so it happens only while a
// view asks for it (ForwardRenderer::setLpvCapture); with no request the
// renderer reads nothing and keeps nothing.
#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <vector>

namespace lpv::renderer {

// Where a cascade lies: minimum corner, cell size (world units), cells per axis.
struct LpvGridFrame {
    glm::vec3 origin{0.0f};
    float cellSize = 1.0f;
    int gridSize = 0;

    float extent() const { return cellSize * float(gridSize); }
};

// Which cascade and which step to capture: step 0 is the injected volume V_0,
// step s the result V_s of the s-th propagation step. A step beyond the
// frame's lpv.propagationSteps is clamped to the last one.
struct LpvCaptureRequest {
    int cascade = 0;
    int step = 0;
};

// Per colour channel, N^3 SH (x fastest, then y, then z), as the GPU holds them.
using ShVolume = std::array<std::vector<glm::vec4>, 3>;

struct LpvSnapshot {
    LpvGridFrame frame;
    int cascade = 0;
    int cascades = 0;
    int step = 0;                    // the step captured (after clamping)
    int propagationSteps = 0;        // of the frame
    ShVolume stepVolume;             // V_step
    ShVolume accumulatedToStep;      // V_0 + ... + V_step (the accumulator at that moment)
    std::vector<glm::vec4> geometry; // (N+1)^3 blocking potential; empty when lpv.occlusion is off
};

} // namespace lpv::renderer
