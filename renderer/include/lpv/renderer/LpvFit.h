#pragma once
// Fitting the LPV to the scene it lights (issue #41): with lpv.cellSize =
// auto the finest cell size, the cascade count and the propagation steps
// come from the scene's size and where the camera stands, not from
// constants in metres, so the same scene in millimetres, in metres or
// 100 km from the origin gets the same cells relative to its size and the
// same indirect light.
//
// The rule: the finest cascade has cells of 1/160 of the scene's largest
// side (what 0.25 m, the default of the metre-scale scenes, is to Sponza's
// and Sibenik's 35-40 m); each of the lpv.cascades (4) doubles them, so
// the coarsest (cells of 1/20) serves 0.7 of the scene around the camera,
// and its 8 steps carry light 0.4 of the way across. Camera-centred
// cascades serve surfaces at distance r with cells of about r/14, so the
// view gets cells fitted to its distance. When the camera stands far from
// the scene (a box framed from outside), every cascade doubles until the
// coarsest serves the scene's middle and a quarter of it beyond. Cells
// counted from the scene's bounds' corner (RenderSpace.h) put the walls
// of a box on cell faces. docs/lpv.md, "The LPV fitted to the scene", has
// the measurements behind it.
#include "lpv/scene/ParameterRegistry.h"
#include "lpv/scene/Scene.h"

#include <glm/glm.hpp>

#include <string>

namespace lpv::renderer {

// Finest cells per scene side (the scene's largest bounds side).
inline constexpr int kFinestCellsPerScene = 160;

// lpv.refinement r (issue #47's convergence question): on top of the fit
// (or a forced size) the cells are 1/r the size, r times as many along each
// axis (lpv.gridSize, rounded, 8 to 128) and the steps r times
// lpv.propagationSteps (rounded, at most 64), so each cascade covers the
// same space and light travels the same distance in finer (r > 1) or
// coarser (r < 1) steps.
inline constexpr int kMinRefinedGridSize = 8;   // lpv.gridSize's minimum
inline constexpr int kMaxRefinedGridSize = 128; // lpv.gridSize's maximum
inline constexpr int kMaxRefinedSteps = 64;     // lpv.propagationSteps' maximum
int refinedGridSize(int gridSize, double refinement);
int refinedSteps(int steps, double refinement);

struct LpvFit {
    bool fitted = false;   // lpv.cellSize = auto (else the numbers below are the parameters')
    double cellSize = 0.0; // of the finest cascade, world units (refined)
    int cascades = 1;      // lpv.cascades, as far as rsm.cascades has tiles
    int steps = 0;         // lpv.propagationSteps (refined)
    double refinement = 1.0; // lpv.refinement
    int gridSize = 0;      // lpv.gridSize (refined)
    // One line for `lpv render`'s LPV line, --explain and the Effects dock:
    // "cell 5.08 cm (1/160 of the 2.03 m scene, x4 to reach it from the camera), 4 cascades up to 40.6 cm, 8 steps".
    std::string reason;
};

// The fit for a frame whose camera stands at `camera`. A number in
// lpv.cellSize forces it (the fit then only reports the parameters).
// `sceneBounds` in the same space as `camera`.
LpvFit fitLpv(const scene::ParameterSet& params, const scene::Bounds& sceneBounds, const glm::vec3& camera);

// `params` with the fitted lpv.cellSize written in (and, refined, the
// refined lpv.cellSize, lpv.gridSize and lpv.propagationSteps): what every
// pass of the frame reads. Unchanged when neither fitted nor refined.
scene::ParameterSet withFit(const scene::ParameterSet& params, const LpvFit& fit);

// Whether an LPV with these cascades delivers light to the view; when it
// cannot (almost) at all, why: the scene lies outside every cascade (the
// analysis then skips the LPV: its passes would add nothing), no step
// propagates, or even the coarsest cascade carries light less than 1/8 of
// the way across the scene.
// The cascades are cubes of `gridSize` cells of cellSize * 2^k around
// `camera`; `gridSize` is lpv.gridSize as the parameters give it, which the
// fit's refinement multiplies (refinedGridSize).
struct LpvDelivery {
    enum class Problem { None, OutsideCascades, NoSteps, ShortReach };
    Problem problem = Problem::None;
    std::string reason; // empty for None
    bool skipsLpv() const { return problem == Problem::OutsideCascades; }
};
LpvDelivery lpvDelivery(const LpvFit& fit, int gridSize, const scene::Bounds& sceneBounds, const glm::vec3& camera);

// What the LPV line (`lpv render`, the Effects dock) and the scene analysis
// (`--explain`) append for a running LPV: "; fitted: <reason>" when fitted,
// "; warning: almost no indirect light: <why>" when it delivers little.
std::string fitNote(const LpvFit& fit, const LpvDelivery& delivery);

} // namespace lpv::renderer
