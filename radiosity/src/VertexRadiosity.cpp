#include "lpv/radiosity/VertexRadiosity.h"

namespace lpv::radiosity {

std::vector<glm::vec3> cornerValues(const PatchMesh& mesh, std::span<const glm::vec3> perPatch, bool smooth) {
    constexpr float kSameSide = 0.9f; // cos of ~25 degrees
    std::vector<glm::vec3> out(mesh.size() * 4, glm::vec3(0.0f));
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const Patch& p = mesh.patches[i];
        for (int k = 0; k < 4; ++k) {
            const int corner = std::min(k, p.cornerCount - 1);
            if (!smooth || mesh.vertexPatchOffsets.empty()) {
                out[4 * i + std::size_t(k)] = perPatch[i];
                continue;
            }
            const std::uint32_t v = p.vertices[std::size_t(corner)];
            glm::vec3 sum(0.0f);
            float weight = 0.0f;
            for (std::uint32_t e = mesh.vertexPatchOffsets[v]; e < mesh.vertexPatchOffsets[v + 1]; ++e) {
                const std::uint32_t q = mesh.vertexPatches[e];
                const Patch& other = mesh.patches[q];
                if (glm::dot(other.normal, p.normal) < kSameSide || other.material != p.material)
                    continue;
                sum += perPatch[q] * other.area;
                weight += other.area;
            }
            out[4 * i + std::size_t(k)] = weight > 0.0f ? sum / weight : perPatch[i];
        }
    }
    return out;
}

} // namespace lpv::radiosity
