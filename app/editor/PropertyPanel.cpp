#include "PropertyPanel.h"

#include "CameraProperties.h"
#include "LightProperties.h"
#include "MaterialProperties.h"
#include "ObjectProperties.h"
#include "SkyProperties.h"

#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

namespace lpv::editor {

PropertyPanel::PropertyPanel(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    outer->addWidget(scroll);

    auto* content = new QWidget(scroll);
    auto* layout = new QVBoxLayout(content);
    title_ = new QLabel(content);
    title_->setObjectName("propertiesTitle");
    QFont bold = title_->font();
    bold.setBold(true);
    title_->setFont(bold);
    object_ = new ObjectProperties(doc, content);
    material_ = new MaterialProperties(doc, content);
    light_ = new LightProperties(doc, content);
    camera_ = new CameraProperties(doc, content);
    sky_ = new SkyProperties(doc, content);
    other_ = new QLabel(content);
    other_->setWordWrap(true);
    layout->addWidget(title_);
    layout->addWidget(object_);
    layout->addWidget(light_);
    layout->addWidget(camera_);
    layout->addWidget(sky_);
    layout->addWidget(other_);
    layout->addWidget(material_);
    layout->addStretch(1);
    // Pages keep their natural height; the space left over goes to the stretch below them.
    for (QWidget* page : std::initializer_list<QWidget*>{object_, light_, camera_, sky_, other_, material_})
        page->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum);
    scroll->setWidget(content);

    connect(object_, &ObjectProperties::materialChosen, this, [this](int material) {
        if (doc_->selection().kind == Selection::Kind::Object) {
            material_->setIndex(material);
            material_->setVisible(material >= 0);
        }
    });
    connect(doc, &Document::selectionChanged, this, &PropertyPanel::showSelection);
    connect(doc, &Document::changed, this, &PropertyPanel::refresh);
    showSelection(doc->selection());
}

void PropertyPanel::showSelection(const Selection& selection) {
    using Kind = Selection::Kind;
    const scene::Scene& s = doc_->scene();
    object_->setVisible(selection.kind == Kind::Object);
    light_->setVisible(selection.kind == Kind::Light);
    camera_->setVisible(selection.kind == Kind::Camera);
    sky_->setVisible(selection.kind == Kind::None);
    other_->setVisible(selection.kind == Kind::CameraPath);

    // Pages not shown get -1 so they hold no stale index into a changed scene.
    object_->setIndex(selection.kind == Kind::Object ? selection.index : -1);
    light_->setIndex(selection.kind == Kind::Light ? selection.index : -1);
    camera_->setIndex(selection.kind == Kind::Camera ? selection.index : -1);
    int material = -1;
    if (selection.kind == Kind::Material)
        material = selection.index;
    else if (selection.kind == Kind::Object)
        material = object_->chosenMaterial();
    material_->setIndex(material);
    material_->setVisible(material >= 0);

    auto nameOf = [](const auto& list, int index) {
        return index >= 0 && std::size_t(index) < list.size()
                   ? QString::fromStdString(list[std::size_t(index)].name)
                   : QString();
    };
    switch (selection.kind) {
    case Kind::None:
        title_->setText(tr("Scene"));
        break;
    case Kind::Object:
        title_->setText(tr("Object: %1").arg(nameOf(s.objects, selection.index)));
        break;
    case Kind::Light:
        title_->setText(tr("Light: %1").arg(nameOf(s.lights, selection.index)));
        break;
    case Kind::Camera:
        title_->setText(tr("Camera: %1").arg(nameOf(s.cameras, selection.index)));
        break;
    case Kind::Material:
        title_->setText(tr("Material: %1").arg(nameOf(s.materials, selection.index)));
        break;
    case Kind::CameraPath: {
        title_->setText(tr("Camera path: %1").arg(nameOf(s.cameraPaths, selection.index)));
        const bool valid = selection.index >= 0 && std::size_t(selection.index) < s.cameraPaths.size();
        other_->setText(valid ? tr("%n keyframe(s)", nullptr,
                                   int(s.cameraPaths[std::size_t(selection.index)].keyframes.size()))
                              : QString());
        break;
    }
    }
    stale_ = false;
}

void PropertyPanel::refresh(Changes changes) {
    // A hidden dock costs nothing during a gizmo drag; it catches up when shown.
    if (!isVisible()) {
        stale_ = true;
        return;
    }
    // Each page re-reads its element (a few dozen widget updates; cheap), and
    // names show in the title. Parameter and preset changes show elsewhere.
    if (changes & ~Changes(Change::Parameters | Change::Presets))
        showSelection(doc_->selection());
}

void PropertyPanel::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    if (stale_)
        showSelection(doc_->selection());
}

} // namespace lpv::editor
