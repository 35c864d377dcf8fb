#include "lpv/radiosity/RayCastFormFactors.h"

#include "lpv/radiosity/DirectLight.h"
#include "lpv/reference/EmbreeScene.h"

#include "ParallelChunks.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lpv::radiosity {
namespace {

struct ShooterSamples {
    std::vector<glm::vec3>
        points; // in Embree's frame, already lifted off the shooter (EmbreeScene::offsetWorldPoint)
    glm::vec3 normal{0.0f};
    float pieceArea = 0.0f; // A_i / S
    float area = 0.0f;
};

} // namespace

scene::Expected<std::unique_ptr<RayCastFormFactors>>
RayCastFormFactors::create(const PatchMesh& mesh, const scene::Scene& scene,
                           const scene::TextureImages& textures, int samples, int batch) {
    auto embree = reference::EmbreeScene::build(scene, textures);
    if (!embree)
        return std::unexpected(embree.error());
    return std::unique_ptr<RayCastFormFactors>(
        new RayCastFormFactors(mesh, std::make_unique<reference::EmbreeScene>(std::move(*embree)),
                               std::max(samples, 1), std::max(batch, 1)));
}

RayCastFormFactors::RayCastFormFactors(const PatchMesh& mesh, std::unique_ptr<reference::EmbreeScene> embree,
                                       int samples, int batch)
    : mesh_(mesh), embree_(std::move(embree)), samples_(samples), batch_(batch) {}

RayCastFormFactors::~RayCastFormFactors() = default;

scene::Expected<void> RayCastFormFactors::compute(std::span<const std::uint32_t> shooters,
                                                  std::vector<float>& factors) {
    const std::size_t n = mesh_.size();
    factors.assign(shooters.size() * n, 0.0f);
    std::vector<ShooterSamples> shots(shooters.size());
    for (std::size_t s = 0; s < shooters.size(); ++s) {
        if (shooters[s] >= n)
            return scene::makeError(scene::ErrorCode::IndexOutOfRange, "radiosity", "raycast form factors",
                                    "shooter " + std::to_string(shooters[s]) + " of " + std::to_string(n));
        const Patch& p = mesh_.patches[shooters[s]];
        ShooterSamples& out = shots[s];
        for (const glm::vec3& q : patchSamplePoints(p, samples_))
            out.points.push_back(embree_->offsetWorldPoint(q, p.normal));
        out.normal = p.normal;
        out.area = p.area;
        out.pieceArea = p.area / float(out.points.size());
    }
    constexpr float kPi = std::numbers::pi_v<float>;
    forEachChunk(n, 512, [&](std::size_t begin, std::size_t end) {
        for (std::size_t j = begin; j < end; ++j) {
            const Patch& r = mesh_.patches[j];
            const glm::vec3 origin = embree_->offsetWorldPoint(r.center, r.normal);
            for (std::size_t s = 0; s < shots.size(); ++s) {
                if (shooters[s] == j)
                    continue;
                const ShooterSamples& sh = shots[s];
                float sum = 0.0f;
                for (const glm::vec3& q : sh.points) {
                    const glm::vec3 d = q - origin;
                    const float r2 = glm::dot(d, d);
                    if (!(r2 > 0.0f))
                        continue;
                    const float dist = std::sqrt(r2);
                    const glm::vec3 dir = d / dist;
                    const float cosReceiver = glm::dot(r.normal, dir);
                    const float cosShooter = -glm::dot(sh.normal, dir);
                    if (cosReceiver <= 0.0f || cosShooter <= 0.0f)
                        continue;
                    if (embree_->occluded(origin, dir, 0.0f, dist * (1.0f - 1e-4f)))
                        continue;
                    sum += cosReceiver * cosShooter * sh.pieceArea / (kPi * r2 + sh.pieceArea);
                }
                if (sum > 0.0f)
                    factors[s * n + j] = sum * r.area / sh.area;
            }
        }
    });
    // A receiver's centre stands for all of it: a large patch right beside a
    // shooter can be credited more than the shooter sends. No shooter gives
    // away more than it has.
    for (std::size_t s = 0; s < shots.size(); ++s) {
        float* row = &factors[s * n];
        double total = 0.0;
        for (std::size_t j = 0; j < n; ++j)
            total += row[j];
        if (total > 1.0)
            for (std::size_t j = 0; j < n; ++j)
                row[j] = float(row[j] / total);
    }
    return {};
}

} // namespace lpv::radiosity
