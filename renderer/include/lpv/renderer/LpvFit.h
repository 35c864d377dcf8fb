#pragma once
// Fitting the LPV to the scene it lights (issue #41): with lpv.cellSize =
// auto the finest cell size, the cascade count and the propagation steps
// come from lengths the scene has, not from constants in metres, so the
// same scene in centimetres, in metres or 100 km from the origin gets the
// same cells relative to its size and the same indirect light.
//
// The length that matters is how far light travels between surfaces: the
// scene's mean free path, estimated by Cauchy's mean chord 4V/A (V the
// volume of the scene's bounds, A the area of its visible triangles; exact
// for the chords of a convex room, 2/3 of the side for a closed cube). The
// finest cells are a fixed fraction of it and the steps let light cross
// it; the cascades double until the coarsest holds the whole scene around
// the camera. docs/lpv.md, "The LPV fitted to the scene", has the figures.
#include "lpv/scene/ParameterRegistry.h"
#include "lpv/scene/Scene.h"

#include <glm/glm.hpp>

#include <string>

namespace lpv::renderer {

// Lengths of a scene that do not depend on its unit.
struct SceneScale {
    scene::Bounds bounds;
    double surfaceArea = 0.0;  // visible triangles, world space, one side counted
    double meanFreePath = 0.0; // 4 V / A of the bounds' box; 0 for an empty scene
};
SceneScale measureSceneScale(const scene::Scene& scene);

// Finest cells per mean free path, and the propagation steps that carry
// light across one mean free path of the finest cascade.
inline constexpr double kCellsPerFreePath = 8.0;

struct LpvFit {
    bool fitted = false;   // lpv.cellSize = auto (else the numbers below are the parameters')
    double cellSize = 0.0; // of the finest cascade, world units
    int cascades = 1;
    int steps = 0;
    bool stepsFitted = false;    // false: lpv.propagationSteps was set
    bool cascadesFitted = false; // false: lpv.cascades was set
    // One line for `lpv render`'s LPV line, --explain and the Effects dock:
    // "cell 0.16 m (1/8 of the 1.2 m mean free path), 2 cascades to hold the 2.0 m scene, 8 steps".
    std::string reason;
};

// The fit for a frame whose camera stands at `camera`. A number in
// lpv.cellSize forces it (the fit then only reports the parameters); set
// lpv.cascades or lpv.propagationSteps force those alone.
LpvFit fitLpv(const scene::ParameterSet& params, const SceneScale& scale, const glm::vec3& camera);

// `params` with the fit written in (lpv.cellSize, and lpv.cascades,
// rsm.cascades, lpv.propagationSteps where fitted): what every pass of the
// frame reads. Unchanged when the fit is not fitted.
scene::ParameterSet withFit(const scene::ParameterSet& params, const LpvFit& fit);

// Whether an LPV with these cascades delivers light to the view; when it
// cannot (almost) at all, why: the scene lies outside every cascade (the
// analysis then skips the LPV: its passes would add nothing), no step
// propagates, or light crosses too small a part of the mean free path.
// The cascades are cubes of `gridSize` cells of cellSize * 2^k around `camera`.
struct LpvDelivery {
    enum class Problem { None, OutsideCascades, NoSteps, ShortReach };
    Problem problem = Problem::None;
    std::string reason; // empty for None
    bool skipsLpv() const { return problem == Problem::OutsideCascades; }
};
LpvDelivery lpvDelivery(const LpvFit& fit, int gridSize, const SceneScale& scale, const glm::vec3& camera);

} // namespace lpv::renderer
