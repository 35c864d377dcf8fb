#include "passes/lpv/RsmCascades.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace lpv::renderer {

int findSun(const scene::Scene& scene) {
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        if (scene.lights[i].type == scene::LightType::Directional)
            return int(i);
    return -1;
}

LpvCascadeSettings lpvCascadeSettings(const scene::ParameterSet& params, int count, const scene::Bounds& sceneBounds) {
    return LpvCascadeSettings{count,
                              int(params.getInt("lpv.gridSize")),
                              float(params.getFloat("lpv.cellSize")),
                              params.getBool("lpv.cellSnapping"),
                              float(params.getFloat("lpv.viewShift")),
                              params.getBool("lpv.clampToScene") ? sceneBounds : scene::Bounds{}};
}

LpvCascade lpvCascade(const glm::vec3& camera, const glm::vec3& viewDirection, int k,
                      const LpvCascadeSettings& settings) {
    LpvCascade c;
    c.gridSize = std::max(settings.gridSize, 1);
    c.cellSize = std::ldexp(settings.cellSize, k);
    const double extent = double(c.cellSize) * double(c.gridSize);
    const float length = glm::length(viewDirection);
    // At most half the extent less two cells: the camera keeps two cells of
    // its own cascade behind it (the lookup's margin and blend need them), and
    // snapping cannot push cascade k out of cascade k+1.
    const double reach = std::max(0.0, 0.5 * extent - 2.0 * double(c.cellSize));
    const double shift = std::clamp(double(settings.viewShift), 0.0, 1.0) * reach;
    const glm::dvec3 ahead =
        length > 0.0f && std::isfinite(length) ? glm::dvec3(viewDirection / length) * shift : glm::dvec3(0.0);
    glm::dvec3 ideal = glm::dvec3(camera) + ahead - 0.5 * extent;
    if (!settings.sceneBounds.empty()) {
        // The nearest corner to the camera's placement from which the cube
        // covers the most of the scene along each axis: all of it where the
        // cube is larger, else a stretch inside it.
        const glm::dvec3 lo = glm::dvec3(settings.sceneBounds.min), hi = glm::dvec3(settings.sceneBounds.max);
        const glm::dvec3 a = hi - extent, b = lo; // corners whose cube ends at hi, starts at lo
        ideal = glm::clamp(ideal, glm::min(a, b), glm::max(a, b));
    }
    if (settings.snapToCells) {
        // Round (in double, so that far from the origin the corner still lands
        // on a cell) rather than floor: the centre stays within half a cell of
        // where it should be. Cascade k+1 then contains cascade k for gridSize >= 3.
        const double cell = double(c.cellSize);
        c.origin = glm::vec3(glm::round(ideal / cell) * cell);
    } else {
        c.origin = glm::vec3(ideal);
    }
    return c;
}

std::vector<LpvCascade> lpvCascades(const glm::vec3& camera, const glm::vec3& viewDirection,
                                    const LpvCascadeSettings& settings) {
    std::vector<LpvCascade> cascades;
    for (int k = 0; k < settings.cascades; ++k)
        cascades.push_back(lpvCascade(camera, viewDirection, k, settings));
    if (!settings.sceneBounds.empty()) {
        // Clamped at a scene's edge, two cascades can want the same corner,
        // and rounding each to its own cells may then push the finer one out
        // of the coarser by half a coarse cell: move it back in. Cascade k+1's
        // corner lies on cascade k's cells, so k stays snapped.
        for (int k = int(cascades.size()) - 2; k >= 0; --k) {
            const LpvCascade& outer = cascades[std::size_t(k + 1)];
            LpvCascade& inner = cascades[std::size_t(k)];
            inner.origin = glm::clamp(inner.origin, outer.origin,
                                      outer.origin + glm::vec3(outer.extent() - inner.extent()));
        }
    }
    return cascades;
}

LpvCascade lpvCascade(const glm::vec3& camera, int k, const LpvCascadeSettings& settings) {
    return lpvCascade(camera, glm::vec3(0.0f), k, settings);
}

std::vector<LpvCascade> lpvCascades(const glm::vec3& camera, const LpvCascadeSettings& settings) {
    return lpvCascades(camera, glm::vec3(0.0f), settings);
}

glm::mat4 sunView(const glm::vec3& direction) {
    const glm::vec3 dir = glm::normalize(direction);
    const glm::vec3 up = std::abs(dir.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::lookAt(glm::vec3(0.0f), dir, up);
}

scene::Bounds lightSpaceBounds(const glm::mat4& view, const scene::Bounds& box) {
    scene::Bounds out;
    if (box.empty())
        return out;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                               (i & 4) ? box.max.z : box.min.z);
        out.extend(glm::vec3(view * glm::vec4(corner, 1.0f)));
    }
    return out;
}

RsmTile makeRsmTile(const LpvCascade& cascade, const glm::vec3& sunDirection,
                    const scene::Bounds& sceneBounds, int tileSize) {
    RsmTile t;
    t.cascade = cascade;
    t.view = sunView(sunDirection);
    const scene::Bounds cube = lightSpaceBounds(t.view, cascade.bounds());
    const int n = std::max(tileSize, 2);

    // Square texels. The window is one texel wider than the cube's footprint so
    // that snapping its corner to the texel grid (by up to half a texel each
    // way) never uncovers the cube. The texel size depends only on the cube's
    // size and the sun's direction, so it stays fixed while the camera moves.
    const glm::vec3 size = cube.size();
    t.texelSize = std::max(size.x, size.y) / float(n - 1);
    t.texelArea = t.texelSize * t.texelSize;
    const double texel = double(t.texelSize);
    const double half = 0.5 * texel * double(n);
    const glm::dvec2 centre = glm::dvec2(cube.center());
    const glm::dvec2 lo = glm::round((centre - half) / texel) * texel;
    const glm::dvec2 hi = lo + texel * double(n);

    // The sun looks down -z: depth along its rays is -z. Reach back toward the
    // sun to the scene's bounds so casters above the cube occlude it; a margin
    // keeps faces lying exactly on the cube's sides inside.
    const float margin = 0.01f * cascade.extent();
    float nearDepth = -cube.max.z;
    if (const scene::Bounds all = lightSpaceBounds(t.view, sceneBounds); !all.empty())
        nearDepth = std::min(nearDepth, -all.max.z);
    t.nearDepth = nearDepth - margin;
    t.farDepth = -cube.min.z + margin;
    t.windowMin = glm::vec2(lo);
    t.windowMax = glm::vec2(hi);
    t.projection = glm::ortho(float(lo.x), float(hi.x), float(lo.y), float(hi.y), t.nearDepth, t.farDepth);
    t.viewProj = t.projection * t.view;
    return t;
}

glm::mat4 rsmUnionViewProj(const std::vector<RsmTile>& tiles) {
    if (tiles.empty())
        return glm::mat4(1.0f);
    glm::vec2 lo = tiles.front().windowMin, hi = tiles.front().windowMax;
    float nearDepth = tiles.front().nearDepth, farDepth = tiles.front().farDepth;
    for (const RsmTile& t : tiles) {
        lo = glm::min(lo, t.windowMin);
        hi = glm::max(hi, t.windowMax);
        nearDepth = std::min(nearDepth, t.nearDepth);
        farDepth = std::max(farDepth, t.farDepth);
    }
    return glm::ortho(lo.x, hi.x, lo.y, hi.y, nearDepth, farDepth) * tiles.front().view;
}

} // namespace lpv::renderer
