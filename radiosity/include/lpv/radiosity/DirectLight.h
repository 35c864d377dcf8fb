#pragma once
// The lights' direct light at every patch (issue #27 item 2): the sun, spot,
// point and area lights deliver their light to the patches as the first
// shots, with their shadows, so a sunlit scene with no emissive surface
// solves. The light is evaluated by the path-traced reference's own light
// model (reference::PathTracer::directIrradiance: the renderer's falloffs,
// cones and area-light sampling, shadow rays through Embree), at a few
// stratified points of each patch, so radiosity and the reference agree on
// what a light delivers.
#include "lpv/radiosity/PatchMesh.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/Image.h"
#include "lpv/scene/Scene.h"

#include <atomic>
#include <vector>

namespace lpv::radiosity {

// Stratified points on a patch: a k x k grid of cells (k = ceil(sqrt(count))),
// one point per cell at its centre, mapped bilinearly onto a quad or by the
// square-root map onto a triangle. `count` is at least 1.
std::vector<glm::vec3> patchSamplePoints(const Patch& patch, int count);

// Per patch: the mean irradiance / pi over `samplesPerPatch` points, from
// every light of `scene` (emissive surfaces are not lights here: they shoot
// as patches). Runs on all cores; `cancel` (may be null) stops it early with
// an error. An error also when Embree cannot build the scene.
scene::Expected<std::vector<glm::vec3>> directLight(const PatchMesh& mesh, const scene::Scene& scene,
                                                    const scene::TextureImages& textures, int samplesPerPatch,
                                                    const std::atomic<bool>* cancel = nullptr);

} // namespace lpv::radiosity
