#include "CameraProperties.h"

#include "Document.h"
#include "PropertyWidgets.h"

#include "lpv/scene/SceneFields.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>

namespace lpv::editor {

namespace {
using scene::Camera;
constexpr const auto& kNear = scene::fieldOf<&Camera::nearPlane>();
constexpr const auto& kFar = scene::fieldOf<&Camera::farPlane>();
} // namespace

CameraProperties::CameraProperties(Document* doc, QWidget* parent)
    : ElementPanel(doc, &scene::Scene::cameras, &Document::setCamera, parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* group = new QGroupBox(tr("Camera"), this);
    auto* form = new QFormLayout(group);
    layout->addWidget(group);

    name_ = new QLineEdit(group);
    name_->setObjectName("cameraName");
    position_ = new Vec3Edit(scene::fieldOf<&Camera::position>(), 3, 0.1, {}, group);
    position_->setObjectName("cameraPosition");
    target_ = new Vec3Edit(scene::fieldOf<&Camera::target>(), 3, 0.1, {}, group);
    target_->setObjectName("cameraTarget");
    fov_ =
        makeFieldSpinBox(scene::fieldOf<&Camera::fovY>(), 2, 1.0, QStringLiteral("°"), group, Shown::Degrees);
    fov_->setObjectName("cameraFov");
    fov_->setToolTip(tr("Vertical field of view"));
    near_ = makeFieldSpinBox(kNear, 4, 0.01, QStringLiteral(" m"), group);
    near_->setObjectName("cameraNear");
    far_ = makeFieldSpinBox(kFar, 2, 10.0, QStringLiteral(" m"), group);
    far_->setObjectName("cameraFar");
    form->addRow(tr("Name"), name_);
    form->addRow(tr("Position"), position_);
    form->addRow(tr("Target"), target_);
    form->addRow(tr("Field of view"), fov_);
    form->addRow(tr("Near plane"), near_);
    form->addRow(tr("Far plane"), far_);

    connect(name_, &QLineEdit::editingFinished, this, [this] {
        const std::string name = name_->text().toStdString();
        edit(tr("Rename camera"), [&](scene::Camera& c) { c.name = name; });
    });
    connect(position_, &Vec3Edit::edited, this, [this](int axis, double v) {
        edit(tr("Edit camera position"), [&](scene::Camera& c) { c.position[axis] = float(v); });
    });
    connect(target_, &Vec3Edit::edited, this, [this](int axis, double v) {
        edit(tr("Edit camera target"), [&](scene::Camera& c) { c.target[axis] = float(v); });
    });
    connect(fov_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        edit(tr("Edit camera field of view"),
             [&](scene::Camera& c) { c.fovY = storedValue(v, Shown::Degrees); });
    });
    connect(near_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        // Equal planes would make a singular projection: the rule keeps the near one strictly in
        // front, within the depth buffer's ratio of the far one.
        edit(tr("Edit camera near plane"),
             [&](Camera& c) { kNear.of(c) = rangeGivenOthers(c, kNear.name).clamp(float(v)); });
    });
    connect(far_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        edit(tr("Edit camera far plane"),
             [&](Camera& c) { kFar.of(c) = rangeGivenOthers(c, kFar.name).clamp(float(v)); });
    });

    setIndex(-1);
}

void CameraProperties::refresh() {
    const scene::Camera* shown = shownElement();
    if (!shown) {
        showText(name_, {});
        return;
    }
    const scene::Camera& c = *shown;
    showText(name_, QString::fromStdString(c.name));
    position_->showValue(glm::dvec3(c.position));
    target_->showValue(glm::dvec3(c.target));
    showValue(fov_, shownValue(c.fovY, Shown::Degrees));
    // The near plane stays in front of the far one, and within the depth
    // buffer's ratio of it: each bounds the other (SceneFields.h's rule).
    const QSignalBlocker blockNear(near_);
    const QSignalBlocker blockFar(far_);
    setFieldRange(near_, kNear.widgetRange());
    setFieldRange(far_, kFar.widgetRange());
    showValue(near_, c.nearPlane);
    showValue(far_, c.farPlane);
    setFieldRange(near_, kNear.widgetRange().within(rangeGivenOthers(c, kNear.name)));
    setFieldRange(far_, kFar.widgetRange().within(rangeGivenOthers(c, kFar.name)));
}

} // namespace lpv::editor
