#pragma once
// Reflective shadow maps (Dachsbacher & Stamminger 2005): per texel the world
// position, normal and reflected flux of what the sun sees, one tile per LPV
// cascade (RsmCascades.h). The LPV injection reads them as virtual point lights.
//
// All tiles render in one pass: rsm.geom runs one invocation per tile and
// routes each triangle to its layer of 2D array targets (layer k = tile k).
// Targets:
//   position  RGBA32F  world xyz, w = 1 where a surface was seen, 0 elsewhere.
//             32-bit, not half: a half float has 11 significant bits, i.e.
//             1.5 cm steps 30 m from the origin and 12 cm at 250 m, enough to
//             put a VPL into the neighbouring LPV cell of a fine cascade.
//   normal    RGBA16F  world normal turned toward the sun (0.05 degree steps).
//   flux      RGBA32F  reflected flux of the texel in W (rgb); a = 1 + the
//             material's translucency (the subsurface LPV injects texels with
//             a > 1; a stays non-zero where a surface was seen). Half floats keep
//             3 significant digits down to 6e-5 W per texel; below (a dim sun
//             on millimetre cells) they lose precision.
//   depth     DEPTH_COMPONENT32F.
// 36 bytes per texel: 9 MiB for the default 4 tiles of 256^2, 216 MiB for
// 6 tiles of 1024^2.
#include "frame/FrameContext.h"
#include "scenegpu/MaterialGpu.h"
#include "passes/lpv/RsmCascades.h"
#include "passes/lpv/RsmTargets.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/renderer/SceneGpu.h"
#include "lpv/scene/Error.h"

#include <array>
#include <vector>

namespace lpv::renderer {

// The GL limits the RSM targets must fit.
struct RsmTargetLimits {
    int maxTextureSize = 0;       // GL_MAX_TEXTURE_SIZE
    int maxArrayLayers = 0;       // GL_MAX_ARRAY_TEXTURE_LAYERS
    int maxFramebufferLayers = 0; // GL_MAX_FRAMEBUFFER_LAYERS
    int maxFramebufferSize = 0;   // min(GL_MAX_FRAMEBUFFER_WIDTH, GL_MAX_FRAMEBUFFER_HEIGHT)

    static RsmTargetLimits query(); // of the current context
};

// An error value naming the parameter when `tiles` tiles of tileSize^2 do not fit `limits`.
scene::Expected<void> checkRsmTargets(int tileSize, int tiles, const RsmTargetLimits& limits);

class RsmPass {
  public:
    static scene::Expected<RsmPass> create();

    // Renders every tile of this frame. Without a directional
    // light it renders nothing and frees its targets.
    scene::Expected<void> render(const FrameContext& frame, const SceneGpu& geometry,
                                 const MaterialGpu& materials);
    // The same with the cascades given (rsm.cascades of them, as the LPV
    // places them this frame, lpv.viewShift included).
    scene::Expected<void> render(const FrameContext& frame, const SceneGpu& geometry, const MaterialGpu& materials,
                                 const std::vector<LpvCascade>& cascades);

    // Frees the targets and renders nothing until the next render() (gi.method = off).
    void release() {
        sunIndex_ = -1;
        tiles_.clear();
        releaseTargets();
    }

    // Position, normal and flux of every tile of the last frame:
    // "rsm-K-position", "rsm-K-normal", "rsm-K-flux" (4 floats per texel).
    std::vector<DebugImage> debugImages() const;

    // --- For the LPV injection (valid after render(), while active()) ---
    bool active() const { return sunIndex_ >= 0 && !tiles_.empty(); }
    int sunIndex() const { return sunIndex_; }
    int tileSize() const { return targets_.size(); }
    // One per LPV cascade: its cube, the tile's matrices and texel size/area.
    const std::vector<RsmTile>& tiles() const { return tiles_; }
    // 2D array textures, layer k = tile k (formats above).
    GLuint positionArray() const { return targets_.position(); }
    GLuint normalArray() const { return targets_.normal(); }
    GLuint fluxArray() const { return targets_.flux(); }
    GLuint depthArray() const { return targets_.depth(); }
    // GPU memory held by the targets (0 when there is no sun).
    std::size_t allocatedBytes() const { return targets_.bytes(); }

  private:
    RsmPass() = default;
    scene::Expected<void> ensureTargets(int tileSize, int layers);
    // The program whose geometry shader runs `tiles` invocations (built on first use).
    scene::Expected<GLuint> programFor(int tiles);
    void releaseTargets();

    std::array<Program, kMaxRsmCascades> programs_; // [k] renders k + 1 tiles
    // rsm.tileDraws = perTile: one draw per tile through rsm.vert alone (RSM_NO_GEOMETRY_SHADER).
    scene::Expected<GLuint> perTileProgram();
    Program perTileProgram_;
    int sunIndex_ = -1;
    std::vector<RsmTile> tiles_;
    RsmTargets targets_;
};

} // namespace lpv::renderer
