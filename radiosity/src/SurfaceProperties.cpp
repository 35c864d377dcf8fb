#include "lpv/radiosity/SurfaceProperties.h"

#include "lpv/scene/AreaLight.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lpv::radiosity {
namespace {

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

glm::vec3 textureAverage(const std::string& path, const scene::TextureImages& textures) {
    if (path.empty())
        return glm::vec3(1.0f);
    const auto it = textures.find(path);
    return it == textures.end() ? glm::vec3(1.0f) : averageLinearColor(it->second);
}

} // namespace

glm::vec3 averageLinearColor(const scene::Image8& image) {
    const std::size_t count = std::size_t(image.width) * std::size_t(image.height);
    if (count == 0 || image.channels < 1 || image.pixels.size() < count * std::size_t(image.channels))
        return glm::vec3(1.0f);
    // A lookup table: 256 pow() calls instead of one per texel.
    std::array<float, 256> linear{};
    for (int i = 0; i < 256; ++i)
        linear[std::size_t(i)] = srgbToLinear(float(i) / 255.0f);
    glm::dvec3 sum(0.0);
    const std::size_t ch = std::size_t(image.channels);
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint8_t* px = &image.pixels[i * ch];
        if (ch >= 3)
            sum += glm::dvec3(linear[px[0]], linear[px[1]], linear[px[2]]);
        else
            sum += glm::dvec3(linear[px[0]]);
    }
    return glm::vec3(sum / double(count));
}

std::vector<glm::vec3> materialReflectances(const scene::Scene& scene, const scene::TextureImages& textures) {
    std::vector<glm::vec3> out;
    for (const scene::Material& m : scene.materials) {
        // Below 1 in every channel, or a closed scene would never converge.
        out.push_back(glm::clamp(m.diffuseColor * textureAverage(m.diffuseTexture, textures), 0.0f, 0.999f));
    }
    return out;
}

std::vector<glm::vec3> materialEmissions(const scene::Scene& scene, const scene::TextureImages& textures) {
    std::vector<glm::vec3> out;
    for (const scene::Material& m : scene.materials)
        out.push_back(glm::max(m.emissive * textureAverage(m.emissiveTexture, textures), glm::vec3(0.0f)));
    return out;
}

SurfaceProperties surfaceProperties(const PatchMesh& mesh, const scene::Scene& scene,
                                    const scene::TextureImages& textures) {
    const auto reflect = materialReflectances(scene, textures);
    const auto emit = materialEmissions(scene, textures);
    SurfaceProperties out;
    out.reflectance.reserve(mesh.size());
    out.emission.reserve(mesh.size());
    for (const Patch& p : mesh.patches) {
        const bool known = p.material < reflect.size();
        out.reflectance.push_back(known ? reflect[p.material] : glm::vec3(0.5f));
        // A lamp's visible surface (the Cornell light quad) is its area light,
        // which shoots as a light: emitting here too would count it twice, as
        // the LPV's emissive VPLs and the reference's emitters also avoid.
        const bool lamp = scene::liesOnAnAreaLight(scene.lights, p.corners[0], p.corners[1], p.corners[2]);
        out.emission.push_back(known && !lamp ? emit[p.material] : glm::vec3(0.0f));
    }
    return out;
}

} // namespace lpv::radiosity
