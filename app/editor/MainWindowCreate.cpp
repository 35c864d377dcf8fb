// The Create menu: lights, cameras and primitives, each one undo step, placed
// where the user is looking.
#include "MainWindow.h"
#include "Viewport.h"

#include "lpv/scene/Primitives.h"

#include <glm/gtc/constants.hpp>

namespace lpv::editor {
namespace {

// A point in front of the view camera, at its target distance.
glm::vec3 pointInView(const scene::Camera& c) { return c.target; }

// A size that reads well from the current view (a tenth of the eye–target distance, at least 0.1).
float sizeInView(const scene::Camera& c) { return std::max(0.1f, 0.25f * glm::length(c.target - c.position)); }

} // namespace

void MainWindow::createLight(scene::LightType type) {
    const scene::Camera& view = viewport_->viewCamera();
    scene::Light light;
    light.type = type;
    switch (type) {
    case scene::LightType::Directional:
        light.name = "sun";
        light.direction = glm::normalize(glm::vec3(-0.35f, -1.0f, -0.25f));
        light.intensity = 3.0f;
        break;
    case scene::LightType::Point:
        light.name = "point light";
        light.position = pointInView(view);
        light.intensity = 10.0f;
        break;
    case scene::LightType::Spot:
        light.name = "spot light";
        light.position = view.position;
        light.direction = glm::normalize(view.target - view.position);
        light.intensity = 20.0f;
        light.innerConeAngle = glm::radians(20.0f);
        light.outerConeAngle = glm::radians(30.0f);
        break;
    case scene::LightType::Area: {
        // A panel above the point looked at, facing down, sized to the view.
        light.name = "area light";
        const float size = sizeInView(view);
        light.position = pointInView(view) + glm::vec3(0.0f, size, 0.0f);
        light.direction = {0.0f, -1.0f, 0.0f};
        light.size = {size, size};
        light.radius = 0.5f * size;
        light.intensity = 5.0f; // W/(m^2 sr)
        break;
    }
    }
    int created = -1;
    document_->editScene(tr("Create %1").arg(QString::fromStdString(light.name)), Change::Lights,
                         [&](scene::Scene& s) {
                             s.lights.push_back(light);
                             created = int(s.lights.size()) - 1;
                         });
    document_->select({Selection::Kind::Light, created});
}

void MainWindow::createPrimitive(const QString& kind) {
    const scene::Camera& view = viewport_->viewCamera();
    scene::Mesh mesh = kind == "plane" ? scene::makePlane(8) : kind == "box" ? scene::makeBox() : scene::makeSphere();
    int created = -1;
    document_->editScene(tr("Create %1").arg(kind), Change::Structure | Change::Materials, [&](scene::Scene& s) {
        scene::Material material;
        material.name = kind.toStdString() + " material";
        material.diffuseColor = glm::vec3(0.75f);
        mesh.submeshes[0].materialIndex = std::uint32_t(s.materials.size());
        s.materials.push_back(material);
        s.meshes.push_back(std::move(mesh));
        scene::Object object;
        object.name = kind.toStdString();
        object.mesh = int(s.meshes.size()) - 1;
        object.transform.translation = pointInView(view);
        object.transform.scale = glm::vec3(kind == "plane" ? 4.0f * sizeInView(view) : sizeInView(view));
        s.objects.push_back(object);
        created = int(s.objects.size()) - 1;
    });
    document_->select({Selection::Kind::Object, created});
}

void MainWindow::createCameraFromView() {
    scene::Camera camera = viewport_->viewCamera();
    int created = -1;
    document_->editScene(tr("Create camera"), Change::Cameras, [&](scene::Scene& s) {
        camera.name = "camera " + std::to_string(s.cameras.size() + 1);
        s.cameras.push_back(camera);
        created = int(s.cameras.size()) - 1;
    });
    document_->select({Selection::Kind::Camera, created});
}

} // namespace lpv::editor
