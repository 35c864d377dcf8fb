#pragma once
// The frame's display mapping on the CPU (issue #43): exposure, the
// tonemapping operator and the sRGB encoding exactly as shaders/tonemap.frag
// applies them, so that a path-traced reference shown beside the frame (the
// Accuracy dock's LPV | reference split, the live reference view) goes
// through the same curve and equal radiance shows as equal pixels. The
// `--preview` mapping (x / (x + mean), reference/Preview.h) stays an option.
// Qt-free, beside AutoExposure.h's CPU twin: the editor and the sweeps' images use it.
#include "lpv/renderer/AutoExposure.h"
#include "lpv/scene/Image.h"
#include "lpv/scene/ParameterRegistry.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace lpv::renderer {

// output.tonemapper, in tonemap.frag's numbering. Neutral is Khronos PBR
// Neutral (2024): linear up to 0.76, then a shoulder that compresses the
// brightest channel toward 1 without reaching it and keeps the hue, fading
// to white only as the overexposure grows; the others clip per channel
// (ACES near 5.5, Uncharted2 at its white 5.6, linear at 1).
enum class Tonemapper { Aces, Reinhard, Uncharted2, Linear, Neutral };
// The operator of a registry value ("aces", ...); Aces for one it does not know.
Tonemapper tonemapperOf(const std::string& name);

// The smallest grey value before the operator (exposure applied) that the
// display shows as white (255 in all channels of an 8-bit image): where auto
// exposure lets the highlight percentile go at most.
double whiteInput(Tonemapper op);

struct DisplayMapping {
    double exposure = 1.0; // the linear scale before the operator (2^EV, times the metered exposure on auto)
    Tonemapper tonemapper = Tonemapper::Aces;
};

// How a reference is shown beside the frame.
enum class ReferenceMapping {
    FrameTonemap, // the frame's exposure and tonemapper (the default)
    Preview,      // `lpv reference --preview`: x / (x + mean), gamma 2.2, the reference's own mean
};

// One linear RGB value as the display shows it (sRGB-encoded, 0..1 per channel).
glm::vec3 mapToDisplay(const glm::vec3& hdr, const DisplayMapping& mapping);
// A linear HDR image (rows top to bottom) as RGBA8, as tonemap.frag writes it.
scene::Image8 tonemapImage(const std::vector<glm::vec3>& hdr, int width, int height,
                           const DisplayMapping& mapping);

// What output.exposureKey, output.exposureHighlights and output.tonemapper
// ask of the auto exposure (the renderer's and the CPU twin's).
MeterTarget meterTargetOf(const scene::ParameterSet& parameters);

// The mapping an image the renderer never metered would get from these
// parameters (the live reference view): 2^output.exposure, times, on
// output.exposureMode = auto, the exposure the renderer's meter would give
// this image (renderer/AutoExposure.h's CPU twin, at once, no adaptation).
DisplayMapping meteredMapping(const std::vector<glm::vec3>& hdr, const scene::ParameterSet& parameters);

} // namespace lpv::renderer
