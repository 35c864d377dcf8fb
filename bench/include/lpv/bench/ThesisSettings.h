#pragma once
// `lpv bench render --thesis-settings` (issue #25): the settings, view and
// phase grouping under which the thesis application (djbozkosz, raster
// gather, its fastest) was measured beside us on a 2-core llvmpipe machine,
// so later changes compare with those figures like for like.
#include "lpv/bench/Timing.h"
#include "lpv/renderer/GpuTimer.h"
#include "lpv/scene/Camera.h"
#include "lpv/scene/Error.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lpv::bench {

inline constexpr int kThesisWidth = 1024;
inline constexpr int kThesisHeight = 600;

// 4 LPV cascades of 32^3, RSM tiles of 128^2, 6 shadow cascades of 1024^2,
// 8 propagation steps, as KEY=VALUE (a later --set wins).
std::vector<std::string> thesisSettingsSets();

// The thesis application's start camera in our coordinates: at (-2.2, 5.7,
// 4.3), pitched 5 degrees down, looking along +x (its engine.cpp sets
// rotation (5, -90, 0) degrees and a 60 degree vertical field of view).
scene::Camera thesisStartCamera();

// One phase as the thesis application times it, with our passes summed
// into it and the thesis application's figure. Ours is over timing rounds:
// in each round the phase's passes' medians summed, then the median and
// quartiles of those sums (issue #43).
struct ThesisPhase {
    std::string name;
    std::string ourPasses; // which of our passes it sums
    TimingStats ours;
    std::optional<double> thesisMs;
};

// The thesis application's median per phase (ms) and where they come from.
// Its figures are only comparable with ours from the same machine on the same
// day (this 2-core VM's speed moves by 1.2x from day to day), so the table
// takes them from tools/thesis-app/run.sh's output of this session when given.
struct ThesisFigures {
    std::optional<double> shadowMaps, rsm, injection, propagation, finalShading, wholeFrame, lpvOff;
    std::string source; // for the table's footer
};

// The figures of issue #25's day (another day's machine: an old baseline).
ThesisFigures issue25ThesisFigures();

// tools/thesis-app/run.sh's output: its "phase NAME MS" lines (shadow_maps,
// rsm, lpv_clear, injection, propagation, final_shading, whole_frame,
// lpv_off_whole_frame); other lines are ignored. Its injection is lpv_clear
// plus injection, as the tables in the README sum it (our injection clears
// its volumes in its own pass). An error names the line it could not read,
// or says that no whole_frame line was found.
scene::Expected<ThesisFigures> parseThesisRun(std::string_view text, std::string source);

// shadow maps | RSM | injection | propagation | final shading | whole frame,
// then the whole frame with the LPV off when `lpvOff` is given. `rounds`
// holds the per-pass table of each timing round (medians over its frames).
std::vector<ThesisPhase> thesisPhases(const std::vector<std::vector<renderer::PassTiming>>& rounds,
                                      std::optional<TimingStats> lpvOff,
                                      const ThesisFigures& figures = issue25ThesisFigures());

// The table, its footer naming where the thesis figures come from.
std::string formatThesisPhases(const std::vector<ThesisPhase>& phases,
                               const std::string& thesisSource = issue25ThesisFigures().source);

} // namespace lpv::bench
