#pragma once
// The GPU memory of the LPV: per colour channel one RGBA32F 3D texture of
// N x N x (N * K) texels (the K cascades stacked along z) for each of the two
// ping-pong volumes and the accumulator; the geometry volume ((N+1)^3 per
// cascade, stacked the same way); the integer buffers the atomics sum into;
// and the framebuffers the raster variants draw through.
#include "lpv/renderer/GlHandle.h"
#include "lpv/scene/Error.h"

#include <array>
#include <cstddef>
#include <cstdint>

namespace lpv::renderer {

class GpuMemoryLedger;

struct LpvVolumeSet {
    std::array<Texture, 3> channel; // R, G, B
};

class LpvVolumes {
  public:
    // Allocates for N cells per axis and K cascades, or names the parameter
    // that does not fit the GPU (texture size, buffer size, memory).
    scene::Expected<void> ensure(int gridSize, int cascades);
    // The normals volume of directed propagation, allocated only while it runs.
    void ensureDirected(bool directed);
    // The running total of earlier bounces, allocated only while lpv.bounces > 1.
    void ensureBounces(bool bounces);
    // The compute gather's interleaved ping-pong volumes, allocated only while it runs.
    void ensureInterleaved(bool interleaved);
    // The visibility-aware lookup's moments, allocated only while it is on;
    // true when this call allocated them (their content is not this frame's yet).
    bool ensureVisibility(bool visibility);
    void release();

    int gridSize() const { return gridSize_; }
    // Bumped by every ensure() that allocates and by release().
    std::uint64_t generation() const { return generation_; }
    int cascades() const { return cascades_; }
    std::size_t allocatedBytes() const;
    // Names every volume and buffer allocated now (resources::LpvVolumes,
    // LpvGeometry... in FrameResources.h) for ForwardRenderer::gpuMemory().
    void addGpuMemory(GpuMemoryLedger& ledger) const;

    std::array<LpvVolumeSet, 2> volume; // ping-pong
    LpvVolumeSet accumulator;
    Texture geometry;                    // (N+1) x (N+1) x ((N+1) K), RGBA32F
    Texture faceBlocking;                // 3N x N x NK: per cell, the GV on its +x, +y, +z face side by side
                                         // (all but raster scatter)
    Buffer lpvSums;                      // 12 int per cell: fixed-point sums of injection / scatter
    Buffer gvSums;                       // 2 sources x 4 int per GV cell
    Buffer scales;                       // 3K uint (float bits): brightest texel per tile, then the largest
                                         // |coefficient| per cascade of two volumes (lpv_common.glsl)
    std::array<Framebuffer, 2> rasterTarget; // [i]: volume[i] (0-2) + accumulator (3-5), layered
    // Directed propagation only (ensureDirected): the averaged VPL normals per
    // cell, ping-pong for the dilation (RGBA32F, N x N x N K), and their
    // fixed-point sums at injection (4 int per cell).
    std::array<Texture, 2> normals;
    Buffer normalSums;
    // Multi-bounce only (ensureBounces): the sum of the bounces propagated so far.
    LpvVolumeSet bounceTotal;
    // Compute gather only (ensureInterleaved): the ping-pong volumes with a
    // cell's R, G, B side by side, 3N x N x NK. The gather's first step reads
    // volume[] (V_0) and writes here; the later steps live here, and
    // lpv_deinterleave.comp unpacks a step the LPV viewer captures.
    std::array<Texture, 2> interleaved;
    // Visibility-aware lookup only (ensureVisibility, docs/lpv.md): per cell
    // and axis a the distance moments (E[d], E[d^2]) toward +a and -a, the
    // three axes side by side like faceBlocking, 3N x N x NK RGBA32F.
    Texture visibility;
  private:
    int gridSize_ = 0;
    int cascades_ = 0;
    std::uint64_t generation_ = 0;
};

} // namespace lpv::renderer
