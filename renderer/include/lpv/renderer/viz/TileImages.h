#pragma once
// The RSM, shadow-map and geometry-volume viewers' pictures of the renderer's
// internal images (DebugImage), shared by the editor and `lpv dump`.
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/Image.h"

#include <string>
#include <vector>

namespace lpv::renderer::viz {

// An internal image made visible: normals as n * 0.5 + 0.5, depth and
// positions stretched over their range (empty texels black), flux and
// colours scaled by their maximum.
scene::Image8 debugImageView(const DebugImage& image);

// Images side by side, each shrunk (nearest texel) to at most maxTileSize
// pixels across (0: full size) and labelled with its name underneath.
scene::Image8 tileRow(const std::vector<DebugImage>& images, int maxTileSize = 0);

// The images whose names start with `prefix` (e.g. "rsm-1-", "shadow-").
std::vector<DebugImage> imagesNamed(const std::vector<DebugImage>& images, const std::string& prefix);

} // namespace lpv::renderer::viz
