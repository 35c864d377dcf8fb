#pragma once
// Small analytic scenes for the radiosity tests: unit squares and boxes made
// of quads (two triangles each, as importers deliver them).
#include "lpv/radiosity/FormFactors.h"
#include "lpv/radiosity/PatchMesh.h"
#include "lpv/scene/Scene.h"

#include <gtest/gtest.h>

#include <array>

namespace lpv::test {

// Adds one object whose mesh is the quad `c` (any winding), turned so its
// front faces along `normal`.
inline void addQuad(scene::Scene& s, std::array<glm::vec3, 4> c, const glm::vec3& normal,
                    std::uint32_t material) {
    if (glm::dot(glm::cross(c[1] - c[0], c[2] - c[0]), normal) < 0.0f)
        std::swap(c[1], c[3]);
    scene::Mesh mesh;
    mesh.positions = {c[0], c[1], c[2], c[3]};
    mesh.normals.assign(4, normal);
    mesh.indices = {0, 1, 2, 0, 2, 3};
    mesh.submeshes = {{0, 6, material}};
    s.meshes.push_back(std::move(mesh));
    scene::Object o;
    o.mesh = int(s.meshes.size() - 1);
    s.objects.push_back(o);
}

inline scene::Material material(const glm::vec3& diffuse, const glm::vec3& emissive = glm::vec3(0.0f)) {
    scene::Material m;
    m.diffuseColor = diffuse;
    m.emissive = emissive;
    return m;
}

// Two unit squares facing each other at distance 1 (analytic F = 0.1998):
// object 0 at z = 0, object 1 at z = 1.
inline scene::Scene parallelSquares() {
    scene::Scene s;
    s.materials = {material(glm::vec3(0.5f))};
    addQuad(s, {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}}, {0, 0, 1}, 0);
    addQuad(s, {{{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}}, {0, 0, -1}, 0);
    return s;
}

// Two unit squares sharing the edge x = y = 0 at 90 degrees (analytic F = 0.2000).
inline scene::Scene perpendicularSquares() {
    scene::Scene s;
    s.materials = {material(glm::vec3(0.5f))};
    addQuad(s, {{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}}, {0, 1, 0}, 0);
    addQuad(s, {{{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}}, {1, 0, 0}, 0);
    return s;
}

// A closed unit box seen from inside; material 0 on the walls, material 1
// (emissive) on the ceiling (y = 1).
inline scene::Scene closedBox(const glm::vec3& wallReflectance, const glm::vec3& ceilingEmission) {
    scene::Scene s;
    s.materials = {material(wallReflectance), material(wallReflectance, ceilingEmission)};
    addQuad(s, {{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}}, {0, 1, 0}, 0);
    addQuad(s, {{{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}}}, {0, -1, 0}, 1);
    addQuad(s, {{{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}}, {1, 0, 0}, 0);
    addQuad(s, {{{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}}, {-1, 0, 0}, 0);
    addQuad(s, {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}}, {0, 0, 1}, 0);
    addQuad(s, {{{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}}, {0, 0, -1}, 0);
    return s;
}

// A closed unit box with a smaller box floating inside it (faces outward), so
// the walls hide parts of each other.
inline scene::Scene boxWithBlock() {
    auto s = closedBox(glm::vec3(0.6f), glm::vec3(1.0f));
    const glm::vec3 lo(0.3f, 0.2f, 0.35f), hi(0.6f, 0.5f, 0.65f);
    addQuad(s, {{{lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}}},
                  {0, 1, 0}, 0);
    addQuad(s, {{{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z}}},
                  {0, -1, 0}, 0);
    addQuad(s, {{{lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, {lo.x, lo.y, hi.z}}},
                  {-1, 0, 0}, 0);
    addQuad(s, {{{hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {hi.x, lo.y, hi.z}}},
                  {1, 0, 0}, 0);
    addQuad(s, {{{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}}},
                  {0, 0, -1}, 0);
    addQuad(s, {{{lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}}},
                  {0, 0, 1}, 0);
    return s;
}

// `source`'s form factors as a function of the shooters (objectFormFactor's
// `compute`); a failed compute is a test failure and an empty row.
inline auto computeWith(radiosity::FormFactorSource& source) {
    return [&source](const std::vector<std::uint32_t>& shooters) {
        std::vector<float> out;
        const auto ok = source.compute(shooters, out);
        EXPECT_TRUE(ok.has_value()) << ok.error().describe();
        return out;
    };
}

// Area-weighted form factor from object `from` to object `to`, out of
// per-shooter factors for every patch of `from` (rows in patch order).
template <class ComputeFn>
double objectFormFactor(const radiosity::PatchMesh& mesh, std::uint32_t from, std::uint32_t to,
                        ComputeFn&& compute) {
    std::vector<std::uint32_t> shooters;
    double area = 0.0;
    for (std::uint32_t i = 0; i < mesh.size(); ++i)
        if (mesh.patches[i].object == from) {
            shooters.push_back(i);
            area += mesh.patches[i].area;
        }
    const std::vector<float> factors = compute(shooters);
    double sum = 0.0;
    for (std::size_t s = 0; s < shooters.size(); ++s) {
        double row = 0.0;
        for (std::uint32_t j = 0; j < mesh.size(); ++j)
            if (mesh.patches[j].object == to)
                row += factors[s * mesh.size() + j];
        sum += row * mesh.patches[shooters[s]].area;
    }
    return sum / area;
}

} // namespace lpv::test
