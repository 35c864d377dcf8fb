// The Cornell box as measured by the Cornell Program of Computer Graphics
// (https://www.graphics.cornell.edu/online/box/data.html). Coordinates there
// are millimetres; we scale by 1/100 so the box is 5.5 units across, a
// room-sized interior that suits the LPV defaults (32 cells of 0.25 m).
// Reflectances are the usual RGB reductions of the measured spectra.
#include "lpv/scene/CornellBox.h"

#include <array>
#include <cmath>
#include <numbers>

namespace lpv::scene {
namespace {

constexpr float kScale = 0.01f;
using Quad = std::array<glm::vec3, 4>;

// Appends quads (corners in order around the face) as a submesh of one material.
void addQuads(Mesh& mesh, const std::vector<Quad>& quads, std::uint32_t material) {
    Submesh sub;
    sub.firstIndex = std::uint32_t(mesh.indices.size());
    sub.materialIndex = material;
    for (const Quad& q : quads) {
        const std::uint32_t base = std::uint32_t(mesh.positions.size());
        glm::vec3 n = glm::normalize(glm::cross(q[1] - q[0], q[2] - q[0]));
        for (const glm::vec3& p : q) {
            mesh.positions.push_back(p * kScale);
            mesh.normals.push_back(n);
        }
        mesh.uvs.insert(mesh.uvs.end(), {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
        const glm::vec3 t = glm::normalize(q[1] - q[0]);
        for (int i = 0; i < 4; ++i)
            mesh.tangents.emplace_back(t, 1.0f);
        mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    sub.indexCount = std::uint32_t(mesh.indices.size()) - sub.firstIndex;
    mesh.submeshes.push_back(sub);
}

// The published data lists some faces clockwise as seen from inside the
// box; orient every quad so its normal points towards `inside`.
Quad facing(Quad q, const glm::vec3& inside) {
    const glm::vec3 n = glm::cross(q[1] - q[0], q[2] - q[0]);
    const glm::vec3 c = 0.25f * (q[0] + q[1] + q[2] + q[3]);
    if (glm::dot(n, inside - c) < 0.0f)
        std::swap(q[1], q[3]);
    return q;
}

// Block side faces must point away from the block centre.
Quad outward(Quad q, const glm::vec3& blockCenter) {
    const glm::vec3 c = 0.25f * (q[0] + q[1] + q[2] + q[3]);
    return facing(q, c + (c - blockCenter));
}

Material diffuse(std::string name, glm::vec3 albedo) {
    Material m;
    m.name = std::move(name);
    m.diffuseColor = albedo;
    m.specularColor = glm::vec3(0.0f);
    return m;
}

} // namespace

Project makeCornellBoxProject() {
    Project project;
    project.name = "cornell-box";
    Scene& scene = project.scene;

    scene.materials = {
        diffuse("white", {0.725f, 0.71f, 0.68f}),
        diffuse("red", {0.63f, 0.065f, 0.05f}),
        diffuse("green", {0.14f, 0.45f, 0.091f}),
        diffuse("light", {0.78f, 0.78f, 0.78f}),
    };
    scene.materials[3].emissive = {17.0f, 12.0f, 4.0f};

    const glm::vec3 inside(278.0f, 274.4f, 279.6f);
    Mesh room;
    room.name = "room";
    addQuads(room,
             {facing({{{552.8f, 0, 0}, {0, 0, 0}, {0, 0, 559.2f}, {549.6f, 0, 559.2f}}}, inside),             // floor
              facing({{{556, 548.8f, 0}, {556, 548.8f, 559.2f}, {0, 548.8f, 559.2f}, {0, 548.8f, 0}}}, inside), // ceiling
              facing({{{549.6f, 0, 559.2f}, {0, 0, 559.2f}, {0, 548.8f, 559.2f}, {556, 548.8f, 559.2f}}}, inside)}, // back
             0);
    addQuads(room, {facing({{{552.8f, 0, 0}, {549.6f, 0, 559.2f}, {556, 548.8f, 559.2f}, {556, 548.8f, 0}}}, inside)},
             1); // left wall, red
    addQuads(room, {facing({{{0, 0, 559.2f}, {0, 0, 0}, {0, 548.8f, 0}, {0, 548.8f, 559.2f}}}, inside)},
             2); // right wall, green

    Mesh shortBlock;
    shortBlock.name = "shortBlock";
    const glm::vec3 shortCenter(186.0f, 82.5f, 168.5f);
    addQuads(shortBlock,
             {outward({{{130, 165, 65}, {82, 165, 225}, {240, 165, 272}, {290, 165, 114}}}, shortCenter),
              outward({{{290, 0, 114}, {290, 165, 114}, {240, 165, 272}, {240, 0, 272}}}, shortCenter),
              outward({{{130, 0, 65}, {130, 165, 65}, {290, 165, 114}, {290, 0, 114}}}, shortCenter),
              outward({{{82, 0, 225}, {82, 165, 225}, {130, 165, 65}, {130, 0, 65}}}, shortCenter),
              outward({{{240, 0, 272}, {240, 165, 272}, {82, 165, 225}, {82, 0, 225}}}, shortCenter)},
             0);

    Mesh tallBlock;
    tallBlock.name = "tallBlock";
    const glm::vec3 tallCenter(368.5f, 165.0f, 351.5f);
    addQuads(tallBlock,
             {outward({{{423, 330, 247}, {265, 330, 296}, {314, 330, 456}, {472, 330, 406}}}, tallCenter),
              outward({{{423, 0, 247}, {423, 330, 247}, {472, 330, 406}, {472, 0, 406}}}, tallCenter),
              outward({{{472, 0, 406}, {472, 330, 406}, {314, 330, 456}, {314, 0, 456}}}, tallCenter),
              outward({{{314, 0, 456}, {314, 330, 456}, {265, 330, 296}, {265, 0, 296}}}, tallCenter),
              outward({{{265, 0, 296}, {265, 330, 296}, {423, 330, 247}, {423, 0, 247}}}, tallCenter)},
             0);

    // The light quad sits a hair below the ceiling so it is not z-fighting it.
    Mesh lightQuad;
    lightQuad.name = "light";
    addQuads(lightQuad, {facing({{{343, 548.7f, 227}, {343, 548.7f, 332}, {213, 548.7f, 332}, {213, 548.7f, 227}}}, inside)},
             3);

    scene.meshes = {room, shortBlock, tallBlock, lightQuad};
    for (int i = 0; i < int(scene.meshes.size()); ++i)
        scene.objects.push_back(Object{scene.meshes[std::size_t(i)].name, i, -1, Transform{}, true, {}});

    // The lamp as published: a 130 x 105 mm rectangle in the plane of the
    // visible light quad, facing down, emitting radiance (17, 12, 4) W/(m^2 sr)
    // from its lower side only. The quad above stays its visible surface; it is
    // not injected as well (lpv.emissive is off by default), so the lamp counts once.
    Light light;
    light.name = "ceilingLight";
    light.type = LightType::Area;
    light.shape = AreaShape::Rectangle;
    light.position = glm::vec3(278.0f, 548.7f, 279.5f) * kScale;
    light.direction = {0.0f, -1.0f, 0.0f};
    light.tangent = {1.0f, 0.0f, 0.0f};
    light.size = glm::vec2(130.0f, 105.0f) * kScale;
    light.color = glm::vec3(17.0f, 12.0f, 4.0f) / 17.0f;
    light.intensity = 17.0f;
    light.unit = AreaUnit::Radiance;
    scene.lights.push_back(light);

    // The published camera: 35 mm focal length on a 25 mm film.
    Camera cam;
    cam.name = "default";
    cam.position = glm::vec3(278.0f, 273.0f, -800.0f) * kScale;
    cam.target = glm::vec3(278.0f, 273.0f, 0.0f) * kScale;
    cam.fovY = 2.0f * std::atan(12.5f / 35.0f);
    cam.nearPlane = 0.1f;
    cam.farPlane = 30.0f;
    scene.cameras.push_back(cam);

    scene.sky.color = glm::vec3(0.0f);
    scene.sky.intensity = 0.0f; // closed box: no sky light

    // No LPV settings of its own (issue #41): lpv.cellSize = auto fits the
    // cells to the box, and the registry's offsets serve it as they serve
    // an imported copy of it, which renders the same.
    // No exposure of its own: auto exposure (the default) meters the box.
    return project;
}

} // namespace lpv::scene
