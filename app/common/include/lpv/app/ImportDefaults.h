#pragma once
// What an imported scene gets so that it shows well, the same in `lpv import`
// and the editor's Import (issue #26: the editor framed an imported Sponza
// from outside and lit it from a fixed direction, while the CLI stood inside
// it and chose its sun): the first view and, for a scene without lights, a
// sun placed where it lights the most of that view.
#include "lpv/scene/Scene.h"

#include <string>

namespace lpv::app {

// The scene's own first camera, else scene::framingCamera (inside an
// enclosed scene such as Sponza, around an object otherwise).
scene::Camera firstView(const scene::Scene& scene);

struct DefaultSun {
    scene::Light light;
    std::string how; // for the user: where it comes from and what it lights
};

// A sun for a scene that has no lights (one would render black): the
// direction reference::chooseSunDirection finds from firstView, or the old
// fixed direction when nothing beats it or the scene cannot be ray traced.
DefaultSun chooseDefaultSun(const scene::Scene& scene);

} // namespace lpv::app
