#include "lpv/reference/PathTracer.h"

#include "Sampling.h"
#include "lpv/scene/AreaLight.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>
#include <vector>

namespace lpv::reference {

namespace {

constexpr float kPi = 3.14159265358979f;
constexpr int kTile = kShardTileSize; // shards are made of whole tiles
// Paths longer than this continue with probability = their throughput (Russian roulette).
constexpr int kRouletteDepth = 3;

float smoothstep(float e0, float e1, float x) {
    const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// Welford's running mean and M2, per channel.
struct Welford {
    glm::vec3 mean{0.0f};
    glm::vec3 m2{0.0f};
    void add(const glm::vec3& x, int n) { // n = count including x
        const glm::vec3 delta = x - mean;
        mean += delta / float(n);
        m2 += delta * (x - mean);
    }
    glm::vec3 varianceOfMean(int n) const { return n > 1 ? m2 / (float(n - 1) * float(n)) : glm::vec3(0.0f); }
};

struct PixelState {
    Welford image, one, multi;
};

} // namespace

PathTracer::PathTracer(const EmbreeScene& embree, const scene::Scene& scene, const scene::Camera& camera,
                       PathTracerSettings settings)
    : embree_(embree), scene_(scene), settings_(settings) {
    const float aspect = float(settings_.width) / float(std::max(settings_.height, 1));
    // Rays are traced in Embree's frame (EmbreeScene.h): the camera and the
    // lights move into it once, in double, so a scene far from the origin is
    // traced as one at the origin.
    scene::Camera framed = camera;
    framed.position = embree.toFrame(camera.position);
    framed.target = embree.toFrame(camera.target);
    cameraRays_ = CameraRays(framed, aspect);
    lights_ = scene.lights;
    for (scene::Light& light : lights_)
        light.position = embree.toFrame(light.position);
    // ForwardRenderer clears to the sky colour times its intensity.
    background_ = scene.sky.color * scene.sky.intensity;
}

glm::vec3 PathTracer::escapedRadiance() const {
    return settings_.skyLight ? background_ : glm::vec3(0.0f);
}

glm::vec3 PathTracer::areaLightIrradiance(const scene::Light& light, const glm::vec3& p,
                                          const glm::vec3& offsetNormal, const glm::vec3& n, glm::vec3& l,
                                          Rng& rng) const {
    const scene::AreaLightFrame f = scene::areaLightFrame(light);
    const float u = rng.next(), w = rng.next();
    glm::vec3 q;
    if (light.shape == scene::AreaShape::Disc) {
        // Uniform on the disc: radius sqrt(u) (the renderer's polygon has the same area).
        const float r = std::sqrt(u), a = 2.0f * kPi * w;
        q = f.center + r * (std::cos(a) * f.halfU + std::sin(a) * f.halfV);
    } else {
        q = f.center + (2.0f * u - 1.0f) * f.halfU + (2.0f * w - 1.0f) * f.halfV;
    }
    const glm::vec3 origin = embree_.offsetOrigin(p, offsetNormal);
    const glm::vec3 d = q - origin;
    const float dist2 = glm::dot(d, d);
    // A float guard only (1 / dist2 must stay finite), not a length: it holds at any scale.
    if (!(dist2 >= std::numeric_limits<float>::min()))
        return glm::vec3(0.0f);
    const float dist = std::sqrt(dist2);
    l = d / dist;
    const float facing = -glm::dot(f.normal, l);
    const float cosEmitter = light.twoSided ? std::abs(facing) : facing; // one-sided unless flagged
    const float cosReceiver = glm::dot(n, l);
    if (cosEmitter <= 0.0f || cosReceiver <= 0.0f || glm::dot(offsetNormal, l) <= 0.0f)
        return glm::vec3(0.0f);
    if (light.castShadows && embree_.occluded(origin, l, 0.0f, dist * (1.0f - 1e-4f)))
        return glm::vec3(0.0f);
    return scene::areaLightRadiance(light) * (scene::areaLightArea(light) * cosEmitter * cosReceiver / dist2);
}

glm::vec3 PathTracer::lightIrradiance(const scene::Light& light, const glm::vec3& p,
                                      const glm::vec3& offsetNormal, const glm::vec3& n, glm::vec3& l,
                                      Rng& rng) const {
    if (light.type == scene::LightType::Area)
        return areaLightIrradiance(light, p, offsetNormal, n, l, rng);
    glm::vec3 irradiance = light.color * light.intensity;
    const glm::vec3 origin = embree_.offsetOrigin(p, offsetNormal);
    float maxT = std::numeric_limits<float>::infinity();
    if (light.type == scene::LightType::Directional) {
        l = -glm::normalize(light.direction);
    } else {
        const glm::vec3 d = light.position - p;
        const float dist = glm::length(d);
        if (dist <= 0.0f)
            return glm::vec3(0.0f);
        l = d / dist;
        // The 1e-8 m^2 clamp of the inverse square is forward.frag's, kept so
        // the direct parts agree; it only bites within 0.1 mm of a point light.
        float atten = 1.0f / std::max(dist * dist, 1e-8f);
        if (light.range > 0.0f) {
            // Smooth window to zero at the range (glTF convention, as forward.frag).
            const float r = dist / light.range;
            atten *= std::clamp(1.0f - r * r * r * r, 0.0f, 1.0f);
        }
        if (light.type == scene::LightType::Spot) {
            const float cosAngle = glm::dot(-l, glm::normalize(light.direction));
            atten *= smoothstep(std::cos(light.outerConeAngle), std::cos(light.innerConeAngle), cosAngle);
        }
        irradiance *= atten;
        maxT = glm::length(light.position - origin) * (1.0f - 1e-4f);
    }
    const float ndotl = glm::dot(n, l);
    if (ndotl <= 0.0f || irradiance == glm::vec3(0.0f))
        return glm::vec3(0.0f);
    if (light.castShadows && embree_.occluded(origin, l, 0.0f, maxT))
        return glm::vec3(0.0f);
    return irradiance * ndotl;
}

glm::vec3 PathTracer::emitterIrradiance(const glm::vec3& p, const glm::vec3& offsetNormal, const glm::vec3& n,
                                        Rng& rng) const {
    if (!settings_.emissiveLight || !embree_.hasEmitters())
        return glm::vec3(0.0f);
    const float pick = rng.next(), u1 = rng.next(), u2 = rng.next();
    const EmitterSample e = embree_.sampleEmitter(pick, u1, u2);
    const glm::vec3 origin = embree_.offsetOrigin(p, offsetNormal);
    const glm::vec3 d = e.position - origin;
    const float dist2 = glm::dot(d, d);
    // dist2: a float guard only (1 / dist2 must stay finite), not a length.
    if (e.pdfArea <= 0.0f || !(dist2 >= std::numeric_limits<float>::min()) || e.radiance == glm::vec3(0.0f))
        return glm::vec3(0.0f);
    const float dist = std::sqrt(dist2);
    const glm::vec3 l = d / dist;
    const float cosReceiver = glm::dot(n, l);
    // One-sided unless the material is two-sided (as pbrt, Cycles and glTF): the
    // back of a lamp quad lights nothing (the gap above the Cornell lamp).
    const float facing = -glm::dot(e.normal, l);
    const float cosEmitter = e.twoSided ? std::abs(facing) : facing;
    if (cosReceiver <= 0.0f || glm::dot(offsetNormal, l) <= 0.0f || cosEmitter <= 0.0f)
        return glm::vec3(0.0f);
    // Stop short of the emitter's own triangle.
    if (embree_.occluded(origin, l, 0.0f, dist * (1.0f - 1e-4f)))
        return glm::vec3(0.0f);
    return e.radiance * (cosReceiver * cosEmitter / (dist2 * e.pdfArea));
}

glm::vec3 PathTracer::directIrradiance(const glm::vec3& p, const glm::vec3& offsetNormal, const glm::vec3& n,
                                       Rng* rng) const {
    // A float world point is already rounded to steps of its magnitude (8 mm
    // 100 km out): where those steps outgrow the usual lift it is first lifted
    // past them, or its shadow rays could start behind its own wall.
    const glm::vec3 q = embree_.toFrame(p);
    const glm::vec3 lifted = embree_.offsetWorldPoint(p, offsetNormal);
    return directIrradianceInFrame(lifted == embree_.offsetOrigin(q, offsetNormal) ? q : lifted, offsetNormal,
                                   n, rng);
}

glm::vec3 PathTracer::directIrradianceInFrame(const glm::vec3& p, const glm::vec3& offsetNormal,
                                              const glm::vec3& n, Rng* rng) const {
    Rng seeded(std::bit_cast<std::uint32_t>(p.x), std::bit_cast<std::uint32_t>(p.y),
               std::bit_cast<std::uint32_t>(p.z));
    Rng& r = rng ? *rng : seeded;
    glm::vec3 e(0.0f);
    glm::vec3 l;
    for (const scene::Light& light : lights_)
        e += lightIrradiance(light, p, offsetNormal, n, l, r);
    return e;
}

PixelSample PathTracer::samplePixel(int x, int y, int sampleIndex) const {
    PixelSample out;
    // Through the pixel centre, as the rasteriser samples the G-buffer.
    const float ndcX = 2.0f * (float(x) + 0.5f) / float(settings_.width) - 1.0f;
    const float ndcY = 1.0f - 2.0f * (float(y) + 0.5f) / float(settings_.height);
    // A degenerate camera (a NaN field) gives no ray: the pixel shows the background.
    const std::optional<CameraRay> ray = cameraRays_.through(ndcX, ndcY);
    const glm::vec3 dir = ray ? ray->direction : glm::vec3(0.0f);
    const auto primary = ray ? embree_.intersect(ray->origin, dir, 0.0f, ray->length) : std::nullopt;
    if (!primary) {
        out.radiance = background_;
        return out;
    }
    out.covered = true;
    Rng rng(std::uint32_t(x), std::uint32_t(y) * 65537u, std::uint32_t(sampleIndex));

    const Hit& h = *primary;
    const SurfaceSample s = embree_.surface(h);
    const glm::vec3 v = -dir;
    // Direct light with the renderer's full BRDF (brdf.glsl), so the direct parts agree.
    glm::vec3 radiance = s.emissive;
    for (const scene::Light& light : lights_) {
        glm::vec3 l;
        const glm::vec3 e = lightIrradiance(light, h.position, h.geometricNormal, h.shadingNormal, l, rng);
        if (e != glm::vec3(0.0f))
            radiance += surfaceBrdf(s, h.shadingNormal, l, v) * e;
    }

    // Indirect irradiance at the primary hit: E = pi * mean incoming radiance
    // over cosine-weighted directions. Each later vertex is Lambertian.
    glm::vec3 pos = h.position;
    glm::vec3 ng = h.geometricNormal;
    glm::vec3 n = h.shadingNormal;
    glm::vec3 throughput(1.0f); // product of the diffuse albedos after the primary hit
    glm::vec3 multi(0.0f);      // incoming radiance at the primary hit, all bounces
    glm::vec3 one(0.0f);
    // Emitters' light reaches each vertex by next-event estimation. At the
    // primary hit it is direct light (in the image, never in the indirect
    // layers); at vertex d it has been reflected d times on its way, like the
    // lights' (issue #22: `bounces` = N reflections for every light kind, and
    // indirect1 holds exactly the light reflected once).
    radiance += s.diffuse / kPi * emitterIrradiance(h.position, h.geometricNormal, h.shadingNormal, rng);
    for (int depth = 1; depth <= settings_.bounces; ++depth) {
        const glm::vec3 w = cosineSample(n, rng.next(), rng.next());
        if (glm::dot(w, ng) <= 0.0f)
            break; // below the true surface: the shading normal leans past the face
        const auto hit =
            embree_.intersect(embree_.offsetOrigin(pos, ng), w, 0.0f, std::numeric_limits<float>::infinity());
        if (!hit) {
            const glm::vec3 sky = throughput * escapedRadiance();
            multi += sky;
            if (depth == 1)
                one += sky;
            break;
        }
        const SurfaceSample hs = embree_.surface(*hit);
        // Every light's direct light at this vertex, reflected here: `depth` reflections in all.
        const glm::vec3 lit =
            hs.diffuse / kPi *
            (directIrradianceInFrame(hit->position, hit->geometricNormal, hit->shadingNormal, &rng) +
             emitterIrradiance(hit->position, hit->geometricNormal, hit->shadingNormal, rng));
        multi += throughput * lit;
        if (depth == 1)
            one += lit;
        throughput *= hs.diffuse;
        if (depth >= kRouletteDepth) {
            const float keep = std::min(0.95f, std::max(throughput.x, std::max(throughput.y, throughput.z)));
            if (keep <= 0.0f || rng.next() >= keep)
                break;
            throughput /= keep;
        }
        pos = hit->position;
        ng = hit->geometricNormal;
        n = hit->shadingNormal;
    }
    out.indirectOne = kPi * one;
    out.indirectMulti = kPi * multi;
    out.radiance = radiance + s.diffuse / kPi * out.indirectMulti;
    return out;
}

ReferenceImage PathTracer::render(const ProgressCallback& progress, const PassImageCallback& passImage) const {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    ReferenceImage result;
    result.resize(settings_.width, settings_.height);
    std::vector<PixelState> state(result.pixelCount());
    const int tilesX = (settings_.width + kTile - 1) / kTile;
    const int tilesY = (settings_.height + kTile - 1) / kTile;
    std::vector<int> tiles; // this shard's tiles (all of them unsharded)
    for (int t = 0; t < tilesX * tilesY; ++t)
        if (shardOwnsTile(settings_.shard, t % tilesX, t / tilesX))
            tiles.push_back(t);
    const int tileCount = int(tiles.size());
    const int threadCount =
        settings_.threads > 0 ? settings_.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    const int target = std::max(1, settings_.samplesPerPixel);

    // The means and variances of `passes` passes into `result`.
    auto fillFromState = [&](int passes) {
        for (std::size_t i = 0; i < state.size(); ++i) {
            result.image[i] = state[i].image.mean;
            result.indirectOne[i] = state[i].one.mean;
            result.indirectMulti[i] = state[i].multi.mean;
            result.imageVariance[i] = state[i].image.varianceOfMean(passes);
            result.indirectOneVariance[i] = state[i].one.varianceOfMean(passes);
            result.indirectMultiVariance[i] = state[i].multi.varianceOfMean(passes);
        }
        result.samplesPerPixel = passes;
        result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    };
    int done = 0;
    double lastPass = 0.0;
    while (done < target) {
        const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        // Stop before a pass that would run past the budget (the first pass always runs).
        if (done > 0 && settings_.maxSeconds > 0.0 && elapsed + lastPass > settings_.maxSeconds)
            break;
        const auto passStart = Clock::now();
        const int sampleIndex = done;
        std::atomic<int> nextTile{0};
        auto worker = [&] {
            for (int next = nextTile++; next < tileCount; next = nextTile++) {
                const int t = tiles[std::size_t(next)];
                const int x0 = (t % tilesX) * kTile, y0 = (t / tilesX) * kTile;
                for (int y = y0; y < std::min(y0 + kTile, settings_.height); ++y)
                    for (int x = x0; x < std::min(x0 + kTile, settings_.width); ++x) {
                        const PixelSample s = samplePixel(x, y, sampleIndex);
                        const std::size_t i = std::size_t(y) * std::size_t(settings_.width) + std::size_t(x);
                        PixelState& p = state[i];
                        p.image.add(s.radiance, sampleIndex + 1);
                        p.one.add(s.indirectOne, sampleIndex + 1);
                        p.multi.add(s.indirectMulti, sampleIndex + 1);
                        result.coverage[i] = s.covered ? 1.0f : 0.0f;
                    }
            }
        };
        std::vector<std::jthread> pool;
        for (int k = 1; k < threadCount; ++k)
            pool.emplace_back(worker);
        worker();
        pool.clear(); // joins
        ++done;
        lastPass = std::chrono::duration<double>(Clock::now() - passStart).count();
        if (passImage) {
            fillFromState(done);
            passImage(result);
        }
        if (progress &&
            !progress({done, target, std::chrono::duration<double>(Clock::now() - start).count()}))
            break;
    }
    fillFromState(done);
    return result;
}

} // namespace lpv::reference
