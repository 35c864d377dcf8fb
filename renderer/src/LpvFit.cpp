#include "lpv/renderer/LpvFit.h"

#include "lpv/scene/WorldMatrices.h"

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

// Largest per-axis distance from `p` to a point of `b` (a cube around p
// holds b when its half extent is at least this), and the smallest.
double farthestAxisDistance(const scene::Bounds& b, const glm::dvec3& p) {
    const glm::dvec3 lo = glm::dvec3(b.min) - p, hi = glm::dvec3(b.max) - p;
    const glm::dvec3 far = glm::max(glm::abs(lo), glm::abs(hi));
    return std::max({far.x, far.y, far.z});
}
double nearestAxisDistance(const scene::Bounds& b, const glm::dvec3& p) {
    const glm::dvec3 outside = glm::max(glm::dvec3(b.min) - p, glm::max(p - glm::dvec3(b.max), glm::dvec3(0.0)));
    return std::max({outside.x, outside.y, outside.z});
}

} // namespace

SceneScale measureSceneScale(const scene::Scene& scene) {
    SceneScale s;
    const std::vector<glm::mat4> worlds = scene::worldMatrices(scene);
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const scene::Object& obj = scene.objects[o];
        if (!obj.visible || obj.mesh < 0 || std::size_t(obj.mesh) >= scene.meshes.size())
            continue;
        const scene::Mesh& mesh = scene.meshes[std::size_t(obj.mesh)];
        const glm::dmat4 m = glm::dmat4(worlds[o]);
        auto world = [&](std::uint32_t i) { return glm::dvec3(m * glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0)); };
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
            if (a >= mesh.positions.size() || b >= mesh.positions.size() || c >= mesh.positions.size())
                continue;
            const glm::dvec3 pa = world(a), pb = world(b), pc = world(c);
            s.surfaceArea += 0.5 * glm::length(glm::cross(pb - pa, pc - pa));
            s.bounds.extend(glm::vec3(pa));
            s.bounds.extend(glm::vec3(pb));
            s.bounds.extend(glm::vec3(pc));
        }
    }
    if (s.bounds.empty() || !(s.surfaceArea > 0.0) || !std::isfinite(s.surfaceArea))
        return s;
    // A flat scene (a ground plane, a single wall) has no volume: give its
    // box a thickness of 1% of its largest side, so the free path stays a
    // length of the scene rather than 0.
    glm::dvec3 size = glm::dvec3(s.bounds.size());
    const double largest = std::max({size.x, size.y, size.z});
    size = glm::max(size, glm::dvec3(0.01 * largest));
    s.meanFreePath = 4.0 * size.x * size.y * size.z / s.surfaceArea;
    // Never longer than the box itself (a few small objects in a big empty box).
    s.meanFreePath = std::min(s.meanFreePath, largest);
    return s;
}

LpvFit fitLpv(const scene::ParameterSet& params, const SceneScale& scale, const glm::vec3& camera) {
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
    if (!(scale.meanFreePath > 0.0)) {
        // Nothing to light: any size serves; 1 keeps the numbers finite.
        fit.cellSize = 1.0;
        fit.reason = "cell 1 m: the scene has no visible surface to fit to";
        return fit;
    }
    fit.cellSize = scale.meanFreePath / kCellsPerFreePath;
    fit.stepsFitted = !params.isSet("lpv.propagationSteps");
    if (fit.stepsFitted)
        fit.steps = int(kCellsPerFreePath);
    // Cascades: double the cells until the coarsest serves the whole scene
    // around the camera, at most lpv.cascades' upper bound (6). When even
    // that cannot, the cells grow instead, so no part of the scene goes
    // without indirect light.
    fit.cascadesFitted = !params.isSet("lpv.cascades") && !params.isSet("rsm.cascades");
    const glm::dvec3 eye = glm::dvec3(camera);
    const double farthest = farthestAxisDistance(scale.bounds, eye);
    constexpr int kMaxCascades = 6;
    if (fit.cascadesFitted) {
        fit.cascades = 1;
        while (fit.cascades < kMaxCascades &&
               servedReach(std::ldexp(fit.cellSize, fit.cascades - 1), gridSize) < farthest)
            ++fit.cascades;
        const double coarsest = servedReach(std::ldexp(fit.cellSize, fit.cascades - 1), gridSize);
        if (coarsest < farthest)
            fit.cellSize *= farthest / coarsest;
    }
    const double sceneSize = double(std::max({scale.bounds.size().x, scale.bounds.size().y, scale.bounds.size().z}));
    fit.reason = "cell " + length(fit.cellSize) + " (1/" + std::to_string(int(kCellsPerFreePath)) + " of the " +
                 length(scale.meanFreePath) + " mean free path), " + std::to_string(fit.cascades) +
                 (fit.cascades == 1 ? " cascade" : " cascades") +
                 (fit.cascadesFitted ? " to hold the " + length(sceneSize) + " scene around the view"
                                     : " (lpv.cascades)") +
                 ", " + std::to_string(fit.steps) + " steps" + (fit.stepsFitted ? "" : " (lpv.propagationSteps)");
    return fit;
}

scene::ParameterSet withFit(const scene::ParameterSet& params, const LpvFit& fit) {
    if (!fit.fitted)
        return params;
    scene::ParameterSet out = params;
    // The registry's range holds every fit (1e-6 .. 1e6 m); a scene beyond
    // it is refused at load (ValueChecks' kMaxLength bounds every length).
    const double cell = std::clamp(fit.cellSize, 1e-6, 1e6);
    (void)out.set("lpv.cellSize", cell);
    if (fit.cascadesFitted) {
        (void)out.set("lpv.cascades", fit.cascades);
        (void)out.set("rsm.cascades", fit.cascades);
    }
    if (fit.stepsFitted)
        (void)out.set("lpv.propagationSteps", fit.steps);
    return out;
}

LpvDelivery lpvDelivery(const LpvFit& fit, int gridSize, const SceneScale& scale, const glm::vec3& camera) {
    using Problem = LpvDelivery::Problem;
    if (scale.bounds.empty() || !(fit.cellSize > 0.0) || fit.cascades < 1)
        return {};
    const glm::dvec3 eye = glm::dvec3(camera);
    const double coarsestCell = std::ldexp(fit.cellSize, fit.cascades - 1);
    const double served = servedReach(coarsestCell, gridSize);
    const double nearest = nearestAxisDistance(scale.bounds, eye);
    if (nearest > served)
        return {Problem::OutsideCascades, "the scene lies outside every cascade: the coarsest reaches " +
                                              length(served) + " from the camera, the scene starts " +
                                              length(nearest) + " away"};
    // Light travels `steps` cells of a cascade. Where even the coarsest
    // carries it less than half a mean free path, little of it reaches
    // another surface (measured: the Cornell box keeps 3% of its light at
    // 0.4 mean free paths, docs/lpv.md).
    const double reach = double(fit.steps) * coarsestCell;
    if (fit.steps == 0)
        return {Problem::NoSteps, "lpv.propagationSteps is 0: light stays in the cells it was injected into"};
    if (scale.meanFreePath > 0.0 && reach < 0.5 * scale.meanFreePath)
        return {Problem::ShortReach, "light travels at most " + length(reach) + " (" + std::to_string(fit.steps) +
                                         " steps of " + length(coarsestCell) + " cells), under half the " +
                                         length(scale.meanFreePath) +
                                         " between the scene's surfaces: little reaches another surface"};
    return {};
}

} // namespace lpv::renderer
