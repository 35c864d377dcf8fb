#pragma once
// The world matrices of all objects at once. A separate header (not a member
// in Scene.h) so that code which only reads a Scene does not recompile.
#include "lpv/scene/Scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace lpv::scene {

// worldMatrices(s)[i] == s.worldMatrix(i), bit for bit, in one pass whose time
// is linear in the number of objects however long the parent chains are
// (worldMatrix per object walks each chain again: quadratic for a chain of N
// objects). A cyclic chain, which the loader rejects, is cut where it closes
// rather than followed forever.
std::vector<glm::mat4> worldMatrices(const Scene& scene);

} // namespace lpv::scene
