#pragma once
// Where to put a sun for an imported scene that has no light (issue #22):
// among candidate directions, the one under which the largest part of what a
// camera sees is sunlit, found by casting a grid of camera rays and a shadow
// ray toward each candidate from every hit (Embree).
#include "lpv/reference/EmbreeScene.h"
#include "lpv/scene/Camera.h"

#include <glm/glm.hpp>

namespace lpv::reference {

struct SunChoice {
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // the direction the light travels
    float azimuthDegrees = 0.0f;            // where it comes from: from +Z toward +X
    float elevationDegrees = 90.0f;         // above the horizon
    float litFraction = 0.0f;               // of the camera rays that hit geometry, the share sunlit
    int viewHits = 0;                       // camera rays that hit geometry
};

// How much of `camera`'s view (a gridW x gridH grid of rays) `direction`
// lights; `viewHits` counts the rays that hit anything.
SunChoice sunlitShare(const EmbreeScene& embree, const scene::Camera& camera, const glm::vec3& direction,
                      int gridW = 48, int gridH = 27);

// The best of 8 azimuths x 4 elevations (20, 35, 50, 65 degrees) and
// `fallback` (the direction used so far), ties going to the fallback.
SunChoice chooseSunDirection(const EmbreeScene& embree, const scene::Camera& camera, const glm::vec3& fallback);

} // namespace lpv::reference
