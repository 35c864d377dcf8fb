#include "ObjectProperties.h"

#include "Document.h"
#include "PropertyWidgets.h"

#include "lpv/scene/SceneFields.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>

namespace lpv::editor {

ObjectProperties::ObjectProperties(Document* doc, QWidget* parent)
    : ElementPanel(doc, &scene::Scene::objects, &Document::setObject, parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);

    auto* general = new QGroupBox(tr("Object"), this);
    auto* form = new QFormLayout(general);
    name_ = new QLineEdit(general);
    name_->setObjectName("objectName");
    visible_ = new QCheckBox(tr("Visible"), general);
    visible_->setObjectName("objectVisible");
    form->addRow(tr("Name"), name_);
    form->addRow(QString(), visible_);
    layout->addWidget(general);

    auto* transform = new QGroupBox(tr("Transform"), this);
    auto* tform = new QFormLayout(transform);
    translation_ = new Vec3Edit(scene::fieldOf<&scene::Object::transform, &scene::Transform::translation>(),
                                3, 0.1, QString(), transform);
    translation_->setObjectName("objectTranslation");
    rotation_ = new Vec3Edit(-360.0, 360.0, 2, 5.0, QStringLiteral("°"), transform);
    rotation_->setObjectName("objectRotation");
    rotation_->setToolTip(tr("Euler angles in degrees, applied about X, then Y, then Z"));
    scale_ = new Vec3Edit(scene::fieldOf<&scene::Object::transform, &scene::Transform::scale>(), 3, 0.1,
                          QString(), transform);
    scale_->setObjectName("objectScale");
    tform->addRow(tr("Translation"), translation_);
    tform->addRow(tr("Rotation"), rotation_);
    tform->addRow(tr("Scale"), scale_);
    layout->addWidget(transform);

    auto* mesh = new QGroupBox(tr("Mesh"), this);
    auto* mlayout = new QVBoxLayout(mesh);
    meshInfo_ = new QLabel(mesh);
    meshInfo_->setObjectName("objectMeshInfo");
    meshInfo_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    materials_ = new QListWidget(mesh);
    materials_->setObjectName("objectMaterials");
    materials_->setToolTip(tr("The material of each submesh; choose one to edit it below"));
    materials_->setMaximumHeight(120);
    mlayout->addWidget(meshInfo_);
    mlayout->addWidget(materials_);
    layout->addWidget(mesh);

    connect(name_, &QLineEdit::editingFinished, this, [this] {
        const std::string name = name_->text().toStdString();
        edit(tr("Rename object"), [&](scene::Object& o) { o.name = name; });
    });
    connect(visible_, &QCheckBox::toggled, this, [this](bool on) {
        edit(tr("Toggle object visibility"), [&](scene::Object& o) { o.visible = on; });
    });
    connect(translation_, &Vec3Edit::edited, this, [this](int axis, double v) {
        edit(tr("Edit object translation"),
             [&](scene::Object& o) { o.transform.translation[axis] = float(v); });
    });
    connect(rotation_, &Vec3Edit::edited, this, &ObjectProperties::editRotation);
    connect(scale_, &Vec3Edit::edited, this, [this](int axis, double v) {
        edit(tr("Edit object scale"), [&](scene::Object& o) { o.transform.scale[axis] = float(v); });
    });
    connect(materials_, &QListWidget::currentRowChanged, this, &ObjectProperties::announceMaterial);

    setIndex(-1);
}

void ObjectProperties::forgetLastElement() {
    eulerObject_ = -1;
    // A new object starts with its first submesh's material.
    const QSignalBlocker block(materials_);
    materials_->clear();
}

int ObjectProperties::chosenMaterial() const {
    const QListWidgetItem* item = materials_->currentItem();
    return item ? item->data(Qt::UserRole).toInt() : -1;
}

void ObjectProperties::editRotation(int axis, double degrees) {
    euler_[axis] = degrees;
    eulerQuat_ = quatFromEulerDegrees(euler_);
    eulerObject_ = index();
    const glm::quat q = eulerQuat_;
    edit(tr("Edit object rotation"), [&](scene::Object& o) { o.transform.rotation = q; });
}

void ObjectProperties::refresh() {
    const scene::Object* shown = shownElement();
    if (!shown) {
        showText(name_, {});
        meshInfo_->clear();
        refreshMaterials();
        return;
    }
    const scene::Object& o = *shown;
    showText(name_, QString::fromStdString(o.name));
    {
        const QSignalBlocker block(visible_);
        visible_->setChecked(o.visible);
    }
    translation_->showValue(glm::dvec3(o.transform.translation));
    if (eulerObject_ != index() || eulerQuat_ != o.transform.rotation) {
        euler_ = eulerDegrees(o.transform.rotation);
        eulerQuat_ = o.transform.rotation;
        eulerObject_ = index();
    }
    rotation_->showValue(euler_);
    scale_->showValue(glm::dvec3(o.transform.scale));

    const auto& meshes = doc_->scene().meshes;
    if (o.mesh >= 0 && std::size_t(o.mesh) < meshes.size()) {
        const scene::Mesh& m = meshes[std::size_t(o.mesh)];
        meshInfo_->setText(tr("%1: %2 triangles, %3 submeshes")
                               .arg(QString::fromStdString(m.name))
                               .arg(qulonglong(m.triangleCount()))
                               .arg(qulonglong(m.submeshes.size())));
    } else {
        meshInfo_->setText(tr("No mesh"));
    }
    refreshMaterials();
}

void ObjectProperties::refreshMaterials() {
    // Rebuilt only when the entries change, so the chosen row survives edits.
    struct Entry {
        QString text;
        int material;
    };
    std::vector<Entry> entries;
    const scene::Scene& s = doc_->scene();
    if (index() >= 0 && std::size_t(index()) < s.objects.size()) {
        const int mesh = s.objects[std::size_t(index())].mesh;
        if (mesh >= 0 && std::size_t(mesh) < s.meshes.size()) {
            const auto& submeshes = s.meshes[std::size_t(mesh)].submeshes;
            for (std::size_t i = 0; i < submeshes.size(); ++i) {
                const std::uint32_t mi = submeshes[i].materialIndex;
                const QString name = mi < s.materials.size() ? QString::fromStdString(s.materials[mi].name)
                                                             : tr("(missing material %1)").arg(mi);
                entries.push_back(
                    {tr("%1: %2 (%3 triangles)").arg(i).arg(name).arg(submeshes[i].indexCount / 3),
                     mi < s.materials.size() ? int(mi) : -1});
            }
        }
    }
    bool same = int(entries.size()) == materials_->count();
    for (int i = 0; same && i < materials_->count(); ++i) {
        const QListWidgetItem* item = materials_->item(i);
        same = item->text() == entries[std::size_t(i)].text &&
               item->data(Qt::UserRole).toInt() == entries[std::size_t(i)].material;
    }
    if (same)
        return announceMaterial();
    const int row = materials_->currentRow();
    {
        const QSignalBlocker block(materials_);
        materials_->clear();
        for (const Entry& e : entries) {
            auto* item = new QListWidgetItem(e.text, materials_);
            item->setData(Qt::UserRole, e.material);
        }
        if (!entries.empty())
            materials_->setCurrentRow(std::clamp(row, 0, int(entries.size()) - 1));
    }
    announceMaterial();
}

void ObjectProperties::announceMaterial() {
    const int material = chosenMaterial();
    if (material == announced_)
        return;
    announced_ = material;
    emit materialChosen(material);
}

} // namespace lpv::editor
