#include "lpv/renderer/lpv/EmissiveVpls.h"
#include "lpv/scene/WorldMatrices.h"

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
void forEachEmissiveTriangle(const scene::Scene& scene, Visit&& visit) {
    const std::vector<glm::mat4> worlds = scene::worldMatrices(scene); // linear in any parent chain
    for (int o = 0; o < int(scene.objects.size()); ++o) {
        const scene::Object& object = scene.objects[std::size_t(o)];
        if (!object.visible || object.mesh < 0 || std::size_t(object.mesh) >= scene.meshes.size())
            continue;
        const scene::Mesh& mesh = scene.meshes[std::size_t(object.mesh)];
        const glm::mat4 world = worlds[std::size_t(o)];
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
        for (const scene::Submesh& sub : mesh.submeshes) {
            if (sub.materialIndex >= scene.materials.size() || !emits(scene.materials[sub.materialIndex]))
                continue;
            for (std::uint32_t t = sub.firstIndex; t + 2 < sub.firstIndex + sub.indexCount; t += 3) {
                const std::uint32_t i[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
                const glm::vec3 a(world * glm::vec4(mesh.positions[i[0]], 1.0f));
                const glm::vec3 b(world * glm::vec4(mesh.positions[i[1]], 1.0f));
                const glm::vec3 c(world * glm::vec4(mesh.positions[i[2]], 1.0f));
                const glm::vec3 cross = glm::cross(b - a, c - a);
                const float length = glm::length(cross);
                if (!(length > 0.0f))
                    continue; // degenerate: no area, no light
                if (scene::liesOnAnAreaLight(scene.lights, a, b, c))
                    continue; // an area light's visible surface: injected as that light
                glm::vec3 n = cross / length;
                // The emitting side is the one the shading normals face (the winding may disagree).
                if (mesh.normals.size() == mesh.positions.size()) {
                    const glm::vec3 shading =
                        normalMatrix * (mesh.normals[i[0]] + mesh.normals[i[1]] + mesh.normals[i[2]]);
                    if (glm::dot(shading, n) < 0.0f)
                        n = -n;
                }
                if (!visit(EmissiveTriangle{a, b, c, n, scene.materials[sub.materialIndex].emissive, 0.5f * length}))
                    return;
            }
        }
    }
}

std::vector<EmissiveTriangle> emissiveTriangles(const scene::Scene& scene) {
    std::vector<EmissiveTriangle> out;
    forEachEmissiveTriangle(scene, [&](const EmissiveTriangle& t) {
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
bool sceneHasEmissiveSurface(const scene::Scene& scene) {
    bool found = false;
    forEachEmissiveTriangle(scene, [&](const EmissiveTriangle&) {
        found = true;
        return false;
    });
    return found;
}

std::vector<Vpl> sampleEmissiveVpls(const scene::Scene& scene, float spacing, int maxVpls) {
    const std::vector<EmissiveTriangle> triangles = emissiveTriangles(scene);
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
        // Centroids of the m^2 sub-triangles: m (m + 1) / 2 upright, m (m - 1) / 2 upside down.
        for (int i = 0; i < m; ++i)
            for (int j = 0; i + j < m; ++j) {
                add(float(i) + 1.0f / 3.0f, float(j) + 1.0f / 3.0f);
                if (i + j < m - 1)
                    add(float(i) + 2.0f / 3.0f, float(j) + 2.0f / 3.0f);
            }
    }
    return vpls;
}

} // namespace lpv::renderer::lpvref
