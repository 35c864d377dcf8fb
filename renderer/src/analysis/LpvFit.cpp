#include "lpv/renderer/LpvFit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lpv::renderer {

namespace {

// A length for people: "0.16 m", "2.0 km", "3 mm"; the unit is the
// project's (metres by convention), so this only picks the prefix.
std::string length(double metres) {
    char text[48];
    const double a = std::abs(metres);
    if (a >= 1000.0)
        std::snprintf(text, sizeof text, "%.3g km", metres / 1000.0);
    else if (a >= 1.0 || a == 0.0)
        std::snprintf(text, sizeof text, "%.3g m", metres);
    else if (a >= 0.01)
        std::snprintf(text, sizeof text, "%.3g cm", metres * 100.0);
    else
        std::snprintf(text, sizeof text, "%.3g mm", metres * 1000.0);
    return text;
}

// Half the extent of a cube of `cells` cells of size `cell` less the two
// cells the lookup's margin and cascade blend need: how far from the
// camera (along each axis) the cascade still serves a lookup.
double servedReach(double cell, int cells) { return cell * (0.5 * double(cells) - 2.0); }

// The per-axis distance from `p` to the nearest point of `b` (0 inside): a
// cube around p reaches b when its half extent is more than this.
double nearestAxisDistance(const scene::Bounds& b, const glm::dvec3& p) {
    const glm::dvec3 outside = glm::max(glm::dvec3(b.min) - p, glm::max(p - glm::dvec3(b.max), glm::dvec3(0.0)));
    return std::max({outside.x, outside.y, outside.z});
}

double largestSide(const scene::Bounds& b) {
    const glm::vec3 size = b.size();
    return double(std::max({size.x, size.y, size.z}));
}

// The fit before lpv.refinement.
LpvFit fitUnrefined(const scene::ParameterSet& params, const scene::Bounds& sceneBounds, const glm::vec3& camera) {
    LpvFit fit;
    const int gridSize = params.getInt("lpv.gridSize");
    fit.cascades = std::min(params.getInt("lpv.cascades"), params.getInt("rsm.cascades"));
    fit.steps = params.getInt("lpv.propagationSteps");
    if (!params.isWord("lpv.cellSize", "auto")) {
        fit.cellSize = params.getFloat("lpv.cellSize");
        fit.reason = "cell " + length(fit.cellSize) + " (lpv.cellSize), " + std::to_string(fit.cascades) +
                     " cascades, " + std::to_string(fit.steps) + " steps";
        return fit;
    }
    fit.fitted = true;
    const double side = sceneBounds.empty() ? 0.0 : largestSide(sceneBounds);
    if (!(side > 0.0) || !std::isfinite(side)) {
        // Nothing to light (or a single point): any size serves; 1 keeps the numbers finite.
        fit.cellSize = 1.0;
        fit.reason = "cell 1 m: the scene has no extent to fit to";
        return fit;
    }
    // lpv.cascades and rsm.cascades keep their meaning (4 by default): the
    // fit chooses the sizes, not how many.
    double finest = side / double(kFinestCellsPerScene);
    // The camera far from the scene: double every cascade until the
    // coarsest serves the scene's middle and a quarter of it beyond.
    const glm::dvec3 middle = glm::dvec3(sceneBounds.center());
    const glm::dvec3 offset = glm::abs(middle - glm::dvec3(camera));
    const double needed = std::max({offset.x, offset.y, offset.z}) + 0.25 * side;
    int doublings = 0;
    while (servedReach(std::ldexp(finest, fit.cascades - 1), gridSize) < needed && doublings < 60) {
        finest *= 2.0;
        ++doublings;
    }
    fit.cellSize = finest;
    const double coarsest = std::ldexp(finest, fit.cascades - 1);
    fit.reason = "cell " + length(fit.cellSize) + " (1/" + std::to_string(kFinestCellsPerScene) + " of the " +
                 length(side) + " scene" + (doublings == 0 ? "" : ", x" + std::to_string(1 << std::min(doublings, 30)) +
                                                                     " to reach it from the camera") +
                 "), " + std::to_string(fit.cascades) + (fit.cascades == 1 ? " cascade" : " cascades up to ") +
                 (fit.cascades == 1 ? "" : length(coarsest)) + ", " + std::to_string(fit.steps) + " steps";
    return fit;
}

} // namespace

int refinedGridSize(int gridSize, double refinement) {
    const long cells = std::lround(double(gridSize) * refinement);
    return int(std::clamp<long>(cells, std::min(gridSize, kMinRefinedGridSize), std::max(gridSize, kMaxRefinedGridSize)));
}

int refinedSteps(int steps, double refinement) {
    const long refined = std::lround(double(steps) * refinement);
    return int(std::clamp<long>(refined, steps > 0 ? 1 : 0, std::max(steps, kMaxRefinedSteps)));
}

namespace {

// lpv.refinement on top of the fit (LpvFit.h): finer (or coarser) cells, as
// many more (fewer) of them and steps, so the cascades' extent and light's
// reach stay the same.
LpvFit refined(LpvFit fit, int gridSize) {
    fit.gridSize = refinedGridSize(gridSize, fit.refinement);
    if (fit.refinement == 1.0)
        return fit;
    const double r = fit.refinement;
    fit.cellSize /= r;
    const int steps = refinedSteps(fit.steps, r);
    char factor[32];
    std::snprintf(factor, sizeof factor, "%g", r);
    fit.reason += std::string(", refinement x") + factor + ": cell " + length(fit.cellSize) + ", " +
                  std::to_string(fit.gridSize) + "^3 cells, " + std::to_string(steps) + " steps";
    if (double(fit.gridSize) != double(gridSize) * r || double(steps) != double(fit.steps) * r)
        fit.reason += " (rounded, or capped at lpv.gridSize " + std::to_string(kMinRefinedGridSize) + "-" +
                      std::to_string(kMaxRefinedGridSize) + " and lpv.propagationSteps " +
                      std::to_string(kMaxRefinedSteps) + ")";
    fit.steps = steps;
    return fit;
}

} // namespace

LpvFit fitLpv(const scene::ParameterSet& params, const scene::Bounds& sceneBounds, const glm::vec3& camera) {
    LpvFit fit = fitUnrefined(params, sceneBounds, camera);
    fit.refinement = double(params.getFloat("lpv.refinement"));
    return refined(std::move(fit), params.getInt("lpv.gridSize"));
}

scene::ParameterSet withFit(const scene::ParameterSet& params, const LpvFit& fit) {
    const bool refinedFit = fit.refinement != 1.0;
    if (!fit.fitted && !refinedFit)
        return params;
    scene::ParameterSet out = params;
    // The registry's range holds every fit (1e-6 .. 1e6 m); a scene beyond
    // it is refused at load (ValueChecks' kMaxLength bounds every length).
    (void)out.set("lpv.cellSize", std::clamp(fit.cellSize, 1e-6, 1e6));
    if (refinedFit) {
        (void)out.set("lpv.gridSize", fit.gridSize);
        (void)out.set("lpv.propagationSteps", fit.steps);
    }
    return out;
}

LpvDelivery lpvDelivery(const LpvFit& fit, int gridSize, const scene::Bounds& sceneBounds, const glm::vec3& camera) {
    using Problem = LpvDelivery::Problem;
    if (sceneBounds.empty() || !(fit.cellSize > 0.0) || fit.cascades < 1)
        return {};
    const glm::dvec3 eye = glm::dvec3(camera);
    const double coarsestCell = std::ldexp(fit.cellSize, fit.cascades - 1);
    const double served = servedReach(coarsestCell, refinedGridSize(gridSize, fit.refinement));
    const double nearest = nearestAxisDistance(sceneBounds, eye);
    if (nearest > served)
        return {Problem::OutsideCascades, "the scene lies outside every cascade: the coarsest reaches " +
                                              length(served) + " from the camera, the scene starts " +
                                              length(nearest) + " away"};
    if (fit.steps == 0)
        return {Problem::NoSteps, "lpv.propagationSteps is 0: light stays in the cells it was injected into"};
    // Light travels `steps` cells of a cascade. Where even the coarsest
    // carries it less than 1/8 of the scene, little of it reaches another
    // surface: a single cascade whose steps carried light a quarter of the
    // Cornell box's side kept 3% of its indirect light (docs/lpv.md's
    // measurements); the fit's coarsest carries it 0.4 of the scene.
    const double side = largestSide(sceneBounds);
    const double reach = double(fit.steps) * coarsestCell;
    if (reach < side / 8.0)
        return {Problem::ShortReach, "light travels at most " + length(reach) + " (" + std::to_string(fit.steps) +
                                         " steps of " + length(coarsestCell) + " cells), under 1/8 of the " +
                                         length(side) + " scene: little reaches another surface"};
    return {};
}

std::string fitNote(const LpvFit& fit, const LpvDelivery& delivery) {
    std::string note = fit.fitted           ? "; fitted: " + fit.reason
                       : fit.refinement != 1.0 ? "; " + fit.reason
                                            : std::string();
    if (delivery.problem != LpvDelivery::Problem::None && !delivery.skipsLpv())
        note += "; warning: almost no indirect light: " + delivery.reason;
    return note;
}

} // namespace lpv::renderer
