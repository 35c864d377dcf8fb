#pragma once
// A scene's lengths times one factor: `lpv import --unit/--scale` and the
// units formats state (docs/importers.md, "Units (issue #41)").
#include "lpv/scene/Scene.h"

namespace lpv::scene {

// Which lengths scaleSceneLengths leaves alone.
struct SceneScaleParts {
    // Camera near/far planes. An importer that does not read them from the
    // file leaves the Camera defaults, which are already in metres; scaling
    // those would clip a scene read in centimetres at 5 m.
    bool cameraPlanes = true;
};

// Multiplies every length of `s` by `factor` (> 0, finite), so that every
// world position becomes `factor` times what it was: mesh vertex positions,
// object translations (the world matrix chain is linear in both, so parents
// and children stay where they were relative to each other), light
// positions, ranges, area light sizes and radii, camera positions and
// targets (and clip planes, see SceneScaleParts), camera path key positions
// and LOD switch distances. Directions, rotations, object scale factors,
// normals, tangents, uvs, colours, intensities and angles do not change.
// Products are computed in double and rounded once, so a power-of-two
// factor is exact.
void scaleSceneLengths(Scene& s, double factor, const SceneScaleParts& parts = {});

// Moves every world position of `s` by `offset`, computed in double and
// rounded once: root objects' translations (children and meshes stay in
// their parents' space), light positions, cameras and camera path keys.
// The renderer's render space and the framing camera move a scene far from
// the origin near it this way (issue #41).
void moveScene(Scene& s, const glm::dvec3& offset);

} // namespace lpv::scene
