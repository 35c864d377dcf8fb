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
    // Allocates for N cells per axis, K cascades and `bands` SH bands (2 or
    // 3, lpv.shBands), or names the parameter that does not fit the GPU
    // (texture size, buffer size, memory). Three bands (the compute gather
    // only) allocate no per-channel ping-pong volumes and no raster targets:
    // their steps live in the interleaved volumes, and band 2 in the *High
    // textures (docs/lpv.md, "Memory layout").
    scene::Expected<void> ensure(int gridSize, int cascades, int bands = 2);
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
    int bands() const { return bands_; }
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
    // cell's R, G, B side by side, 3N x N x NK (three bands: 7N, a cell's
    // low R, G, B, high R, G, B and last rgb). The gather's first step reads
    // volume[] (V_0) and writes here; the later steps live here, and
    // lpv_deinterleave.comp unpacks a step the LPV viewer captures.
    std::array<Texture, 2> interleaved;
    // Visibility-aware lookup only (ensureVisibility, docs/lpv.md): per cell
    // and axis a the distance moments (E[d], E[d^2]) toward +a and -a, the
    // three axes side by side like faceBlocking, 3N x N x NK RGBA32F.
    Texture visibility;
    // Three bands only: band 2 of the accumulator, 4N x N x NK (planes high
    // R, G, B = Y2-2..Y21 and last rgb = Y22 side by side along x, so the
    // lookup filters each alone); of the GV, 2(N+1) x (N+1) x (N+1)K (a GV
    // cell's high and last side by side); and of the face blocking, 6N x N x
    // NK (face a of cell x at 6x + 2a and 6x + 2a + 1).
    Texture accumulatorHigh;
    Texture geometryHigh;
    Texture faceBlockingHigh;
  private:
    int bands_ = 2;
    int gridSize_ = 0;
    int cascades_ = 0;
    std::uint64_t generation_ = 0;
};

} // namespace lpv::renderer
