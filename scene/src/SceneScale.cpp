#include "lpv/scene/SceneScale.h"

namespace lpv::scene {
namespace {

float scaled(float v, double factor) {
    return float(double(v) * factor);
}

glm::vec3 scaled(const glm::vec3& v, double factor) {
    return glm::vec3(glm::dvec3(v) * factor);
}

glm::vec2 scaled(const glm::vec2& v, double factor) {
    return glm::vec2(glm::dvec2(v) * factor);
}

} // namespace

void scaleSceneLengths(Scene& s, double factor, const SceneScaleParts& parts) {
    if (factor == 1.0)
        return;
    for (Mesh& mesh : s.meshes)
        for (glm::vec3& p : mesh.positions)
            p = scaled(p, factor);
    for (Object& o : s.objects) {
        o.transform.translation = scaled(o.transform.translation, factor);
        for (LodLevel& lod : o.lods)
            lod.distance = scaled(lod.distance, factor);
    }
    for (Light& l : s.lights) {
        l.position = scaled(l.position, factor);
        l.range = scaled(l.range, factor); // 0 (unlimited) stays 0
        l.size = scaled(l.size, factor);
        l.radius = scaled(l.radius, factor);
    }
    for (Camera& c : s.cameras) {
        c.position = scaled(c.position, factor);
        c.target = scaled(c.target, factor);
        if (parts.cameraPlanes) {
            c.nearPlane = scaled(c.nearPlane, factor);
            c.farPlane = scaled(c.farPlane, factor);
        }
    }
    for (CameraPath& path : s.cameraPaths)
        for (CameraKeyframe& key : path.keyframes)
            key.position = scaled(key.position, factor);
}

void moveScene(Scene& s, const glm::dvec3& offset) {
    auto moved = [&](const glm::vec3& p) { return glm::vec3(glm::dvec3(p) + offset); };
    for (Object& o : s.objects)
        if (o.parent < 0 || std::size_t(o.parent) >= s.objects.size())
            o.transform.translation = moved(o.transform.translation);
    for (Light& l : s.lights)
        l.position = moved(l.position);
    for (Camera& c : s.cameras) {
        c.position = moved(c.position);
        c.target = moved(c.target);
    }
    for (CameraPath& path : s.cameraPaths)
        for (CameraKeyframe& key : path.keyframes)
            key.position = moved(key.position);
}

} // namespace lpv::scene
