#pragma once
#include "lpv/scene/Project.h"

namespace lpv::scene {

// The Cornell box from its published measurements (Cornell University
// Program of Computer Graphics), in metres, with the thesis' camera.
Project makeCornellBoxProject();

} // namespace lpv::scene
