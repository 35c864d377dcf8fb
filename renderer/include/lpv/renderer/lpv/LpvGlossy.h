#pragma once
// Glossy reflections from the LPV (docs/lpv.md, Glossy reflections): the CPU
// twin of shaders/lpv_glossy.glsl. A ray marched from the surface along the
// reflection vector reads, at each step, the finest cascade that holds the
// point and whose cells are as wide as the reflection cone there, and averages
// the radiance arriving along the ray. LpvGlossyGLTest holds the GLSL to it.
#include "lpv/renderer/lpv/LpvReference.h"

#include <glm/glm.hpp>

#include <span>

namespace lpv::renderer::lpvref {

struct GlossyMarch {
    int steps = 16;                 // effects.glossySteps
    float maxDistanceCells = 32.0f; // effects.glossyMaxDistance, in cells of the finest cascade
    float intensity = 1.0f;         // lpv.intensity * effects.glossyIntensity
};

// Cells between x and the nearest face of the cascade's cube (negative outside).
float cascadeMargin(const GridFrame& frame, const glm::vec3& x);

// The cascade a sample at x reads: the finest with margin >= 1 whose cell size
// is at least `footprint`, else the coarsest with margin >= 1; -1 if none.
int glossyCascade(std::span<const GridFrame> frames, const glm::vec3& x, float footprint);

// Radiance (rgb) of light at x travelling along unit `travel`: the intensity
// in that direction over the cell's face area (Kaplanyan's approximation), >= 0.
glm::vec3 radianceToward(const ShGrid& accumulated, const GridFrame& frame, const glm::vec3& x,
                         const glm::vec3& travel);

// Radiance arriving at x from unit direction r, averaged over the march's
// samples; `frames[k]` describes `accumulated[k]`, finest first.
glm::vec3 glossyIncoming(std::span<const ShGrid> accumulated, std::span<const GridFrame> frames,
                         const glm::vec3& x, const glm::vec3& r, float glossiness, const GlossyMarch& march);

// Share of that radiance the surface reflects toward the viewer: glossiness
// times Schlick's Fresnel term of the specular colour f0 at n.v.
glm::vec3 glossyReflectance(const glm::vec3& f0, float glossiness, float nDotV);

} // namespace lpv::renderer::lpvref
