#pragma once
// The reference solver: a progressive, multithreaded CPU path tracer on
// Embree that computes, through the pixel centres of the renderer's camera
// (the same pixels as its G-buffer), the full image and the indirect diffuse
// irradiance at the primary hit (one bounce and multi-bounce), each with the
// variance of its mean. Lights follow the renderer's conventions
// (shaders/forward.frag): a directional light's intensity is irradiance, a
// point or spot light's is intensity over distance squared with the glTF
// range window and smoothstep cone; secondary surfaces are Lambertian.
#include "lpv/reference/CameraRays.h"
#include "lpv/reference/EmbreeScene.h"
#include "lpv/reference/ReferenceImage.h"
#include "lpv/reference/Shards.h"
#include "lpv/scene/Scene.h"

#include <atomic>
#include <functional>
#include <vector>

namespace lpv::reference {

class Rng; // Sampling.h

struct PathTracerSettings {
    int width = 320;
    int height = 180;
    int samplesPerPixel = 64; // reference.samplesPerPixel
    double maxSeconds = 0.0;  // reference.maxSeconds; 0 = until samplesPerPixel
    int bounces = 4;          // reference.bounces: diffuse reflections counted in indirectMulti
    bool skyLight = false;    // reference.skyLight: rays that escape see the sky's radiance
    // reference.emissiveLight: emissive surfaces light others. Off matches the
    // renderer, where emission is only seen, and where a light (the Cornell
    // box's spot) already stands for the emitting panel: both would count it twice.
    bool emissiveLight = false;
    int threads = 0; // 0 = std::thread::hardware_concurrency()
    // Trace only this shard's tiles (Shards.h); the other pixels stay zero.
    ShardSpec shard;
};

struct TraceProgress {
    int samplesDone = 0;
    int samplesTarget = 0;
    double seconds = 0.0;
};

// Called after every progressive pass; return false to stop early.
using ProgressCallback = std::function<bool(const TraceProgress&)>;
// Called after every pass, before the progress callback, with the image of
// the passes so far (what render() would return if it stopped there): a live view.
using PassImageCallback = std::function<void(const ReferenceImage&)>;

// One sample of one pixel: what every estimator adds up (exposed for tests).
struct PixelSample {
    bool covered = false;
    glm::vec3 radiance{0.0f};
    glm::vec3 indirectOne{0.0f};
    glm::vec3 indirectMulti{0.0f};
};

class PathTracer {
  public:
    PathTracer(const EmbreeScene& embree, const scene::Scene& scene, const scene::Camera& camera,
               PathTracerSettings settings);

    ReferenceImage render(const ProgressCallback& progress = {}, const PassImageCallback& passImage = {}) const;

    // Sample `sampleIndex` of pixel (x, y) (rows from the top); deterministic.
    PixelSample samplePixel(int x, int y, int sampleIndex) const;
    // Irradiance the scene's lights deliver at the world point p with normal n (shadow rays included).
    // Area lights are sampled at one point drawn from `rng` (an unbiased estimate);
    // without one, from a generator seeded by p, so the call stays deterministic.
    glm::vec3 directIrradiance(const glm::vec3& p, const glm::vec3& offsetNormal, const glm::vec3& n,
                               Rng* rng = nullptr) const;

  private:
    const EmbreeScene& embree_;
    const scene::Scene& scene_;
    PathTracerSettings settings_;
    CameraRays cameraRays_;            // in the EmbreeScene's frame
    std::vector<scene::Light> lights_; // the scene's lights, positions in that frame
    glm::vec3 background_{0.0f};

    glm::vec3 escapedRadiance() const;
    // directIrradiance at p in the EmbreeScene's frame.
    glm::vec3 directIrradianceInFrame(const glm::vec3& p, const glm::vec3& offsetNormal, const glm::vec3& n,
                                      Rng* rng) const;
    // With reference.emissiveLight: the irradiance emissive surfaces deliver at
    // p toward n, estimated from one point sampled on them (next-event
    // estimation; paths that hit an emitter by chance then add nothing, so
    // a small bright panel does not leave the image speckled).
    glm::vec3 emitterIrradiance(const glm::vec3& p, const glm::vec3& offsetNormal, const glm::vec3& n,
                                Rng& rng) const;
    // Irradiance one light delivers at p toward n (0 when shadowed); `l` = unit direction to the light.
    glm::vec3 lightIrradiance(const scene::Light& light, const glm::vec3& p, const glm::vec3& offsetNormal,
                              const glm::vec3& n, glm::vec3& l, Rng& rng) const;
    // An area light: one point drawn uniformly on it, L A cos cos / d^2 with its shadow ray.
    glm::vec3 areaLightIrradiance(const scene::Light& light, const glm::vec3& p, const glm::vec3& offsetNormal,
                                  const glm::vec3& n, glm::vec3& l, Rng& rng) const;
};

} // namespace lpv::reference
