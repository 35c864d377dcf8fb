#include "lpv/renderer/SceneAnalysis.h"

#include "lpv/renderer/LocalLightAnalysis.h"
#include "lpv/renderer/LpvFit.h"

#include "lpv/scene/Picking.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace lpv::renderer {
namespace {

// Probe rays per side of the grid over the scene's footprint.
constexpr int kProbeGrid = 6;

std::set<std::uint32_t> materialsInUse(const scene::Scene& s) {
    std::set<std::uint32_t> used;
    for (const scene::Object& o : s.objects)
        if (o.visible && o.mesh >= 0 && std::size_t(o.mesh) < s.meshes.size())
            for (const scene::Submesh& sub : s.meshes[std::size_t(o.mesh)].submeshes)
                used.insert(sub.materialIndex);
    return used;
}

// The sun is on screen when the direction towards it falls inside the view frustum.
bool sunOnScreen(const scene::Camera& camera, const glm::vec3& towardSun, float aspect) {
    const glm::vec4 clip = camera.projection(aspect) * glm::mat4(glm::mat3(camera.view())) * glm::vec4(towardSun, 1.0f);
    if (clip.w <= 0.0f)
        return false;
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return std::abs(ndc.x) <= 1.0f && std::abs(ndc.y) <= 1.0f;
}

EffectDecision decide(std::string effect, std::string key, const scene::ParameterSet& params, bool sceneWants,
                      const std::string& whyYes, const std::string& whyNo) {
    EffectDecision d;
    d.effect = std::move(effect);
    d.parameter = std::move(key);
    d.setting = params.getEnum(d.parameter);
    if (d.setting == "on") {
        d.wanted = true;
        d.reason = "forced on by " + d.parameter + " (scene: " + (sceneWants ? whyYes : whyNo) + ")";
    } else if (d.setting == "off") {
        d.wanted = false;
        d.reason = "forced off by " + d.parameter;
    } else {
        d.wanted = sceneWants;
        d.reason = sceneWants ? whyYes : whyNo;
    }
    return d;
}


// lpv.lookupResolution = auto (docs/renderer.md, "The lookup at reduced
// resolution", measured against the path-traced reference): a reduced
// lookup's texel spans at most 1/kLookupPixelsPerCellPerTexel of the LPV's
// cell, and the view has at least kLookupMinPixelsPerTriangle pixels per
// triangle (below, its three extra draws of the scene cost more than the
// lookups it saves).
constexpr double kLookupPixelsPerCellPerTexel = 1.0;
constexpr double kLookupMinPixelsPerTriangle = 2.0;
} // namespace

SceneTraits analyseSceneTraits(const scene::Scene& s) {
    SceneTraits t;
    for (const scene::Light& l : s.lights)
        t.hasDirectionalLight |= l.type == scene::LightType::Directional && l.intensity > 0.0f;
    for (std::uint32_t m : materialsInUse(s)) {
        if (m >= s.materials.size())
            continue;
        t.hasTranslucentMaterial |= s.materials[m].translucency > 0.0f;
        t.hasGlossyMaterial |= s.materials[m].glossiness > 0.0f;
        t.maxGlossiness = std::max(t.maxGlossiness, s.materials[m].glossiness);
    }
    const scene::Bounds b = s.worldBounds();
    t.bounds = b;
    if (b.empty())
        return t;
    // Per column of a grid over the inner part of the footprint (the outer
    // margin is usually outside the walls), a ray straight down from above
    // the scene: where the first surface it meets lies in the lowest quarter
    // of the scene's height, the sky reaches the ground there (a courtyard);
    // a roof or ceiling stops it high up.
    int open = 0;
    const float height = std::max(b.size().y, 1e-3f);
    for (int i = 0; i < kProbeGrid; ++i)
        for (int j = 0; j < kProbeGrid; ++j) {
            const float u = 0.15f + 0.7f * (float(i) + 0.5f) / float(kProbeGrid);
            const float v = 0.15f + 0.7f * (float(j) + 0.5f) / float(kProbeGrid);
            const glm::vec3 origin{b.min.x + u * b.size().x, b.max.y + 0.01f * height, b.min.z + v * b.size().z};
            const auto hit = scene::pickObject(s, origin, {0.0f, -1.0f, 0.0f});
            if (hit && hit->position.y < b.min.y + 0.25f * height)
                ++open;
            ++t.skyProbes;
        }
    t.openSkyFraction = float(open) / float(t.skyProbes);
    return t;
}

bool giMethodRuns(const scene::ParameterSet& params) { return params.getEnum("gi.method") == "lpv"; }

std::string giMethodOffReason(const scene::ParameterSet& params) {
    return "gi.method is " + params.getEnum("gi.method");
}

bool showsBakedRadiosity(const scene::ParameterSet& params) { return params.getEnum("gi.method") == "radiosity"; }

std::string giMethodLpvOffReason(const scene::ParameterSet& params) {
    if (showsBakedRadiosity(params))
        return "gi.method is radiosity: the indirect light is a baked solution's";
    return giMethodOffReason(params) + ": direct light only";
}

EffectDecision decideBakedRadiosity(const scene::ParameterSet& params, std::size_t patches, double residual) {
    EffectDecision d;
    d.effect = "Baked radiosity";
    d.parameter = "gi.method";
    d.setting = params.getEnum("gi.method");
    if (d.setting != "radiosity") {
        d.reason = giMethodOffReason(params);
    } else if (patches == 0) {
        d.reason = "no radiosity solution: run lpv radiosity (direct light only)";
    } else {
        char text[128];
        std::snprintf(text, sizeof text, "a baked solution of %zu patches, residual %.3g", patches, residual);
        d.wanted = true;
        d.reason = text;
    }
    return d;
}

std::vector<EffectDecision> decideEffects(const scene::Scene& s, const SceneTraits& t, const scene::ParameterSet& params,
                                          const scene::Camera* camera, float aspect) {
    std::vector<EffectDecision> out;

    EffectDecision lpv;
    lpv.effect = "Light propagation volumes";
    lpv.parameter = "lpv.intensity";
    lpv.setting = scene::formatValue(params.get("lpv.intensity"));
    // Spot and point lights are injected too (LocalLightAnalysis.h): they alone can run the LPV.
    const EffectDecision local = decideLocalLightInjection(s, params);
    const EffectDecision emissive = decideEmissiveInjection(s, params);
    lpv.wanted = giMethodRuns(params) && (t.hasDirectionalLight || local.wanted || emissive.wanted) &&
                 params.getFloat("lpv.intensity") > 0.0f;
    lpv.reason = !giMethodRuns(params)                  ? giMethodLpvOffReason(params)
                 : params.getFloat("lpv.intensity") <= 0.0f ? "lpv.intensity is 0"
                 : t.hasDirectionalLight ? "a directional light lights the scene: its RSM is injected"
                 : local.wanted          ? "spot, point or area lights light the scene: their RSMs are injected"
                 : emissive.wanted       ? "emissive surfaces light the scene: their VPLs are injected"
                                         : "no directional light (and no spot, point or area light): nothing to inject";
    if (lpv.wanted && camera) {
        // The fitted (or forced) cell size, and an LPV that cannot deliver
        // light to this view (LpvFit.h): the renderer skips the one whose
        // cascades miss the scene, and warns about the others.
        const LpvFit fit = fitLpv(params, t.bounds, camera->position);
        const LpvDelivery delivery = lpvDelivery(fit, params.getInt("lpv.gridSize"), t.bounds, camera->position);
        if (delivery.skipsLpv()) {
            lpv.wanted = false;
            lpv.reason = delivery.reason;
        } else {
            lpv.reason += fitNote(fit, delivery);
        }
    }
    out.push_back(lpv);

    out.push_back(decideDirectedPropagation(params, lpv.wanted, lpv.reason));
    EffectDecision sky = decideSkyInjection(s, t, params);
    if (sky.wanted && !lpv.wanted) {
        sky.wanted = false; // the sky is injected into the LPV: without one there is nowhere to put it
        sky.reason += "; but the LPV does not run (" + lpv.reason + ")";
    }
    out.push_back(sky);
    EffectDecision sss = decideSubsurface(t, params, lpv.wanted, lpv.reason);
    if (sss.wanted && !t.hasDirectionalLight) {
        sss.wanted = false; // its volume is injected from the sun's RSM (the renderer skips it too)
        sss.reason += "; but it is injected from the sun's RSM and no directional light lights the scene";
    }
    out.push_back(sss);
    out.push_back(decideGlossyReflections(t, params, lpv.wanted, lpv.reason));
    out.push_back(decideSunRays(s, params, camera, aspect));
    out.push_back(local);
    out.push_back(emissive);
    out.push_back(decideBounces(params, lpv.wanted));
    return out;
}

EffectDecision decideDirectedPropagation(const scene::ParameterSet& params, bool lpvRuns, const std::string& lpvReason) {
    EffectDecision d = decide("Directed propagation", "lpv.directedPropagation", params, lpvRuns,
                              "the LPV runs: keeps light from flowing back onto the surfaces that emitted it",
                              "the LPV does not run");
    if (d.wanted && !lpvRuns) {
        d.wanted = false; // forced on, but there is no LPV to direct
        d.reason = "forced on by lpv.directedPropagation, but the LPV does not run (" + lpvReason + ")";
    }
    return d;
}

// lpv.shBands = 3 (issue #47): the effects that read or write two bands only
// are off, and the effects list says why rather than mixing bands.
static void offWithThreeBands(EffectDecision& d, const scene::ParameterSet& params, const char* why) {
    if (d.wanted && params.getInt("lpv.shBands") == 3) {
        d.wanted = false;
        d.reason += std::string("; but lpv.shBands = 3: ") + why;
    }
}

EffectDecision decideSubsurface(const SceneTraits& t, const scene::ParameterSet& params, bool lpvRuns,
                                const std::string& lpvReason) {
    EffectDecision d = decide("Subsurface LPV", "effects.subsurface", params, t.hasTranslucentMaterial,
                              "a visible material is translucent", "no visible material is translucent");
    offWithThreeBands(d, params, "the subsurface LPV is injected and read in two bands only");
    if (d.wanted && !lpvRuns) {
        d.wanted = false; // injected from the LPV's RSM: without an LPV there is nothing to inject
        d.reason += "; but the LPV does not run (" + lpvReason + ")";
    }
    return d;
}

EffectDecision decideSkyInjection(const scene::Scene& s, const SceneTraits& t, const scene::ParameterSet& params) {
    const int percent = int(std::lround(100.0f * t.openSkyFraction));
    const bool skyLit = s.sky.intensity > 0.0f;
    EffectDecision d = decide("Sky light injection", "effects.skyInjection", params,
                              skyLit && t.openSkyFraction > kOpenSkyThreshold,
                              "open scene: " + std::to_string(percent) + "% of the downward probe rays reach the ground",
                              !skyLit ? "the sky's intensity is 0"
                                      : "closed scene: " + std::to_string(percent) +
                                            "% of the downward probe rays reach the ground");
    if (d.wanted && !skyLit) {
        d.wanted = false;
        d.reason = "forced on by effects.skyInjection, but the sky's intensity is 0";
    }
    return d;
}

EffectDecision decideGlossyReflections(const SceneTraits& t, const scene::ParameterSet& params, bool lpvRuns,
                                       const std::string& lpvReason) {
    const float threshold = params.getFloat("effects.glossyThreshold");
    char glossiness[64];
    std::snprintf(glossiness, sizeof glossiness, "glossiness up to %.2f, threshold %.2f",
                  double(t.maxGlossiness), double(threshold));
    const bool glossy = t.maxGlossiness > threshold;
    EffectDecision d =
        decide("Glossy LPV reflections", "effects.glossyReflections", params, glossy && lpvRuns,
               std::string("a visible material is glossy (") + glossiness +
                   "): the LPV is ray-marched along its reflections",
               !glossy ? std::string("no visible material is glossy enough (") + glossiness + ")"
                       : "the LPV does not run (" + lpvReason + ")");
    if (d.wanted && !lpvRuns) {
        d.wanted = false; // forced on, but there is no LPV to march through
        d.reason = "forced on by effects.glossyReflections, but the LPV does not run (" + lpvReason + ")";
    }
    offWithThreeBands(d, params, "the glossy march reads two bands only");
    return d;
}

const scene::Light* sunOf(const scene::Scene& s) {
    for (const scene::Light& l : s.lights)
        if (l.type == scene::LightType::Directional)
            return &l;
    return nullptr;
}

EffectDecision decideSunRays(const scene::Scene& s, const scene::ParameterSet& params, const scene::Camera* camera,
                             float aspect) {
    const scene::Light* sun = sunOf(s);
    const bool onScreen = sun && camera && sunOnScreen(*camera, -glm::normalize(sun->direction), aspect);
    EffectDecision d = decide("Sun rays", "effects.sunRays", params, onScreen, "the sun is on screen",
                              !sun ? "no sun" : !camera ? "no camera given" : "the sun is not on screen");
    if (!sun && d.wanted) {
        d.wanted = false; // forced on, but there is no sun to draw rays from
        d.reason = "forced on by effects.sunRays, but the scene has no sun";
    }
    return d;
}

LookupResolutionDecision decideLookupResolution(const scene::ParameterSet& params, int viewWidth, int viewHeight,
                                                float fovY, std::size_t triangles) {
    const std::string setting = params.getEnum("lpv.lookupResolution");
    if (setting == "full")
        return {1, "lpv.lookupResolution is full"};
    if (setting == "half")
        return {2, "lpv.lookupResolution is half"};
    if (setting == "quarter")
        return {4, "lpv.lookupResolution is quarter"};
    // Three SH bands (issue #47): the reduced lookup's passes read two bands
    // (LpvPass refuses half and quarter by name), so auto keeps full.
    if (params.getInt("lpv.shBands") == 3)
        return {1, "lpv.lookupResolution is auto and lpv.shBands is 3: the reduced lookup reads two bands"};
    // The fewest pixels one cell of the LPV spans in this view: a cascade of
    // gridSize cells seen from inside, its far side at most gridSize cells away
    // (each coarser cascade's cells grow with its distance, so the same bound holds for all).
    const int grid = params.getInt("lpv.gridSize");
    const double pixelsPerCell = double(viewHeight) / (2.0 * grid * std::tan(0.5 * double(fovY)));
    const double pixels = double(viewWidth) * double(viewHeight);
    const double pixelsPerTriangle = triangles > 0 ? pixels / double(triangles) : pixels;
    char why[200];
    std::snprintf(why, sizeof why, "a cell of the LPV spans at least %.1f pixels of this view, %.1f pixels per triangle",
                  pixelsPerCell, pixelsPerTriangle);
    LookupResolutionDecision d;
    if (pixelsPerTriangle < kLookupMinPixelsPerTriangle) {
        d.reduction = 1;
        char cost[120];
        std::snprintf(cost, sizeof cost, " (under %.1f: the reduced lookup's extra draws of the scene cost more than it saves)",
                      kLookupMinPixelsPerTriangle);
        d.reason = std::string("lpv.lookupResolution is auto: full, ") + why + cost;
        return d;
    }
    for (const int reduction : {4, 2})
        if (pixelsPerCell >= kLookupPixelsPerCellPerTexel * reduction) {
            d.reduction = reduction;
            break;
        }
    char rule[120];
    std::snprintf(rule, sizeof rule, " (quarter needs %.1f, half %.1f)", 4.0 * kLookupPixelsPerCellPerTexel,
                  2.0 * kLookupPixelsPerCellPerTexel);
    d.reason = std::string("lpv.lookupResolution is auto: ") +
               (d.reduction == 4 ? "quarter, " : d.reduction == 2 ? "half, " : "full, ") + why + rule;
    return d;
}

} // namespace lpv::renderer
