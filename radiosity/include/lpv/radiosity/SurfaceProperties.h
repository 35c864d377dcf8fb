#pragma once
// What the solver needs from materials: per patch, the diffuse reflectance
// (diffuse colour times the average of its texture, in linear RGB) and the
// emitted radiance (emissive colour times its texture's average; 0 on an area
// light's visible surface, which shoots as that light).
#include "lpv/radiosity/PatchMesh.h"
#include "lpv/scene/Image.h"
#include "lpv/scene/Scene.h"

#include <vector>

namespace lpv::radiosity {

struct SurfaceProperties {
    std::vector<glm::vec3> reflectance; // per patch, each channel in [0, 0.999]
    std::vector<glm::vec3> emission;    // per patch, radiance
};

// Linear-RGB average of an sRGB-encoded image (alpha ignored); 1 for an empty image.
glm::vec3 averageLinearColor(const scene::Image8& image);

// Per material: diffuse colour x texture average (textures missing from `textures` count as white).
std::vector<glm::vec3> materialReflectances(const scene::Scene& scene, const scene::TextureImages& textures);
std::vector<glm::vec3> materialEmissions(const scene::Scene& scene, const scene::TextureImages& textures);

SurfaceProperties surfaceProperties(const PatchMesh& mesh, const scene::Scene& scene,
                                    const scene::TextureImages& textures);

} // namespace lpv::radiosity
