#include "lpv/radiosity/DirectLight.h"

#include "ParallelChunks.h"

#include "lpv/reference/EmbreeScene.h"
#include "lpv/reference/PathTracer.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lpv::radiosity {

std::vector<glm::vec3> patchSamplePoints(const Patch& patch, int count) {
    const int k = std::max(1, int(std::ceil(std::sqrt(double(std::max(count, 1))))));
    std::vector<glm::vec3> points;
    points.reserve(std::size_t(k * k));
    const glm::vec3* c = patch.corners.data();
    for (int j = 0; j < k; ++j) {
        for (int i = 0; i < k; ++i) {
            const float u = (float(i) + 0.5f) / float(k), v = (float(j) + 0.5f) / float(k);
            if (patch.cornerCount == 4) {
                points.push_back((1 - u) * (1 - v) * c[0] + u * (1 - v) * c[1] + u * v * c[2] +
                                 (1 - u) * v * c[3]);
            } else {
                // Uniform on the triangle: (1 - sqrt(u), sqrt(u) (1 - v), sqrt(u) v).
                const float s = std::sqrt(u);
                points.push_back((1 - s) * c[0] + s * (1 - v) * c[1] + s * v * c[2]);
            }
        }
    }
    return points;
}

scene::Expected<std::vector<glm::vec3>> directLight(const PatchMesh& mesh, const scene::Scene& scene,
                                                    const scene::TextureImages& textures, int samplesPerPatch,
                                                    const std::atomic<bool>* cancel) {
    std::vector<glm::vec3> out(mesh.size(), glm::vec3(0.0f));
    if (scene.lights.empty() || mesh.size() == 0)
        return out;
    auto embree = reference::EmbreeScene::build(scene, textures);
    if (!embree)
        return std::unexpected(embree.error());
    // Only the light model is used: no camera, no pixels.
    const reference::PathTracer tracer(*embree, scene, scene::Camera{}, reference::PathTracerSettings{});
    forEachChunk(
        mesh.size(), 256,
        [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                const Patch& p = mesh.patches[i];
                const std::vector<glm::vec3> points = patchSamplePoints(p, samplesPerPatch);
                glm::vec3 sum(0.0f);
                // Each point seeds its own area-light sample (directIrradiance without a
                // generator is seeded by the point): different points, different samples.
                for (const glm::vec3& q : points)
                    sum += tracer.directIrradiance(q, p.normal, p.normal);
                out[i] = glm::max(sum / (float(points.size()) * std::numbers::pi_v<float>), glm::vec3(0.0f));
            }
        },
        cancel);
    if (cancel && cancel->load())
        return scene::makeError(scene::ErrorCode::Cancelled, "radiosity", "direct light",
                                "cancelled while the lights' direct light was computed");
    return out;
}

} // namespace lpv::radiosity
