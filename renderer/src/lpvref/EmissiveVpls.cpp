#include "lpv/renderer/lpv/EmissiveVpls.h"
#include "lpvref/SceneTriangles.h"

#include "lpv/scene/AreaLight.h"

#include <algorithm>
#include <cmath>

namespace lpv::renderer::lpvref {

namespace {

bool emits(const scene::Material& m) {
    return std::max({m.emissive.r, m.emissive.g, m.emissive.b}) > 0.0f;
}

struct EmissiveTriangle {
    glm::vec3 a, b, c, normal, radiance;
    float area;
};

// Calls `visit` with each emissive triangle (world space) that is not an area
// light's visible surface, until it returns false.
template <class Visit>
void forEachEmissiveTriangle(const scene::Scene& scene, float worldMagnitude, Visit&& visit) {
    detail::forEachWorldTriangle(
        scene,
        [&](std::uint32_t material) { return material < scene.materials.size() && emits(scene.materials[material]); },
        [&](const detail::WorldTriangle& t) {
            if (scene::liesOnAnAreaLight(scene.lights, t.a, t.b, t.c, worldMagnitude))
                return true; // an area light's visible surface: injected as that light
            return bool(visit(EmissiveTriangle{t.a, t.b, t.c, t.normal, scene.materials[t.material].emissive, t.area}));
        });
}

std::vector<EmissiveTriangle> emissiveTriangles(const scene::Scene& scene, float worldMagnitude) {
    std::vector<EmissiveTriangle> out;
    forEachEmissiveTriangle(scene, worldMagnitude, [&](const EmissiveTriangle& t) {
        out.push_back(t);
        return true;
    });
    return out;
}

int subdivisions(float area, float spacing) {
    return std::max(1, int(std::ceil(std::sqrt(area) / spacing)));
}

} // namespace

// Asked every frame by the scene analysis: stops at the first emitter, allocates nothing.
bool sceneHasEmissiveSurface(const scene::Scene& scene, float worldMagnitude) {
    bool found = false;
    forEachEmissiveTriangle(scene, worldMagnitude, [&](const EmissiveTriangle&) {
        found = true;
        return false;
    });
    return found;
}

std::vector<Vpl> sampleEmissiveVpls(const scene::Scene& scene, float spacing, int maxVpls, float worldMagnitude) {
    const std::vector<EmissiveTriangle> triangles = emissiveTriangles(scene, worldMagnitude);
    if (triangles.empty() || maxVpls <= 0)
        return {};
    // Coarser until it fits: each triangle keeps at least one VPL, so the cap can still be passed by the
    // triangle count.
    for (;;) {
        std::size_t count = 0;
        for (const EmissiveTriangle& t : triangles)
            count += std::size_t(subdivisions(t.area, spacing)) * std::size_t(subdivisions(t.area, spacing));
        if (count <= std::size_t(maxVpls) || count == triangles.size())
            break;
        spacing *= 1.25f;
    }
    std::vector<Vpl> vpls;
    for (const EmissiveTriangle& t : triangles) {
        const int m = subdivisions(t.area, spacing);
        const glm::vec3 flux = sh::kPi * t.radiance * (t.area / float(m * m));
        auto add = [&](float u, float v) {
            vpls.push_back(
                {t.a + (u / float(m)) * (t.b - t.a) + (v / float(m)) * (t.c - t.a), t.normal, flux});
        };
        detail::forEachSubTriangleCentroid(m, add);
    }
    return vpls;
}

} // namespace lpv::renderer::lpvref
