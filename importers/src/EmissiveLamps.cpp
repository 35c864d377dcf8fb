#include "EmissiveLamps.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

namespace lpv::importers {
namespace {

struct Panel {
    std::vector<glm::vec3> vertices; // unique world positions
    glm::vec3 normal{0.0f};          // the emitting side
    float area = 0.0f;
    float extent = 0.0f;
};

// The world-space triangles of one submesh of one object, as a candidate panel.
std::optional<Panel> collectPanel(const scene::Scene& s, int object, const scene::Mesh& mesh, const scene::Submesh& sub) {
    const glm::mat4 world = s.worldMatrix(object);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
    Panel p;
    glm::vec3 normalSum(0.0f), shadingSum(0.0f);
    std::vector<glm::vec3> all;
    for (std::uint32_t t = sub.firstIndex; t + 2 < sub.firstIndex + sub.indexCount; t += 3) {
        glm::vec3 v[3];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t i = mesh.indices[t + std::uint32_t(k)];
            if (i >= mesh.positions.size())
                return std::nullopt;
            v[k] = glm::vec3(world * glm::vec4(mesh.positions[i], 1.0f));
            if (mesh.normals.size() == mesh.positions.size())
                shadingSum += normalMatrix * mesh.normals[i];
            all.push_back(v[k]);
        }
        const glm::vec3 cross = glm::cross(v[1] - v[0], v[2] - v[0]);
        p.area += 0.5f * glm::length(cross);
        normalSum += cross; // area-weighted; opposite windings would cancel (then not a panel)
    }
    if (all.empty() || !(p.area > 0.0f) || !(glm::length(normalSum) > 0.5f * 2.0f * p.area))
        return std::nullopt; // empty, degenerate, or triangles facing both ways
    p.normal = glm::normalize(normalSum);
    if (glm::dot(shadingSum, p.normal) < 0.0f)
        p.normal = -p.normal; // the emitting side is the one the shading normals face
    glm::vec3 lo(all[0]), hi(all[0]);
    for (const glm::vec3& v : all) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    p.extent = glm::length(hi - lo);
    const float merge = 1e-5f * p.extent;
    for (const glm::vec3& v : all)
        if (std::none_of(p.vertices.begin(), p.vertices.end(),
                         [&](const glm::vec3& u) { return glm::length(u - v) <= merge; }))
            p.vertices.push_back(v);
    // Flat: every vertex within a thousandth of the extent of the plane.
    for (const glm::vec3& v : p.vertices)
        if (std::abs(glm::dot(v - p.vertices[0], p.normal)) > 1e-3f * p.extent)
            return std::nullopt;
    return p;
}

// A rectangle: the tightest box in the plane, over the directions of the
// vertex pairs, has the triangles' area.
bool asRectangle(const Panel& p, scene::Light& light) {
    if (p.vertices.size() != 4)
        return false;
    float bestArea = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = i + 1; j < 4; ++j) {
            const glm::vec3 u = glm::normalize(p.vertices[j] - p.vertices[i]);
            const glm::vec3 w = glm::normalize(glm::cross(p.normal, u));
            float u0 = 1e30f, u1 = -1e30f, w0 = 1e30f, w1 = -1e30f;
            for (const glm::vec3& v : p.vertices) {
                u0 = std::min(u0, glm::dot(v, u));
                u1 = std::max(u1, glm::dot(v, u));
                w0 = std::min(w0, glm::dot(v, w));
                w1 = std::max(w1, glm::dot(v, w));
            }
            const float area = (u1 - u0) * (w1 - w0);
            if (area < bestArea) {
                bestArea = area;
                const float h = glm::dot(p.vertices[0], p.normal);
                light.position = u * (0.5f * (u0 + u1)) + w * (0.5f * (w0 + w1)) + p.normal * h;
                light.tangent = u;
                light.size = {u1 - u0, w1 - w0};
            }
        }
    light.shape = scene::AreaShape::Rectangle;
    return std::abs(bestArea - p.area) <= 0.01f * p.area;
}

// A disc: the outline's vertices lie on one circle around their centre, and
// the triangles' area is that of a polygon inscribed in it.
bool asDisc(const Panel& p, scene::Light& light) {
    if (p.vertices.size() < 8)
        return false;
    glm::vec3 centre(0.0f);
    float far = 0.0f;
    for (const glm::vec3& v : p.vertices)
        centre += v;
    centre /= float(p.vertices.size());
    for (const glm::vec3& v : p.vertices)
        far = std::max(far, glm::length(v - centre));
    int rim = 0;
    for (const glm::vec3& v : p.vertices) {
        const float r = glm::length(v - centre);
        if (r < 0.01f * far)
            continue; // a fan's centre vertex
        if (std::abs(r - far) > 0.01f * far)
            return false;
        ++rim;
    }
    const float circle = std::numbers::pi_v<float> * far * far;
    if (rim < 8 || p.area < 0.9f * circle || p.area > circle)
        return false;
    light.shape = scene::AreaShape::Disc;
    light.position = centre;
    light.radius = std::sqrt(p.area / std::numbers::pi_v<float>); // the same area
    light.size = glm::vec2(2.0f * light.radius);
    light.tangent = glm::normalize(p.vertices[0] - centre);
    return true;
}

std::string metres(float v) {
    std::ostringstream s;
    s.precision(3);
    s << v;
    return s.str();
}

} // namespace

int addAreaLightsForEmissivePanels(scene::Scene& s, std::vector<std::string>& notes) {
    int added = 0;
    const std::size_t objects = s.objects.size();
    for (std::size_t o = 0; o < objects; ++o) {
        const scene::Object& object = s.objects[o];
        if (!object.visible || object.mesh < 0 || std::size_t(object.mesh) >= s.meshes.size())
            continue;
        const scene::Mesh& mesh = s.meshes[std::size_t(object.mesh)];
        for (const scene::Submesh& sub : mesh.submeshes) {
            if (sub.materialIndex >= s.materials.size())
                continue;
            const scene::Material& m = s.materials[sub.materialIndex];
            const float brightest = std::max({m.emissive.r, m.emissive.g, m.emissive.b});
            if (!(brightest > 0.0f) || !std::isfinite(brightest) || !m.emissiveTexture.empty())
                continue; // not emitting, or not uniformly (a textured emitter stays a surface)
            const auto panel = collectPanel(s, int(o), mesh, sub);
            if (!panel)
                continue;
            scene::Light light;
            light.type = scene::LightType::Area;
            if (!asRectangle(*panel, light) && !asDisc(*panel, light))
                continue;
            light.name = "lamp " + m.name;
            light.direction = panel->normal;
            light.color = m.emissive / brightest;
            light.intensity = brightest;
            light.unit = scene::AreaUnit::Radiance;
            s.lights.push_back(light);
            ++added;
            notes.push_back("object '" + object.name + "', material '" + m.name + "': a flat emissive " +
                            (light.shape == scene::AreaShape::Disc ? "disc of radius " + metres(light.radius)
                                                                    : metres(light.size.x) + " x " + metres(light.size.y)) +
                            " became the area light '" + light.name + "' (its surface stays visible, counted once)");
        }
    }
    return added;
}

} // namespace lpv::importers
