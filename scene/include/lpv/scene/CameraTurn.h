#pragma once
// A camera turned in place about the world's up axis: what `lpv bench
// render --turn` times, and what the frame graph's turn reuse is tested
// with (a turn keeps the LPV's cascades, which follow the position only).
#include "lpv/scene/Camera.h"

namespace lpv::scene {

// `camera` yawed by `degrees` (counter-clockwise seen from above) around
// its position: the target and the up vector turn, the position stays.
Camera yawedAboutUp(const Camera& camera, float degrees);

} // namespace lpv::scene
