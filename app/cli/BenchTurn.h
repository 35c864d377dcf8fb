#pragma once
// `lpv bench render --turn DEG` (issue #25): the frame where only the camera
// turned. The camera yaws by +DEG and -DEG about the world's up axis on
// alternate frames, with the frame graph's reuse on as in the editor, so
// what does not depend on the view direction (the LPV's cascades follow the
// camera's position, the RSM tiles follow the cascades: the whole LPV, issue
// #48) is kept and what does (shadow cascades fitted to the view, the
// camera's G-buffer, shading; the geometry volume too with
// lpv.geometrySource=views, and the LPV with lpv.viewShift > 0) is redrawn.
// The table lists the passes that ran and those the graph reused.
#include "RenderSetup.h"

#include <string>
#include <vector>

namespace lpv::cli {

struct TurnFrames {
    std::vector<double> frameTotalsMs; // per timed frame: every pass that ran, summed
    // Per pass: its times over the frames it ran in (reused passes have none).
    std::vector<std::pair<std::string, std::vector<double>>> passMs;
    // Per pass the frame graph kept (its report's status Reused): in how many
    // timed frames, and the reason of the last one (issue #48: what a turn reuses).
    struct Reused {
        std::string pass;
        int frames = 0;
        std::string reason;
    };
    std::vector<Reused> reused;
};

// Renders `warmup` then `frames` frames turning by +-degrees, one frame at a
// time so each frame's passes are summed on their own; false (message
// printed) on error. The setup's camera is left where it started.
bool renderTurnFrames(RenderSetup& setup, int width, int height, int warmup, int frames, float degrees,
                      TurnFrames& out);

// The per-pass table (median over the frames a pass ran, how many it ran in),
// the passes the frame graph reused and in how many frames, and the median
// whole frame.
std::string formatTurnFrames(const TurnFrames& turn, float degrees);

} // namespace lpv::cli
