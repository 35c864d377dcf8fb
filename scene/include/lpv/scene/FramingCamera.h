#pragma once
// A camera for a scene that has none: inside an enclosed scene (an atrium
// like Sponza, a nave like Sibenik) it stands at one end looking along the
// longest horizontal axis; around an object it looks at the bounds from
// outside, from the open side when exactly one side is open (a Cornell box). Used by `lpv render` and the editor when a project has no camera.
#include "lpv/scene/Scene.h"

namespace lpv::scene {

// True when rays from the point a quarter up the bounds' centre line hit
// geometry in all four horizontal directions +-X, +-Z (a roof is optional),
// and most of the nearest hits are front faces (walls seen from inside, not
// the inside of a closed object's skin).
bool isEnclosed(const Scene& scene);

Camera framingCamera(const Scene& scene);

} // namespace lpv::scene
