#include "lpv/radiosity/ProgressiveSolver.h"

#include <algorithm>
#include <numeric>

namespace lpv::radiosity {
namespace {

double channelSum(const glm::dvec3& v) {
    return v.x + v.y + v.z;
}

} // namespace

ProgressiveSolver::ProgressiveSolver(const PatchMesh& mesh, SurfaceProperties surfaces)
    : mesh_(mesh), surfaces_(std::move(surfaces)) {
    state_.radiosity = surfaces_.emission;
    state_.unshot = surfaces_.emission;
    state_.incident.assign(mesh_.size(), glm::vec3(0.0f));
    state_.direct.assign(mesh_.size(), glm::vec3(0.0f));
    for (std::size_t i = 0; i < mesh_.size(); ++i)
        state_.balance.emitted += glm::dvec3(surfaces_.emission[i]) * double(mesh_.patches[i].area);
}

scene::Expected<void> ProgressiveSolver::addDirectLight(std::vector<glm::vec3> direct) {
    if (direct.size() != mesh_.size())
        return scene::makeError(scene::ErrorCode::InvalidValue, "", "radiosity",
                                "direct light for " + std::to_string(direct.size()) + " patches, the mesh has " +
                                    std::to_string(mesh_.size()));
    for (std::size_t i = 0; i < mesh_.size(); ++i) {
        const glm::dvec3 rho(surfaces_.reflectance[i]);
        const double area = mesh_.patches[i].area;
        // Take back what an earlier call added, then add the new light.
        const glm::dvec3 change = glm::dvec3(direct[i]) - glm::dvec3(state_.direct[i]);
        const glm::vec3 reflected(rho * change);
        state_.radiosity[i] = glm::max(state_.radiosity[i] + reflected, glm::vec3(0.0f));
        state_.unshot[i] = glm::max(state_.unshot[i] + reflected, glm::vec3(0.0f));
        state_.balance.emitted += change * area;
        state_.balance.absorbed += change * (glm::dvec3(1.0) - rho) * area;
    }
    state_.direct = std::move(direct);
    return {};
}

scene::Expected<void> ProgressiveSolver::restore(SolverState state) {
    if (state.incident.empty())
        state.incident.assign(state.radiosity.size(), glm::vec3(0.0f));
    if (state.direct.empty())
        state.direct.assign(state.radiosity.size(), glm::vec3(0.0f));
    if (state.radiosity.size() != mesh_.size() || state.unshot.size() != mesh_.size() ||
        state.incident.size() != mesh_.size() || state.direct.size() != mesh_.size())
        return scene::makeError(scene::ErrorCode::InvalidValue, "", "radiosity",
                                "the saved solution has " + std::to_string(state.radiosity.size()) +
                                    " patches, the mesh " + std::to_string(mesh_.size()));
    state_ = std::move(state);
    return {};
}

glm::dvec3 ProgressiveSolver::unshotPower() const {
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < mesh_.size(); ++i)
        sum += glm::dvec3(state_.unshot[i]) * double(mesh_.patches[i].area);
    return sum;
}

double ProgressiveSolver::residual() const {
    const double emitted = channelSum(state_.balance.emitted);
    return emitted > 0.0 ? channelSum(unshotPower()) / emitted : 0.0;
}

std::vector<std::uint32_t> ProgressiveSolver::pickShooters(int count) const {
    std::vector<std::uint32_t> order;
    std::vector<float> power(mesh_.size());
    for (std::uint32_t i = 0; i < mesh_.size(); ++i) {
        const glm::vec3& u = state_.unshot[i];
        power[i] = (u.x + u.y + u.z) * mesh_.patches[i].area;
        if (power[i] > 0.0f)
            order.push_back(i);
    }
    const std::size_t n = std::min(order.size(), std::size_t(std::max(count, 1)));
    std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(n), order.end(),
                      [&](std::uint32_t a, std::uint32_t b) { return power[a] > power[b]; });
    order.resize(n);
    return order;
}

scene::Expected<int> ProgressiveSolver::step(FormFactorSource& formFactors, int shooters) {
    const std::vector<std::uint32_t> picked = pickShooters(shooters);
    if (picked.empty())
        return 0;
    if (auto ok = formFactors.compute(picked, factors_); !ok)
        return std::unexpected(ok.error());
    const std::size_t n = mesh_.size();
    // All shooters of a batch shoot what they had before it; light they
    // receive from each other waits for a later batch.
    std::vector<glm::vec3> shot(picked.size());
    for (std::size_t s = 0; s < picked.size(); ++s) {
        shot[s] = state_.unshot[picked[s]];
        state_.unshot[picked[s]] = glm::vec3(0.0f);
    }
    for (std::size_t s = 0; s < picked.size(); ++s) {
        const double shooterArea = mesh_.patches[picked[s]].area;
        const glm::dvec3 power = glm::dvec3(shot[s]) * shooterArea;
        const float* row = &factors_[s * n];
        double seen = 0.0;
        glm::dvec3 absorbed(0.0);
        for (std::size_t j = 0; j < n; ++j) {
            const float f = row[j];
            if (f <= 0.0f)
                continue;
            seen += f;
            const glm::dvec3 received = power * double(f);
            const glm::dvec3 rho(surfaces_.reflectance[j]);
            const glm::dvec3 arrived = received / double(mesh_.patches[j].area);
            const glm::vec3 gained(arrived * rho);
            state_.incident[j] += glm::vec3(arrived);
            state_.radiosity[j] += gained;
            state_.unshot[j] += gained;
            absorbed += received * (glm::dvec3(1.0) - rho);
        }
        state_.balance.absorbed += absorbed;
        state_.balance.escaped += power * (1.0 - seen);
    }
    state_.shots += picked.size();
    state_.batches += 1;
    return int(picked.size());
}

std::vector<glm::vec3> ProgressiveSolver::ambient() const {
    double area = 0.0;
    glm::dvec3 reflectance(0.0);
    for (std::size_t i = 0; i < mesh_.size(); ++i) {
        area += mesh_.patches[i].area;
        reflectance += glm::dvec3(surfaces_.reflectance[i]) * double(mesh_.patches[i].area);
    }
    std::vector<glm::vec3> out(mesh_.size(), glm::vec3(0.0f));
    if (area <= 0.0)
        return out;
    reflectance /= area;
    // Unshot radiance spread over all surfaces, then every further bounce: 1 / (1 - rho).
    const glm::dvec3 ambient =
        unshotPower() / area / (glm::dvec3(1.0) - glm::min(reflectance, glm::dvec3(0.999)));
    for (std::size_t i = 0; i < mesh_.size(); ++i)
        out[i] = glm::vec3(glm::dvec3(surfaces_.reflectance[i]) * ambient);
    return out;
}

std::vector<std::uint32_t> ProgressiveSolver::patchesToRefine(float threshold) const {
    std::vector<std::uint32_t> out;
    for (std::uint32_t i = 0; i < mesh_.size(); ++i) {
        const glm::vec3& a = state_.radiosity[i];
        const float la = a.x + a.y + a.z;
        for (std::uint32_t k = mesh_.neighbourOffsets[i]; k < mesh_.neighbourOffsets[i + 1]; ++k) {
            const glm::vec3& b = state_.radiosity[mesh_.neighbours[k]];
            const float lb = b.x + b.y + b.z;
            if (std::abs(la - lb) > threshold * std::max(la, lb)) {
                out.push_back(i);
                break;
            }
        }
    }
    return out;
}

SolverState refineState(const SolverState& state, const std::vector<std::uint32_t>& parentOf) {
    SolverState out = state;
    out.radiosity.clear();
    out.unshot.clear();
    out.incident.clear();
    out.direct.clear();
    for (std::uint32_t parent : parentOf) {
        out.radiosity.push_back(state.radiosity[parent]);
        out.unshot.push_back(state.unshot[parent]);
        out.incident.push_back(state.incident.empty() ? glm::vec3(0.0f) : state.incident[parent]);
        out.direct.push_back(state.direct.empty() ? glm::vec3(0.0f) : state.direct[parent]);
    }
    return out;
}

} // namespace lpv::radiosity
