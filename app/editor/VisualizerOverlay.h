#pragma once
// What the Visualizers dock asks of the viewport, what each frame reads back
// for it, and the overlays drawn over the view: the bounds of every LPV
// cascade, the viewed slice as a translucent plane, and a grid of SH probes
// (small spheres shaded by their cell's light).
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/LpvSnapshot.h"
#include "lpv/renderer/viz/SliceImage.h"
#include "lpv/scene/Camera.h"

#include <QSizeF>

#include <optional>
#include <string>
#include <vector>

class QPainter;

namespace lpv::editor {

struct SlicePlane {
    int cascade = 0;
    renderer::viz::Axis axis = renderer::viz::Axis::Z;
    int index = 0;
    bool geometryVolume = false; // GV cells sit on the LPV cell corners
};

struct VisualizerRequest {
    std::optional<renderer::LpvCaptureRequest> lpv; // read back this cascade and step
    bool rsm = false;                               // the RSM tiles
    bool shadow = false;                            // the shadow-map depth tiles
    bool shadowTint = false;                        // surfaces tinted by their sun shadow cascade
    bool cascadeBounds = false;
    std::optional<SlicePlane> slicePlane;
    bool probes = false; // needs `lpv`: the probes show its accumulated light
    int probeStride = 4; // one probe every this many cells per axis

    bool active() const {
        return lpv || rsm || shadow || shadowTint || cascadeBounds || slicePlane || probes;
    }
};

struct VisualizerFrame {
    std::vector<renderer::LpvGridFrame> cascades;
    std::optional<renderer::LpvSnapshot> lpv;
    std::vector<renderer::DebugImage> rsm, shadow;
    std::string lpvNote;
};

// Draws the requested overlays; `frame` null draws nothing.
void drawVisualizerOverlay(QPainter& painter, const VisualizerRequest& request, const VisualizerFrame* frame,
                           const scene::Camera& camera, const QSizeF& size);

} // namespace lpv::editor
