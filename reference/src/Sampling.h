#pragma once
// Random numbers and hemisphere sampling for the path tracer. A counter-based
// hash (PCG) seeded by pixel and sample index makes every image the same
// whatever the number of threads.
#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>

namespace lpv::reference {

inline std::uint32_t pcgHash(std::uint32_t v) {
    const std::uint32_t state = v * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

class Rng {
  public:
    Rng(std::uint32_t a, std::uint32_t b, std::uint32_t c) : state_(pcgHash(a ^ pcgHash(b ^ pcgHash(c)))) {}
    float next() {
        state_ = pcgHash(state_);
        return float(state_ >> 8) * (1.0f / 16777216.0f); // [0, 1)
    }

  private:
    std::uint32_t state_;
};

// An orthonormal frame around n (Duff et al., "Building an orthonormal basis, revisited").
inline void basis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float c = n.x * n.y * a;
    t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
}

// Cosine-weighted direction around n: pdf = cos / pi, so irradiance = pi * mean radiance.
inline glm::vec3 cosineSample(const glm::vec3& n, float u1, float u2) {
    const float r = std::sqrt(u1);
    const float phi = 6.28318530718f * u2;
    glm::vec3 t, b;
    basis(n, t, b);
    return glm::normalize(t * (r * std::cos(phi)) + b * (r * std::sin(phi)) +
                          n * std::sqrt(std::max(0.0f, 1.0f - u1)));
}

} // namespace lpv::reference
