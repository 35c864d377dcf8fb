#pragma once
// The indirect light shading adds (issue #44 item 2). A pass that computes
// indirect light says so in its setup(), on the frames it runs:
//
//     state.indirectLight.push_back(screenIndirectLight(id(), resources::MyGiIncident));
//
// Shading (passes/direct/ShadingPass.cpp) reads whatever this frame's passes
// declared: their resources join its reads (so the graph runs them first and
// keys shading's reuse on them), their lookups select forward.frag's variant,
// and their bind() sets what the lookup samples. It never names a GI pass.
#include "gl/ProgramCache.h"
#include "graph/FrameGraph.h"
#include "graph/ResourceHandle.h"
#include "lpv/scene/ParameterRegistry.h"

#include <functional>
#include <string>
#include <vector>

namespace lpv::renderer {

struct IndirectLight {
    // forward.frag's ways of reading indirect light.
    enum class Lookup {
        // The LPV's volumes at the shaded point (lpv_lookup.glsl, lpv_glossy.glsl).
        LpvVolume,
        // The subsurface LPV's volume at translucent surfaces (lpv_subsurface_lookup.glsl).
        SubsurfaceVolume,
        // An image the size of the frame whose rgb is the diffuse light arriving at the
        // surface seen at that pixel, as irradiance / pi (screen_indirect.glsl);
        // shading multiplies it by the albedo. Replaces the LPV's lookups (at most one per frame).
        ScreenIncident,
        // The LPV's diffuse lookup drawn at reduced resolution (the lpvLookup pass,
        // lpv.lookupResolution) and resolved to an image of the view (lpvLookupResolve):
        // shading's opaque and masked draws read their pixel of it in place of their own
        // lookup (lpv_lookup_resolved.glsl); blended draws leave its defines out and look
        // the LPV up themselves. LpvVolume still serves glossy and subsurface.
        LpvReducedResolution,
    };
    graph::PassId provider;
    Lookup lookup = Lookup::ScreenIncident;
    // What shading reads of it (ScreenIncident: the image, first).
    std::vector<graph::ResourceHandle> reads;
    // forward.frag's defines for what the provider's run left (may be empty), asked at execute.
    std::function<void(std::vector<std::string>& defines)> defines;
    // Sets the lookup's uniforms and binds its textures to units of `ctx`;
    // empty for ScreenIncident, whose image shading binds itself.
    std::function<void(const CachedProgram& shader, graph::PassContext& ctx)> bind;
};

// The common form for a new GI pass: a screen-sized image of incident light (Lookup::ScreenIncident).
inline IndirectLight screenIndirectLight(graph::PassId provider, graph::ResourceHandle incident) {
    IndirectLight light;
    light.provider = std::move(provider);
    light.lookup = IndirectLight::Lookup::ScreenIncident;
    light.reads = {incident};
    return light;
}

} // namespace lpv::renderer
