#pragma once
// The slice viewer's choices in one value, and the image they give: the
// editor's Visualizers dock and `lpv dump --what lpv|gv|leak|backside` both
// go through renderLpvView, so their pictures are the same pixels.
#include "lpv/renderer/LpvSnapshot.h"
#include "lpv/renderer/viz/SliceImage.h"

#include <optional>
#include <string>

namespace lpv::renderer::viz {

enum class LpvSource {
    Injected,    // V_0, what injection put into the volume
    Step,        // V_s, the light the s-th propagation step moved
    Accumulated, // V_0 + ... + V_s (s = the last step: what shading reads)
    Geometry,    // the geometry volume (blocking potential), (N+1)^3
    LeakHeat,    // flux crossing GV-blocked faces (LeakMaps.h), from the accumulated light
    Backside,    // irradiance on the back side of GV walls (LeakMaps.h), from the accumulated light
};

struct LpvViewSpec {
    int cascade = 0;
    LpvSource source = LpvSource::Accumulated;
    int step = -1; // -1: the frame's last step
    SliceSpec slice;
    ColourSpec colour;
    float wallThreshold = 0.3f; // leak views: the blocking from which a face counts as a wall
};

// The read-back the view needs from the renderer (ForwardRenderer::setLpvCapture).
LpvCaptureRequest captureFor(const LpvViewSpec& spec);

// Names for the CLI and the dock, and back (nullopt: not a name).
const char* sourceName(LpvSource source);
std::optional<LpvSource> sourceFromName(const std::string& name);
const char* quantityName(Quantity quantity);
std::optional<Quantity> quantityFromName(const std::string& name);
const char* channelName(Channel channel);
std::optional<Channel> channelFromName(const std::string& name);
std::optional<Axis> axisFromName(const std::string& name);
// Cells per axis of what the view slices (N, or N + 1 for the geometry volume).
int sliceCount(const LpvSnapshot& snapshot, LpvSource source);

// The title printed under the image, e.g. "CASCADE 0  Z = 12  STEP 3/8 ACCUMULATED  BAND0 LUMINANCE".
std::string viewTitle(const LpvSnapshot& snapshot, const LpvViewSpec& spec);

// The values of the slice (for tests and for a tooltip), and its image with the legend.
scene::Expected<SliceField> lpvViewField(const LpvSnapshot& snapshot, const LpvViewSpec& spec);
scene::Expected<scene::Image8> renderLpvView(const LpvSnapshot& snapshot, const LpvViewSpec& spec,
                                             SliceRange* usedRange = nullptr);

} // namespace lpv::renderer::viz
