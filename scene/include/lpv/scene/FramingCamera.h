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

// Its near and far planes are fractions of the scene's radius (issue #41:
// a 2 cm box and a 2 km one are framed alike, neither clipped).
Camera framingCamera(const Scene& scene);

// Near and far planes that hold all of `bounds` as seen from the camera's
// position, for a camera whose planes did not come from its file (the
// Camera defaults, 0.05 m and 500 m, clip a 2 cm scene whole and cut a 2 km
// one): far 1% past the farthest corner; near half the distance to the
// bounds from outside them, else far / 10^4 (1e-4 of the scene, as the
// framing camera inside a room). An empty bounds leaves the camera as it is.
void fitClipPlanes(Camera& camera, const Bounds& bounds);

} // namespace lpv::scene
