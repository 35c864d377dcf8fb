#pragma once
// Frustum culling of draw items by their world bounding boxes, and the draw
// order: opaque before alpha-masked before blended, then by material so that
// state changes are few. Blended items are drawn back to front.
#include "lpv/scene/Mesh.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace lpv::renderer {

struct DrawItem;

// Six planes (a, b, c, d) with normals pointing inside: left, right, bottom,
// top, near, far, extracted from a view-projection matrix (OpenGL clip space).
using FrustumPlanes = std::array<glm::vec4, 6>;
FrustumPlanes frustumPlanes(const glm::mat4& viewProj);

// False only when the box lies entirely outside one plane (conservative).
bool boxIntersectsFrustum(const scene::Bounds& box, const FrustumPlanes& planes);

// The three shading buckets, in draw order.
enum class DrawBucket : std::uint8_t { Opaque = 0, Masked = 1, Blended = 2 };

struct DrawListStats {
    std::size_t total = 0;
    std::size_t culled = 0;
};

// Items inside the frustum, sorted by (bucket, material); blended ones by
// decreasing distance from `eye`. `bucketOf` gives each item's bucket.
std::vector<const DrawItem*> buildDrawList(const std::vector<DrawItem>& items, const glm::mat4& viewProj,
                                           const glm::vec3& eye, DrawListStats* stats = nullptr);

// A frame's draws that hide what lies behind them, split as the passes that
// write depth draw them: opaque ones through a program that never discards
// (so llvmpipe tests their depth early), alpha-masked ones through one that
// cuts their holes. Blended items are left out: they neither hide nor write depth.
struct SurfaceDraws {
    std::vector<const DrawItem*> opaque, masked;
};
SurfaceDraws surfaceDraws(const std::vector<DrawItem>& items, const glm::mat4& viewProj,
                          const glm::vec3& eye);

} // namespace lpv::renderer
