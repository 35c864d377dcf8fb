#include "lpv/renderer/DrawList.h"

#include "lpv/renderer/SceneGpu.h"

#include <algorithm>
#include <tuple>

namespace lpv::renderer {

FrustumPlanes frustumPlanes(const glm::mat4& m) {
    // Gribb & Hartmann: each plane is a sum or difference of the matrix's
    // fourth row and one of the others (glm is column-major: m[col][row]).
    auto row = [&](int r) { return glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
    FrustumPlanes p{row(3) + row(0), row(3) - row(0), row(3) + row(1),
                    row(3) - row(1), row(3) + row(2), row(3) - row(2)};
    for (glm::vec4& plane : p) {
        const float len = glm::length(glm::vec3(plane));
        if (len > 0.0f)
            plane /= len;
    }
    return p;
}

bool boxIntersectsFrustum(const scene::Bounds& box, const FrustumPlanes& planes) {
    if (box.empty())
        return false;
    for (const glm::vec4& p : planes) {
        // The box corner furthest along the plane normal: if even it is
        // outside, the whole box is.
        const glm::vec3 far{p.x >= 0.0f ? box.max.x : box.min.x, p.y >= 0.0f ? box.max.y : box.min.y,
                            p.z >= 0.0f ? box.max.z : box.min.z};
        if (glm::dot(glm::vec3(p), far) + p.w < 0.0f)
            return false;
    }
    return true;
}

std::vector<const DrawItem*> buildDrawList(const std::vector<DrawItem>& items, const glm::mat4& viewProj,
                                           const glm::vec3& eye, DrawListStats* stats) {
    const FrustumPlanes planes = frustumPlanes(viewProj);
    std::vector<const DrawItem*> out;
    out.reserve(items.size());
    for (const DrawItem& d : items)
        if (boxIntersectsFrustum(d.worldBounds, planes))
            out.push_back(&d);
    if (stats) {
        stats->total = items.size();
        stats->culled = items.size() - out.size();
    }
    auto distance2 = [&](const DrawItem* d) {
        const glm::vec3 c = d->worldBounds.center() - eye;
        return glm::dot(c, c);
    };
    std::stable_sort(out.begin(), out.end(), [&](const DrawItem* a, const DrawItem* b) {
        if (a->bucket != b->bucket)
            return a->bucket < b->bucket;
        if (a->bucket == DrawBucket::Blended)
            return distance2(a) > distance2(b);
        return a->material < b->material;
    });
    return out;
}

SurfaceDraws surfaceDraws(const std::vector<DrawItem>& items, const glm::mat4& viewProj,
                          const glm::vec3& eye) {
    SurfaceDraws out;
    for (const DrawItem* d : buildDrawList(items, viewProj, eye))
        if (d->bucket != DrawBucket::Blended)
            (d->bucket == DrawBucket::Opaque ? out.opaque : out.masked).push_back(d);
    return out;
}

} // namespace lpv::renderer
