// Every tunable of LPV Studio, declared once. Defaults follow the thesis
// (4 cascades of 32^3 cells, 8 propagation steps, 6 shadow cascades, ...).
#include "ParameterDeclarations.h"

namespace lpv::scene {
namespace {

using P = Pass;

ParameterInfo boolean(std::string key, bool def, std::string group, std::string desc, Pass inv) {
    return ParameterInfo{std::move(key), ParameterType::Bool, def, 0.0, 1.0, {}, "", std::move(desc), std::move(group), inv};
}

ParameterInfo integer(std::string key, int def, int lo, int hi, std::string unit, std::string group, std::string desc,
                      Pass inv) {
    return ParameterInfo{std::move(key), ParameterType::Int, def,          double(lo),        double(hi), {},
                         std::move(unit), std::move(desc), std::move(group), inv};
}

ParameterInfo real(std::string key, double def, double lo, double hi, std::string unit, std::string group,
                   std::string desc, Pass inv) {
    return ParameterInfo{std::move(key), ParameterType::Float, def, lo, hi, {}, std::move(unit), std::move(desc),
                         std::move(group), inv};
}

// A Float that also admits `word` (its default): the renderer chooses the number.
ParameterInfo withWords(ParameterInfo info, std::string word) {
    info.enumValues = {word};
    info.defaultValue = std::move(word);
    return info;
}

ParameterInfo choice(std::string key, std::string def, std::vector<std::string> values, std::string group,
                     std::string desc, Pass inv) {
    return ParameterInfo{std::move(key), ParameterType::Enum, std::move(def), 0.0, 0.0, std::move(values), "",
                         std::move(desc), std::move(group), inv};
}

// auto = the scene analysis decides; on/off force the pass.
const std::vector<std::string> kAutoOnOff{"auto", "on", "off"};

// What a change to the LPV volume layout throws away: everything from injection on
// (the sky's height map and the emissive VPLs are sized by the cells too).
constexpr Pass kLpvAll = P::EmissiveVpls | P::SkyHeight | P::LpvInjection | P::SkyInjection | P::LpvNormals |
                         P::GeometryVolume | P::LpvPropagation | P::LpvBounces | P::Subsurface | P::Shading;

} // namespace

std::vector<ParameterInfo> declareParameters() {
    return {
        // --- Global illumination ---
        choice("gi.method", "lpv", {"off", "lpv", "radiosity", "reference"}, "GI",
               "How indirect light is made: off = direct light only (no RSM, LPV, sky, subsurface or glossy "
               "pass runs or holds GPU memory); lpv = cascaded light propagation volumes; radiosity = the "
               "project's baked radiosity solution (lpv radiosity) as the indirect light, the rasteriser "
               "drawing the direct light (no LPV pass runs; without a solution that matches the scene, "
               "direct light only); reference = the editor shows the CPU path tracer's progressive image of "
               "the view (the rasteriser draws direct light only, as with off)",
               P::Rsm | P::LocalRsm | kLpvAll | P::GlossyReflections),
        // --- LPV ---
        choice("lpv.variant", "computeGather", {"computeGather", "computeScatter", "rasterGather", "rasterScatter"},
               "LPV", "Propagation implementation; all give the same image within tolerance, they differ in time",
               P::LpvPropagation | P::LpvBounces | P::Shading),
        integer("lpv.gridSize", 32, 8, 128, "cells", "LPV", "Cells along each axis of every LPV cascade", kLpvAll),
        integer("lpv.cascades", 4, 1, 6, "", "LPV", "Number of nested LPV volumes, each cell twice the previous",
                kLpvAll | P::Rsm),
        boolean("lpv.twoSidedOcclusion", false, "LPV",
                "A geometry-volume surfel blocks light reaching it from either side, not only light that hits its "
                "front: a wall the volume saw from one side only still blocks light from the other",
                P::LpvPropagation | P::LpvBounces | P::Shading),
        boolean("lpv.clampToScene", false, "LPV",
                "Place each cascade, as near the camera as it can, so that it covers as much of the scene's "
                "bounds as its extent allows (all of it where larger, else a stretch inside it): no cells "
                "outside the scene, and a camera outside the scene (a Cornell box) gets the finest cells on it",
                kLpvAll | P::Rsm),
        // auto (issue #41): fitted to the scene's mean free path and the
        // view (renderer/src/analysis/LpvFit.cpp); a number forces it. The range
        // allows a scene in millimetres or kilometres.
        withWords(real("lpv.cellSize", 0.0, 1e-6, 1e6, "m", "LPV",
                       "Cell size of the finest cascade; auto fits it, the cascade count and the steps to the "
                       "scene and the view",
                       kLpvAll | P::Rsm),
                  "auto"),
        // Issue #47: three bands have their CPU twin (renderer/src/lpvref/LpvBands.cpp);
        // no GPU variant runs them yet, and the LPV pass refuses 3 naming the variant.
        integer("lpv.shBands", 2, 2, 3, "bands", "LPV",
                "Spherical-harmonic bands of the LPV's light and geometry volume: 2 (4 coefficients per colour "
                "channel) or 3 (9; not yet on the GPU: rendering refuses it)",
                kLpvAll),
        // The convergence question (issue #47): refinement r on top of the
        // fitted (or forced) LPV, renderer/src/analysis/LpvFit.cpp.
        real("lpv.refinement", 1.0, 0.25, 4.0, "x", "LPV",
             "Refines (above 1) or coarsens (below 1) the LPV by r: cells 1/r the size of lpv.cellSize (fitted or "
             "forced), r times lpv.gridSize cells along each axis and r times lpv.propagationSteps (rounded; at "
             "most 128 and 64), so every cascade covers the same space and light travels as far in finer steps "
             "(r^3 the cells, r^4 the propagation work; powers of two keep the extent exact)",
             kLpvAll | P::Rsm),
        integer("lpv.propagationSteps", 8, 0, 64, "steps", "LPV",
                "Propagation iterations per cascade; light travels one cell per step",
               P::LpvPropagation | P::LpvBounces | P::Shading),
        choice("lpv.cascadeSteps", "same", {"same", "byCellSize"}, "LPV",
               "same: every cascade runs lpv.propagationSteps; byCellSize: each coarser cascade half as many as "
               "the one inside it (at least 1), so light travels the same distance in every cascade for half "
               "the propagation work",
               P::LpvPropagation | P::LpvBounces | P::Shading),
        // 0.875 and lpv.lookupOffset 0.25 (issue #41, with lpv.cellSize =
        // auto): the imported Cornell box 0.74x -> 0.85x of the reference's
        // mean, Sponza 0.74x -> 0.96x, Sibenik 0.95x -> 1.04x (docs/lpv.md).
        real("lpv.injectionOffset", 0.875, 0.0, 4.0, "cells", "LPV",
             "VPLs are moved this far along their normal before injection to avoid self-illumination",
               P::LpvInjection | P::LpvPropagation | P::LpvBounces | P::Shading),
        real("lpv.intensity", 1.0, 0.0, 100.0, "", "LPV", "Scale of the indirect light read from the LPV", P::Shading),
        boolean("lpv.occlusion", true, "LPV", "Geometry-volume occlusion during propagation",
               P::GeometryVolume | P::LpvPropagation | P::LpvBounces | P::Shading),
        boolean("lpv.occlusionFirstStep", true, "LPV",
                "Let the geometry volume block the first propagation step too; off, light leaves the cell it "
                "was injected into past the surface that injected it (no self-occlusion)",
               P::LpvPropagation | P::LpvBounces | P::Shading),
        // 1 with the scene's geometry volume, from the accuracy measurements of issue #24 (docs/lpv.md,
        // "Geometry volume from the scene"); 1.333 suited the views' GV, which misses a wall's hidden face.
        real("lpv.occlusionStrength", 1.0, 0.0, 4.0, "", "LPV",
             "Scale of the geometry volume's blocking potential in propagation: 1 = a surface covering a cell "
             "face blocks 75% of the light meeting it head-on (the two-band cosine lobe), 4/3 = all of it",
               P::LpvPropagation | P::LpvBounces | P::Shading),
        // scene from the accuracy measurements of issue #24 (docs/lpv.md, "Geometry volume from the scene").
        choice("lpv.geometrySource", "scene", {"scene", "views"}, "LPV",
               "Where the geometry volume's surfaces come from: scene = every visible triangle, sampled on the "
               "CPU when its object changes (both faces of every wall, wherever the cascades go); views = what "
               "the sun's RSM and the camera see this frame",
               P::GeometryVolume | P::LpvPropagation | P::LpvBounces | P::Shading),
        boolean("lpv.gvFromCamera", true, "LPV",
                "Also inject blocking potential from the camera G-buffer (lpv.geometrySource = views)",
               P::GeometryVolume | P::LpvPropagation | P::LpvBounces | P::Shading),
        integer("lpv.gvCameraStride", 1, 1, 8, "pixels", "LPV",
                "The camera G-buffer gives the geometry volume one surfel per stride x stride pixels (the "
                "middle one, with the block's area): fewer atomics for the same coverage",
                P::GeometryVolume | P::LpvPropagation | P::LpvBounces | P::Shading),
        real("lpv.bleedingDamping", 1.0, 0.0, 4.0, "", "LPV",
             "Strength of light-bleeding damping from the SH directional derivative along the normal", P::Shading),
        boolean("lpv.visibilityLookup", false, "LPV",
                "Weight each trilinear tap of the lookup by the chance that the shading point sees it (distance "
                "moments from the geometry volume, a Chebyshev bound), so a cell behind a wall is not read; needs "
                "lpv.occlusion or lpv.bounces > 1",
                P::GeometryVolume | P::Shading),
        real("lpv.visibilityBias", 0.5, 0.0, 2.0, "cells", "LPV",
             "How far the visibility-aware lookup moves the shading point along its normal before the test, so "
             "the surface it lies on does not hide the cells in front of it", P::Shading),
        real("lpv.lookupOffset", 0.25, 0.0, 2.0, "cells", "LPV",
             "Read the LPV this far in front of the shaded surface, along its normal: at the surface itself the "
             "trilinear filter takes half its taps from cells behind it (outside the room, inside the wall)",
             P::Shading),
        integer("lpv.cascadeBlendLevels", 2, 1, 6, "cascades", "LPV",
                "Cascades blended at a lookup (2 = the two nearest; more adds coarser ones)", P::Shading),
        choice("lpv.lookupResolution", "full", {"full", "half", "quarter", "auto"}, "LPV",
               "Resolution of the LPV's diffuse lookup: full evaluates it at every pixel; half or quarter evaluates "
               "it once per 2x2 or 4x4 pixels (the lpvLookup pass) and upsamples it with depth- and normal-aware "
               "weights (the lpvLookupResolve pass), looking up at full resolution where no neighbour lies on its "
               "surface; auto takes the cheapest that measured within the reference's noise of full, from how many "
               "pixels a cell of the LPV spans and how many pixels the view has per triangle",
               P::LpvLookup | P::Shading),
        choice("lpv.directedPropagation", "off", kAutoOnOff, "LPV",
               "Directed propagation: a normals volume keeps light from flowing back onto its emitter",
               P::LpvInjection | P::LpvNormals | P::LpvPropagation | P::LpvBounces | P::Shading),
        integer("lpv.directedDilation", 1, 0, 8, "cells", "LPV",
                "How far the VPL normals of directed propagation spread from the cells they were injected into",
               P::LpvNormals | P::LpvPropagation | P::LpvBounces | P::Shading),
        boolean("lpv.reuse", true, "LPV",
                "Keep a pass's output (shadow maps, RSMs, sky height map, geometry volume, LPV) while nothing "
                "it is computed from changed: scene, lights, camera where it matters, the parameters that "
                "invalidate it, its inputs; benchmarks turn it off",
                P::LpvInjection | P::GeometryVolume | P::LpvPropagation),
        boolean("lpv.cellSnapping", true, "LPV",
                "Snap each cascade to its cell size so the volume does not swim when the camera moves", kLpvAll),
        real("lpv.viewShift", 0.0, 0.0, 1.0, "", "LPV",
             "Move each cascade's centre ahead of the camera along the view direction, so its cells cover what "
             "the camera sees rather than what lies behind it: 0 = centred on the camera, 1 = the camera two "
             "cells inside the cascade's back face",
             kLpvAll),
        integer("lpv.bounces", 1, 1, 4, "bounces", "LPV",
                "Light bounces in the LPV: 1 = the VPLs' light only; each further bounce re-injects the last "
                "one's light where the geometry volume has surfaces and propagates it again",
               P::LpvPropagation | P::LpvBounces | P::Shading),
        real("lpv.bounceAlbedo", 0.5, 0.0, 1.0, "", "LPV",
             "Albedo assumed for the geometry volume's surfaces when light bounces again (lpv.bounces > 1)",
               P::LpvBounces | P::Shading),
        choice("lpv.localLights", "auto", kAutoOnOff, "LPV",
               "Inject spot and point lights through reflective shadow maps of their own (auto: whenever such a "
               "light lights something, i.e. has a positive intensity)",
               P::LocalRsm | P::LpvInjection | P::LpvPropagation | P::Shading),
        integer("lpv.localRsmSize", 128, 16, 1024, "px", "LPV",
                "Width and height of each spot light's RSM and of each face of a point light's cube RSM",
               P::LocalRsm | P::LpvInjection | P::LpvPropagation | P::Shading),
        choice("lpv.emissive", "auto", kAutoOnOff, "LPV",
               "Inject emissive surfaces as VPLs sampled on their triangles (auto: when a visible material emits); "
               "an area light's visible surface (an emissive quad in its outline, like the Cornell box lamp) is "
               "left out: it is injected as that light, once",
               P::EmissiveVpls | P::LpvInjection | P::LpvPropagation | P::Shading),
        // --- Effects (thesis extensions) ---
        choice("effects.skyInjection", "auto", kAutoOnOff, "Effects",
               "Inject sky light from above the highest occluder of each column (auto: only for open scenes)",
               P::SkyHeight | P::SkyInjection | P::LpvPropagation | P::Shading),
        choice("effects.subsurface", "auto", kAutoOnOff, "Effects",
               "Subsurface-scattering LPV for translucent materials (auto: only if the scene has one)",
               P::Subsurface | P::Shading),
        real("effects.subsurfaceAttenuation", 0.5, 0.0, 1.0, "1/cell", "Effects",
             "Fraction of light absorbed per cell inside translucent material", P::Subsurface | P::Shading),
        integer("effects.subsurfaceSteps", 4, 0, 16, "steps", "Effects",
                "Propagation steps of the subsurface LPV; light crosses one cell of translucent material per step",
                P::Subsurface | P::Shading),
        choice("effects.glossyReflections", "auto", kAutoOnOff, "Effects",
               "Glossy reflections by ray-marching the LPV (auto: only if a material is glossy)",
               P::GlossyReflections | P::Shading),
        integer("effects.glossySteps", 16, 1, 128, "steps", "Effects", "Ray-march steps for glossy LPV reflections",
                P::GlossyReflections | P::Shading),
        real("effects.glossyThreshold", 0.5, 0.0, 1.0, "", "Effects",
             "Materials with a glossiness at or below this get no LPV reflection (and do not make auto run it)",
             P::GlossyReflections | P::Shading),
        real("effects.glossyMaxDistance", 32.0, 1.0, 1024.0, "cells", "Effects",
             "How far the glossy ray march goes, in cells of the finest LPV cascade", P::GlossyReflections | P::Shading),
        real("effects.glossyIntensity", 1.0, 0.0, 100.0, "", "Effects",
             "Scale of the glossy LPV reflections (on top of lpv.intensity)", P::GlossyReflections | P::Shading),
        choice("effects.sunRays", "auto", kAutoOnOff, "Effects",
               "Screen-space sun rays (auto: only when the sun is on screen)", P::SunRays),
        integer("effects.sunRaySamples", 64, 8, 256, "samples", "Effects", "Radial blur samples per pixel for sun rays",
                P::SunRays),
        real("effects.sunRayDecay", 0.96, 0.5, 1.0, "", "Effects", "Per-sample decay of the radial blur", P::SunRays),
        real("effects.sunRayDensity", 0.8, 0.0, 2.0, "", "Effects",
             "Length of the radial blur as a fraction of the distance to the sun", P::SunRays),
        // --- RSM ---
        choice("rsm.tileDraws", "perTile", {"perTile", "geometryShader"}, "RSM",
               "How the RSM tiles are drawn: perTile culls and draws each tile on its own; geometryShader "
               "draws the scene once and broadcasts every triangle to all tiles",
               P::Rsm),
        integer("rsm.tileSize", 256, 32, 1024, "px", "RSM",
                "Width and height of one reflective-shadow-map tile (one tile per LPV cascade)",
                P::Rsm | kLpvAll),
        integer("rsm.cascades", 4, 1, 6, "", "RSM", "Number of RSM tiles, normally one per LPV cascade",
                P::Rsm | kLpvAll),
        // --- Shadows ---
        integer("shadow.cascades", 6, 1, 8, "", "Shadows", "Cascaded shadow map splits for the sun",
                P::ShadowMaps | P::Shading),
        choice("shadow.cascadeDraws", "perCascade", {"perCascade", "geometryShader"}, "Shadows",
               "How the sun's cascades are drawn: perCascade culls and draws each cascade on its own; "
               "geometryShader draws the scene once and broadcasts every triangle to all cascades",
               P::ShadowMaps),
        integer("shadow.farCascadeInterval", 2, 1, 8, "frames", "Shadows",
                "Amortised far cascades: while the camera moves, the outer half of the sun's cascades is redrawn "
                "every Nth frame each (staggered) and shaded in between from the layer drawn for the earlier "
                "camera, which holds the same depths on the same texel grid (shadow.stabilize; without it every "
                "cascade is redrawn); a point it no longer covers takes the next cascade, and the last is redrawn "
                "whenever it no longer covers its slice. 1 redraws every cascade that moved, every frame",
                P::ShadowMaps | P::Shading),
        integer("shadow.mapSize", 1024, 256, 8192, "px", "Shadows", "Width and height of each shadow map",
                P::ShadowMaps | P::Shading),
        real("shadow.softness", 1.0, 0.0, 8.0, "", "Shadows",
             "Light size for soft shadows: the sun's angular diameter in degrees, the diameter of spot and point "
             "lights in scene units (area lights soften by their own size); the penumbra grows with blocker distance (0 = hard)",
               P::ShadowMaps | P::Shading),
        real("shadow.bias", 1.0, 0.0, 10.0, "texels", "Shadows",
             "Receiver offset along the normal, in shadow-map texels, against shadow acne", P::Shading),
        boolean("shadow.stabilize", true, "Shadows",
                "Snap each cascade to its texel grid in light space so shadow edges do not shimmer",
                P::ShadowMaps | P::Shading),
        // --- Output ---
        choice("output.exposureMode", "auto", {"auto", "manual"}, "Output",
               "auto: expose the frame's log-average luminance of its lit pixels to output.exposureKey, adapting "
               "over output.exposureAdaptation in the editor and videos (metered on the GPU, no read-back); "
               "manual: 2^output.exposure alone. Only the display image is exposed: metrics and EXR stay linear",
               P::Exposure | P::Tonemap),
        real("output.exposure", 0.0, -16.0, 16.0, "EV", "Output",
             "Exposure before tonemapping: the whole exposure (2^EV) when manual, a compensation on the "
             "metered exposure when auto",
             P::Tonemap),
        real("output.exposureKey", 0.18, 0.001, 10.0, "", "Output",
             "Auto exposure: the display luminance the log-average luminance maps to (Reinhard et al.'s key value; "
             "0.18 = middle grey)",
               P::Exposure | P::Tonemap),
        real("output.exposureHighlights", 98.0, 50.0, 100.0, "%", "Output",
             "Auto exposure: highlight protection. The exposure is lowered from the key's until the brightest "
             "channel of this percentage of the lit pixels stays below the tonemapper's white, so at most the "
             "rest clip (100: not even the brightest pixel)",
             P::Exposure | P::Tonemap),
        real("output.exposureAdaptation", 0.5, 0.0, 60.0, "s", "Output",
             "Auto exposure: time constant of the adaptation in the editor and videos (0 = at once)",
               P::Exposure | P::Tonemap),
        choice("output.tonemapper", "neutral", {"aces", "reinhard", "uncharted2", "linear", "neutral"}, "Output",
               "Operator that maps HDR radiance to display values; neutral (Khronos PBR Neutral) keeps hues "
               "and compresses highlights toward white without clipping them (auto exposure meters toward the operator's white)",
               P::Exposure | P::Tonemap),
        choice("output.view", "final", {"final", "indirect", "direct"}, "Output",
               "What the camera image shows: the final image, only the LPV's indirect irradiance (W/m^2, no "
               "albedo: what `lpv compare` measures against the path-traced reference), or direct light only",
               P::Shading),
        integer("output.anisotropy", 8, 1, 16, "samples", "Output",
                "Anisotropic texture filtering of shading (1 = trilinear only; shadow maps and RSMs never "
                "filter anisotropically); nearly free on GPUs, costly on llvmpipe",
               P::Shading),
        boolean("output.depthPrepass", true, "Output",
                "Render the camera's depth first, so that shading lights each visible pixel once instead of "
                "every surface behind it too (off: one pass, the nearest surface wins as it is drawn)",
                P::DepthPrepass | P::Shading),
        // --- Radiosity ---
        real("radiosity.maxPatchArea", 0.05, 0.0001, 100.0, "m^2", "Radiosity",
             "Surfaces are subdivided until every patch is at most this large", P::Radiosity),
        // Sponza at the default patch area makes 1.4 million patches, a 158 MB solution that llvmpipe
        // cannot shoot in any useful time; Sibenik makes 66,791 (issue #27).
        integer("radiosity.maxPatches", 1000000, 1, 100000000, "patches", "Radiosity",
                "A scene that would mesh into more patches than this is refused before meshing, with the count",
                P::Radiosity),
        integer("radiosity.hemicubeResolution", 128, 16, 1024, "px", "Radiosity",
                "Resolution of the hemicube's front face", P::Radiosity),
        integer("radiosity.shootersPerBatch", 16, 1, 1024, "patches", "Radiosity",
                "Patches that shoot their unshot energy in one GPU batch", P::Radiosity),
        integer("radiosity.lightSamples", 4, 1, 256, "points", "Radiosity",
                "Points per patch at which the lights' direct light (the first shots, with shadows) is measured",
                P::Radiosity),
        choice("radiosity.formFactors", "raycast", {"raycast", "hemicube"}, "Radiosity",
               "How shooters find what they light: rays from every patch to points on the shooter (CPU, Embree; "
               "Wallace et al. 1989) or hemicubes rendered on the GPU",
               P::Radiosity),
        // 1: on the Cornell box 4 points cost 3.4x the solve time for 0.25 points of indirect MARE (issue #27).
        integer("radiosity.shooterSamples", 1, 1, 64, "points", "Radiosity",
                "Ray-cast form factors: points on each shooter that every patch casts a ray to", P::Radiosity),
        real("radiosity.convergenceThreshold", 0.01, 0.00001, 1.0, "", "Radiosity",
             "Stop when the unshot energy falls below this fraction of the emitted energy", P::Radiosity),
        boolean("radiosity.smoothing", true, "Radiosity", "Interpolate patch radiosity to vertices for display",
                P::Shading),
        // --- Reference ---
        integer("reference.samplesPerPixel", 64, 1, 65536, "spp", "Reference",
                "Path-traced reference: samples per pixel", P::Reference),
        integer("reference.bounces", 4, 1, 64, "bounces", "Reference", "Path-traced reference: maximum bounces",
                P::Reference),
        real("reference.maxSeconds", 0.0, 0.0, 1e6, "s", "Reference",
             "Path-traced reference: stop after the progressive pass that reaches this wall time (0 = no limit)",
             P::Reference),
        choice("reference.skyLight", "auto", kAutoOnOff, "Reference",
               "Path-traced reference: rays that escape the scene see the sky's radiance. auto: when the LPV "
               "injects sky light (effects.skyInjection decides), so the reference traces the lights the renderer "
               "injects; off: the sky only colours the background. true/false read as on/off",
               P::Reference),
        choice("reference.emissiveLight", "auto", kAutoOnOff, "Reference",
               "Path-traced reference: emissive surfaces light other surfaces. auto: when the LPV injects emissive "
               "VPLs (lpv.emissive decides; an area light's own surface never counts twice). true/false read as on/off",
               P::Reference),
    };
}

} // namespace lpv::scene
