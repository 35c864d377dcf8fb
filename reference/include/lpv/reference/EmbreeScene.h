#pragma once
// The scene flattened into world space and handed to Embree 3: one triangle
// geometry for every visible object, with per-triangle material and the
// vertex normals and UVs needed to shade a hit. Alpha-masked materials are
// cut out by an intersection filter, like the renderer's discard.
//
// Lengths that scale (issue #41, docs/reference.md): the triangles are kept
// relative to frameOrigin(), a point near the scene's centre computed in
// double, so a scene 100 km from the world origin is traced with the float
// precision it has at the origin. Every position this class takes or gives
// (ray origins, hits, emitter samples) is in that frame; toFrame() converts.
// Ray origins are lifted off surfaces by offsetOrigin(), relative to the
// hit's magnitude in that frame with a floor relative to the scene's extent.
#include "lpv/reference/SurfaceLookup.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/Image.h"
#include "lpv/scene/Scene.h"

#include <glm/glm.hpp>

#include <memory>
#include <optional>

namespace lpv::reference {

using scene::Expected;

struct Hit {
    float distance = 0.0f;
    glm::vec3 position{0.0f};
    glm::vec3 geometricNormal{0.0f}; // unit, facing the incoming ray
    glm::vec3 shadingNormal{0.0f};   // interpolated vertex normal, unit, same side as geometricNormal
    glm::vec2 uv{0.0f};
    int material = -1; // index into Scene::materials, -1 = default grey
};

// A point on an emissive triangle, for next-event estimation.
struct EmitterSample {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};   // unit, the triangle's face normal (counter-clockwise front)
    bool twoSided = false;    // the material is two-sided: emission leaves both sides, else the front only
    glm::vec3 radiance{0.0f}; // emitted radiance there (material emissive x map)
    float pdfArea = 0.0f;     // probability density per unit area of picking this point
};

// Whether Embree 3 accepts a ray: its ray.valid() asserts that every origin
// and direction component is within 1.844e18 (FLT_LARGE), NaN failing, and
// that tnear and tfar are not NaN. A ray it refuses aborted `lpv import`
// (issue #42), so intersect() and occluded() check first.
bool embreeAcceptsRay(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax);

class EmbreeScene {
  public:
    // `textures` are the decoded images the renderer also gets (alpha masks
    // are looked up in them); they must outlive the EmbreeScene.
    static Expected<EmbreeScene> build(const scene::Scene& scene, const scene::TextureImages& textures);

    EmbreeScene(EmbreeScene&&) noexcept;
    EmbreeScene& operator=(EmbreeScene&&) noexcept;
    ~EmbreeScene();

    // Closest hit along origin + t dir, t in (tMin, tMax); dir need not be unit.
    // A ray Embree would refuse (embreeAcceptsRay) hits nothing.
    std::optional<Hit> intersect(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax) const;
    // Anything between (shadow rays). A ray Embree would refuse counts as
    // blocked: no light arrives along a direction that does not exist.
    bool occluded(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax) const;

    // The material at a hit: albedo, emission and the direct-light BRDF terms.
    SurfaceSample surface(const Hit& hit) const;

    std::size_t triangleCount() const;

    // The world point the frame's coordinates are measured from: 0 for a
    // scene within its own size of the world origin (its coordinates
    // unchanged), else the centre of its bounds snapped to a power-of-two
    // grid as coarse as the scene, so a far one is moved by an exact amount.
    const glm::dvec3& frameOrigin() const;
    // A world position (or a light's, a camera's) in the frame, computed in double.
    glm::vec3 toFrame(const glm::vec3& world) const;
    // The largest side of the scene's bounds (0 for an empty scene).
    float extent() const;
    // A secondary ray's origin: p lifted along the unit normal n by 2e-5 of
    // max(|p|, extent / 8) (p in the frame). Float rounding of a hit grows
    // with its magnitude and with the ray's length, which is at most the
    // extent; no metre constant, so a 1 cm and a 1 km scene are lifted alike.
    glm::vec3 offsetOrigin(const glm::vec3& p, const glm::vec3& n) const;
    // The same for a point given in float world coordinates (a radiosity
    // patch, DirectLight's sample points): such a point is already rounded to
    // float steps of its world magnitude (8 mm at 100 km), so it is lifted by
    // at least 8 of those steps, or it may start behind its own wall.
    glm::vec3 offsetWorldPoint(const glm::vec3& world, const glm::vec3& n) const;

    // Emissive triangles (materials with emission), picked in proportion to
    // area x emitted luminance, then a uniform point on the one picked.
    bool hasEmitters() const;
    EmitterSample sampleEmitter(float pick, float u1, float u2) const;

  private:
    EmbreeScene();
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace lpv::reference
